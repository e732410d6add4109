#pragma once
/// @file
/// The dimension of an expression in a problem's parameters, read off its structure: a
/// parameter has its unit's powers of mass, length and time (an angle in rad and a pure number
/// none); a product adds them, a rational power multiplies them; the terms of a sum must share
/// one dimension, an exponent and the arguments of sin, exp, atan and the other functions must
/// have none (atan2's two the same, abs keeps its argument's). An expression that breaks one of
/// these (m + R, sin(omega), m^alpha) is mixed.
///
/// Used to tell a student why a wrong expression is wrong ("m R/4 is a mass × length; I0 is in
/// kg m²") and to check that every closed form of a key has its unit's dimension. No verdict
/// rests on it: an expression is right or wrong by its values (judge.hpp).
#include <array>
#include <optional>
#include <string>

#include "solvers/key.hpp"
#include "symbolic/expression.hpp"

namespace wobble::check {

struct ExpressionDimension {
  bool mixed = false;  ///< its parts have unlike dimensions
  /// Powers of mass, length, time, when not mixed and each a whole number (no unit has
  /// sqrt(m)'s mass^(1/2)).
  std::optional<std::array<int, 3>> dim;
  std::string words;  ///< "mass × length²", "mass^(1/2) × length", "a pure number" (not mixed)
};

/// The dimension of `e`, each parameter's unit as `key` lists it. Nothing when it cannot be
/// told: `e` names no parameter (a plain number, whose unit is not written), a symbol that is
/// no parameter of the key, or a unit that does not read.
std::optional<ExpressionDimension> expression_dimension(const GiNaC::ex& e, const Key& key);

}  // namespace wobble::check
