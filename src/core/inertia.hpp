#pragma once
/// @file
/// Inertia tensors of point masses and their shifts between reference points.
///
/// Conventions (used everywhere in wobble):
/// - SI units: masses in kg, positions in m, tensors in kg m^2.
/// - The tensor carries the usual sign of the products of inertia,
///   @f$ I_{ij} = \sum_p m_p (|r_p|^2 \delta_{ij} - r_{p,i} r_{p,j}) @f$, so that L = I w.
/// - Every vector and tensor is expressed in one fixed frame F (the problem's frame); the names
///   say about which point: `I_O` about the origin of F, `I_cm` about the centre of mass.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <vector>

namespace wobble {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// A point mass: mass in kg at position r_O_m (m) from the origin O of the frame.
struct PointMass {
  double mass_kg;
  Vec3 r_O_m;
};

/// Mass, centre of mass and inertia tensor about O of a body (all in frame F).
struct MassProperties {
  double mass_kg = 0.0;
  Vec3 r_cm_m = Vec3::Zero();  ///< centre of mass, from O
  Mat3 I_O = Mat3::Zero();     ///< inertia tensor about O, kg m^2
};

/// Inertia tensor about O of point masses.
/// @throws std::invalid_argument if a mass is negative or not finite, or a position not finite.
Mat3 inertia_of_point_masses(const std::vector<PointMass>& masses);

/// Mass properties (total mass, centre of mass, I about O) of point masses.
/// @throws std::invalid_argument as inertia_of_point_masses, or if the total mass is zero.
MassProperties mass_properties(const std::vector<PointMass>& masses);

/// The tensor @f$ m (|d|^2 1 - d d^T) @f$ of a point mass m at d: the parallel-axis term.
Mat3 parallel_axis_term(double mass_kg, const Vec3& d_m);

/// Parallel-axis theorem: the tensor about a point P, given the tensor about the centre of mass
/// and P's offset from the centre of mass, r_P_from_cm: I_P = I_cm + m (|d|^2 1 - d d^T).
Mat3 shift_from_cm(const Mat3& I_cm, double mass_kg, const Vec3& r_P_from_cm);

/// The inverse shift: the tensor about the centre of mass given the tensor about P.
Mat3 shift_to_cm(const Mat3& I_P, double mass_kg, const Vec3& r_P_from_cm);

/// Composition: the mass properties of a body made of parts (all about the same O).
/// @throws std::invalid_argument if the total mass is zero.
MassProperties combine(const std::vector<MassProperties>& parts);

}  // namespace wobble
