#pragma once
/// @file
/// The Euler-angle solver (`solver = "euler_angles"`): Taylor's z-y-z angles phi, theta, psi and
/// their rates (the `[motion]` table; a PHY 711 problem names them alpha, beta, gamma, the same
/// rotations), and a body symmetric about e3 (its tensor diag(I1, I1, I3) in the body frame).
/// R = Rz(phi) Ry(theta) Rz(psi) takes body components to space components (its columns are
/// e1, e2, e3 in space); PHY 711's R(alpha, beta, gamma) takes inertial components to body ones:
/// it is R's transpose at alpha = phi, beta = theta, gamma = psi. Goldstein's z-x-z angles of the
/// same rotation are (phi + pi/2, theta, psi - pi/2). Angles are given in (-pi, pi] (phi, psi)
/// and [0, pi] (theta). Quantities, by the names the keys use (README, "Solvers"):
///
///     R_zyz, R_phy711         the rotation matrices of the two conventions          (none)
///     angles_phy711           (alpha, beta, gamma) = (phi, theta, psi)             rad
///     angles_zxz              Goldstein's angles of the same rotation              rad
///     omega_space, omega_body, omega_primed   w in the space, body and primed (after phi and
///                             theta, before psi) bases                              rad/s
///     L_primed, kinetic_energy  a symmetric top's L in the primed basis and T      kg m^2/s, J
///     angles_back_zyz, angles_back_zxz   the angles read back from R; at theta = 0 or pi
///                             only phi + psi (phi - psi) is defined: psi = 0        rad
///
/// Each value is checked against core/euler_angles.hpp and core rotations (an independent route).
#include "problem/problem.hpp"
#include "solvers/key.hpp"

namespace wobble {

/// @throws InputError: a body tensor that is not diag(I1, I1, I3), angles outside their ranges,
///   an unknown quantity; and all of build_inertia_body's.
Key solve_euler_angles(const Problem& problem, const sym::Values& values);

}  // namespace wobble
