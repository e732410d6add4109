#pragma once
/// @file
/// The Euler-angle solver (`solver = "euler_angles"`): Taylor's z-y-z angles phi, theta, psi and
/// their rates (the `[motion]` table; a PHY 711 problem names them alpha, beta, gamma, the same
/// rotations), and a body symmetric about e3 (its tensor diag(I1, I1, I3) in the body frame).
/// R = Rz(phi) Ry(theta) Rz(psi) takes body components to space components (its columns are
/// e1, e2, e3 in space); PHY 711's R(alpha, beta, gamma) takes inertial components to body ones:
/// it is R's transpose at alpha = phi, beta = theta, gamma = psi. Goldstein's z-x-z angles of the
/// same rotation are (phi + pi/2, theta, psi - pi/2). Angles are given in (-pi, pi] (phi, psi)
/// and [0, pi] (theta). Its quantities, with units and meanings, are the rows of its table
/// (`wobble solvers`, README "Solvers").
///
/// Each value is checked against core/euler_angles.hpp and core rotations (an independent route).
#include "problem/problem.hpp"
#include "solvers/key.hpp"
#include "solvers/registry.hpp"

namespace wobble {

/// @throws InputError: a body tensor that is not diag(I1, I1, I3), angles outside their ranges;
///   and all of build_inertia_body's.
Key solve_euler_angles(const Problem& problem, const sym::Values& values);

/// Its registry entry.
SolverInfo euler_angles_solver();

}  // namespace wobble
