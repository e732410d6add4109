#pragma once
/// @file
/// The torque-free asymmetric-top solver (`solver = "asymmetric_top"`): a body whose tensor about
/// its centre of mass (or the tensor given) is diag(I1, I2, I3) in the problem's axes with
/// I1 < I2 < I3, spun with w(0) = (w1, w2, w3) in the body frame (the `[motion]` table).
/// Its quantities, with units and meanings, are the rows of its table (`wobble solvers`,
/// README "Solvers").
///
/// The exact forms use the factored invariants 2 T I3 - L^2 = I1 (I3-I1) w1^2 + I2 (I3-I2) w2^2
/// and L^2 - 2 T I1 = I2 (I2-I1) w2^2 + I3 (I3-I1) w3^2, so k'^2 has no cancellation; each is
/// checked against core's ExactFreeMotion (an independent double-precision route).
#include "problem/problem.hpp"
#include "solvers/key.hpp"
#include "solvers/registry.hpp"

namespace wobble {

/// @throws InputError: a tensor with products of inertia, moments not in the order
///   I1 < I2 < I3 (two equal: a symmetric top, for the torque_free_symmetric solver), w(0) zero
///   or not finite; the separatrix (L^2 = 2 T I2, no period) for the
///   period's quantities; and all of build_inertia_body's.
Key solve_asymmetric_top(const Problem& problem, const sym::Values& values);

/// Its registry entry.
SolverInfo asymmetric_top_solver();

}  // namespace wobble
