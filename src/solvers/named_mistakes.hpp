#pragma once
/// @file
/// The problem file's named mistakes of each answer (problem/problem.hpp MistakeSpec), as the
/// judge's approximations of that answer (solvers/key.hpp), in the answer's unit at the values
/// the key is solved at. A value is either a constant with its unit ("433 day", the same in every
/// variant, as an observation is) or an expression in the problem's parameters, in SI
/// ("m*R^2/2", the moment about the other axis, which follows each variant's values).
#include "problem/problem.hpp"
#include "solvers/key.hpp"
#include "symbolic/expression.hpp"

namespace wobble {

/// Adds each answer's named mistakes to `key` (solved from `problem` at `values`); an
/// expression with no value at `values` (m R²/α at α = 0) names nothing there.
/// @throws InputError naming the file and the field: a mistake for an answer that is no single
///   number, a constant of another dimension, an expression that does not read or has no value
///   at the problem's defaults, or one whose dimension is not the answer's (it does not scale as
///   the answer's unit when the units of mass, length and time do: `m*R` for a moment of
///   inertia), tested at the defaults and again at `values` where its value there is not zero.
void add_named_mistakes(const Problem& problem, const sym::Values& values, Key& key);

}  // namespace wobble
