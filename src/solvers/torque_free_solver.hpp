#pragma once
/// @file
/// The torque-free symmetric-top solver (`solver = "torque_free_symmetric"`): a body whose tensor
/// about its centre of mass is diag(I1, I1, I3) in the problem's axes (symmetric about z), spun
/// with w(0) = omega (sin(alpha) x + cos(alpha) z) from body axes = space axes (the `[motion]`
/// table; alpha must name a parameter: max_angle_small_alpha is a series in it). Its quantities,
/// with units and meanings, are the rows of its table (`wobble solvers`, README "Solvers").
///
/// Formulas: core/torque_free_symmetric.hpp, whose numeric closed forms check these exact ones.
#include "problem/problem.hpp"
#include "solvers/key.hpp"
#include "solvers/registry.hpp"
#include "solvers/sketch.hpp"

namespace wobble {

/// @throws InputError: a body that is not symmetric about z (products of inertia or
///   I_xx != I_yy), alpha not a parameter or outside [0, pi/2), omega not > 0; and all of
///   build_inertia_body's.
Key solve_torque_free_symmetric(const Problem& problem, const sym::Values& values);

/// The geometry of the sketch of the cones at t = 0.
/// @throws as solve_torque_free_symmetric.
TopSketch top_sketch(const Problem& problem, const sym::Values& values);

/// Its registry entry.
SolverInfo torque_free_symmetric_solver();

}  // namespace wobble
