#pragma once
/// @file
/// Solving a problem: its solver (solvers/registry.hpp) at parameter values, and the variants.
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

/// The "NAME=VALUE" assignments of variant n: the first of its draws (problem/variants.hpp) that
/// the problem accepts. Parameters drawn one by one can together make an invalid problem (an
/// asymmetric top's moments out of order, a heavy top too slow to precess steadily); the next
/// draw is as reproducible as the first.
/// @throws InputError for n out of range, or when 100 draws all fail (naming the last reason).
std::vector<std::string> variant_for(const Problem& problem, long n);

/// The conventions every key states.
std::vector<std::string> key_conventions();

}  // namespace wobble
