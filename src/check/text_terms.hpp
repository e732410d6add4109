#pragma once
/// @file
/// A typed answer's text taken apart before it is read (inside the check layer only): where its
/// terms start at the top level, a bracket's factors around it, and whether its names are the
/// problem's symbols. Text only: nothing here is read as an expression.
#include <cstddef>
#include <string>

#include "symbolic/expression.hpp"

namespace wobble::check::detail {

/// Whether s has an identifier that is one of the problem's symbols.
bool has_identifier_of(const std::string& s, const sym::SymbolTable& table);
/// Whether all of s's identifiers are the problem's symbols (and it has one).
bool all_identifiers_of(const std::string& s, const sym::SymbolTable& table);

/// Whether the '+' or '-' at s[i] starts a term: not a leading sign, nor a factor's sign after
/// '*', '/', '^' or an exponent's e ("10^-4", "1e-4", "2*-1").
bool starts_term(const std::string& s, std::size_t i);

/// Whether s is one term: no '+' or '-' at its top level starts another ("[a, b]/2 + 1").
bool is_one_term(const std::string& s);

/// Whether X in `before` X `after` (each trimmed) is a factor of the term: not raised to a power
/// ("X^2", "2^X") and not divided by ("1/X").
bool is_factor_between(const std::string& before, const std::string& after);

/// `before` X `after` with 1 in X's place, joined by '*' where no '*' or '/' joins it: "2 [a, b]"
/// is a product where "2 1" would be refused, and "(1 - x)(1)" would read as rows. A sign before
/// X is its own ("-(a, b, c)": -1; X is one term, so the sign starts it).
std::string with_one_in_place(const std::string& before, const std::string& after);

}  // namespace wobble::check::detail
