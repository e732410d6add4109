#pragma once
/// @file
/// Symbols' names run together, as a product is written by hand: "mR^2/4" for m·R²/4, "2Mgl"
/// for 2·M·g·l. A name the problem does not have that splits into its symbols' names in one
/// way only is read as their product. Never a unit's letters ("120 mm" is a length, "kg" a
/// mass), a function's or a Greek letter's name, nor a name with an underscore; a name that
/// splits two ways ("abc" where a, b, ab and c are symbols) stays for the reader to refuse,
/// with a split as its hint. A function's name may end the run where its call or argument
/// follows, or stand before one symbol's name, its argument: "phidotcostheta" (as "φ̇cosθ"
/// reads in ASCII) is "phidot cos theta".
#include <string>

#include "symbolic/expression.hpp"

namespace wobble::check {

/// `text` (ASCII, as the answer reader has prepared it) with each such name written as the
/// product of its symbols: "mR^2/4" -> "m*R^2/4", "2mR^2" -> "2m*R^2".
std::string names_apart(const std::string& text, const sym::SymbolTable& table);

}  // namespace wobble::check
