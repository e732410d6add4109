#pragma once
/// @file
/// Deterministic printing of GiNaC expressions, as GiNaC-readable text and as LaTeX.
///
/// Why not GiNaC's own printer: it orders the terms of a sum and the factors of a product by
/// hash values that depend on how many symbols the process created before, so the same
/// expression prints differently in `wobble solve` and `wobble keys --check`. Golden keys need one
/// spelling. Here:
/// - the factors of a product come in the order coefficient, symbols (in declaration order),
///   functions and powers of sums (by their text); negative powers go to a denominator;
/// - the terms of a sum come positive first, then by the text of the term without its sign;
/// - sqrt(x) for x^(1/2); `Pi` for the constant. The text reads back with GiNaC's parser.
///
/// What is printed is kept, per thread, under the table's version and the style (bounded: emptied
/// beyond 4096 forms), so printing an expression or its parts again is a lookup.
#include <ginac/ginac.h>

#include <string>

#include "symbolic/expression.hpp"

namespace wobble::sym {

/// GiNaC-readable text, e.g. "m*a^2/6", "2*atan(2*tan(alpha))".
std::string to_text(const GiNaC::ex& e, const SymbolTable& table);

/// LaTeX (math mode, no delimiters), symbols spelled with their declared LaTeX.
std::string to_latex(const GiNaC::ex& e, const SymbolTable& table);

}  // namespace wobble::sym
