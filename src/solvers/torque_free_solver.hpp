#pragma once
/// @file
/// The torque-free symmetric-top solver (`solver = "torque_free_symmetric"`): a body whose tensor
/// about its centre of mass is diag(I1, I1, I3) in the problem's axes (symmetric about z), spun
/// with w(0) = omega (sin(alpha) x + cos(alpha) z) from body axes = space axes (the `[motion]`
/// table). Quantities, by the names the keys use (README, "Solvers"):
///
///     I0, I                   I = I0 diag(p, p, q), smallest whole p, q when the ratio is
///                             rational                                             kg m^2
///     L0_body, L0_space       L at t = 0 in the body and space bases               kg m^2/s
///     angle_omega_e3,         the angles of w and L from e3                        rad
///       angle_L_e3
///     body_cone_half_angle,   (w, e3) and (w, L)                                   rad
///       space_cone_half_angle
///     Omega_body,             precession vectors (body frame; space frame at t = 0) rad/s
///       Omega_space
///     Omega_body_rate,        signed component along e3; magnitude                 rad/s
///       Omega_space_rate
///     identity_residual       |Omega_space - Omega_body - w| from the three vectors,
///                             numerically                                          rad/s
///     max_angle,              the largest angle (z, e3); its series' leading term  rad
///       max_angle_small_alpha
///     t_max                   the first time that angle is reached                 s
///
/// Formulas: core/torque_free_symmetric.hpp, whose numeric closed forms check these exact ones.
#include <string>

#include "core/inertia.hpp"
#include "problem/problem.hpp"
#include "solvers/key.hpp"

namespace wobble {

/// @throws InputError: a body that is not symmetric about z (products of inertia or
///   I_xx != I_yy), a missing [motion] table, alpha not a parameter or outside [0, pi/2),
///   omega not > 0, an unknown quantity; and all of build_inertia_body's.
Key solve_torque_free_symmetric(const Problem& problem, const sym::Values& values);

/// The geometry of the sketch of parts (c) and (d), at t = 0, in space axes: unit vectors along
/// e3, w and L, the cones' half angles, and the signed precession rates.
struct TopSketch {
  std::string title;
  Vec3 e3, omega, L;            ///< unit vectors (e3 = z)
  double body_half_angle = 0;   ///< (w, e3): the body cone about e3 through w, rad
  double space_half_angle = 0;  ///< (w, L): the space cone about L through w, rad
  double body_rate = 0;         ///< Omega_body along e3 (sign: sense of precession), rad/s
  double space_rate = 0;        ///< |Omega_space|, along L, rad/s
  std::string kind;             ///< "prolate", "oblate" or "spherical"
};

/// @throws as solve_torque_free_symmetric.
TopSketch top_sketch(const Problem& problem, const sym::Values& values);

}  // namespace wobble
