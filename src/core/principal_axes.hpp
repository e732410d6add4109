#pragma once
/// @file
/// Principal moments and axes of an inertia tensor, in a canonical, deterministic form.
///
/// Conventions:
/// - Moments ascending: lambda1 <= lambda2 <= lambda3 (kg m^2).
/// - Axes are the unit columns e1, e2, e3 of `axes`, in the frame the tensor is given in.
///   e1 and e2 each have their largest-magnitude component positive; e3 = e1 x e2, so the set is
///   right-handed (where that contradicts the sign rule for e3, right-handedness wins).
///   Components whose magnitudes are within kSignTieTolerance of the largest count as tied, and
///   the first of them (x before y before z) decides the sign: exact ties such as (0, 1, -1)/sqrt 2
///   are then decided the same way on every machine.
/// - Degeneracy: two moments closer than kDegeneracyEps * eps * lambda3 are equal. The pair is
///   snapped to its mean, and its plane gets a fixed basis: the first in-plane axis is the
///   projection onto the plane of the coordinate axis (x, y, z) least aligned with the unique
///   axis (first of them on ties), the other completes the set; then the sign rule above applies.
///   All three equal: the moments are snapped to their mean and the axes are the frame's axes.
/// - Solver: Eigen's iterative SelfAdjointEigenSolver::compute(), not computeDirect(), whose
///   closed form loses up to 1e-8 relative and splits exact symmetric tops (see numerics notes).
#include "core/inertia.hpp"

namespace wobble {

/// Which moments are equal (within the degeneracy tolerance).
enum class Degeneracy { none, pair12, pair23, all };

struct PrincipalAxes {
  Vec3 moments = Vec3::Zero();   ///< ascending, kg m^2
  Mat3 axes = Mat3::Identity();  ///< columns e1, e2, e3
  Degeneracy degeneracy = Degeneracy::none;
  double degeneracy_tolerance = 0.0;  ///< absolute, kg m^2
};

/// Moments closer than this many machine epsilons times the largest moment are degenerate.
/// Why 16: a tensor assembled from rounded inputs carries entry errors of a few eps * |I|, and the
/// iterative solver adds a backward error ~ eps * |I|; measured splits of exactly degenerate
/// tensors stay below 4 eps * lambda3, and 16 leaves margin while being far below the 12
/// significant digits a key prints.
inline constexpr double kDegeneracyEps = 16.0;
/// Relative tolerance for deciding the largest-magnitude component of an axis (see file comment).
inline constexpr double kSignTieTolerance = 1e-10;

/// Which of the ascending moments are equal by the rule above: closer than kDegeneracyEps * eps *
/// scale, scale the largest magnitude of the tensor. The one rule for the key and for `check`.
Degeneracy degeneracy_of(const Vec3& ascending_moments, double scale);

/// Principal moments and axes of the symmetric tensor I (only its lower triangle is read).
/// @throws std::invalid_argument if I has a non-finite entry.
PrincipalAxes principal_axes(const Mat3& I);

/// Flips v so that its largest-magnitude component (ties as in the file comment) is positive.
Vec3 canonical_sign(const Vec3& v);

}  // namespace wobble
