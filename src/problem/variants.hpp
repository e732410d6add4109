#pragma once
/// @file
/// Per-student variants: reproducible parameter values for variant N of a problem.
///
/// Each parameter's value is drawn from a generator seeded by (problem id, parameter name, N)
/// through FNV-1a and SplitMix64, so the same N gives the same numbers on every machine and
/// version, and adding a parameter does not change the others. The draw is log-uniform over
/// [default / 2, 2 default] clipped to the parameter's range (uniform over the range for a
/// finite range containing zero, e.g. an angle in [0, pi/2)), then rounded to what a handout
/// shows: 2 significant digits, or whole degrees for an angle. Values come back as the text a
/// student sees ("0.35", "22deg"), and the key is computed from exactly that text.
#include <functional>
#include <string>
#include <vector>

#include "problem/problem.hpp"

namespace wobble {

/// "NAME=VALUE" assignments for variant n (n >= 1), in the problem's parameter order. `draw` > 0
/// draws again for the same n (seeded by id, name, n and the draw): for values that together
/// make an invalid problem (moments out of order, a spin too slow), solvers/solve.hpp's
/// `variant_for` takes the first draw the problem accepts.
/// @throws InputError for n < 1 or n > 1000000.
std::vector<std::string> variant_assignments(const Problem& problem, long n, int draw = 0);

/// Variant n's assignments from the first of up to kVariantDraws draws that `accept` takes
/// (`accept` throws InputError to refuse a draw): a problem's solver, or a scene's setup.
/// @throws InputError naming the last refusal when no draw is accepted.
inline constexpr int kVariantDraws = 100;
std::vector<std::string> first_valid_variant(
    const Problem& problem, long n,
    const std::function<void(const std::vector<std::string>&)>& accept);

}  // namespace wobble
