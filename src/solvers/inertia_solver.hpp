#pragma once
/// @file
/// The inertia solver (`solver = "inertia"`): a body of point masses and/or uniform shapes, or a
/// tensor given directly (no mass, no centre of mass then). Its quantities, with units and
/// meanings, are the rows of its table (`wobble solvers`, README "Solvers").
#include "problem/problem.hpp"
#include "solvers/key.hpp"
#include "solvers/registry.hpp"

namespace wobble {

/// @throws InputError: see build_inertia_body; also a quantity that needs a mass when the
///         tensor is given directly.
Key solve_inertia(const Problem& problem, const sym::Values& values);

/// Its registry entry.
SolverInfo inertia_solver();

}  // namespace wobble
