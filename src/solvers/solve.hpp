#pragma once
/// @file
/// The solvers, by the name a problem file gives in `solver`.
#include <functional>
#include <string>
#include <vector>

#include "problem/problem.hpp"
#include "solvers/key.hpp"

namespace wobble {

/// The key of `problem` at the parameter `values` (SI, every parameter present).
/// @throws InputError for an unknown solver, an answer the solver cannot compute, or bad input
///         found while solving (see the solver's header).
Key solve(const Problem& problem, const sym::Values& values);

/// The parts of `problem` from its answer specs: `compute(quantity)` for each answer, renamed
/// to the spec's name, with the steps of a part's answers merged (shared steps once).
Key assemble_parts(const Problem& problem,
                   const std::function<Computed(const std::string& quantity)>& compute);

/// Names of the solvers, for messages and the README.
std::vector<std::string> solver_names();

/// The conventions every key states.
std::vector<std::string> key_conventions();

}  // namespace wobble
