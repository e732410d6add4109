#pragma once
/// @file
/// Refusing expression text that GiNaC's parser would crash on or compute forever, before it
/// sees it (found by fuzzing): control and non-ASCII characters; a function called
/// with no arguments ("sqrt()" crashes GiNaC 1.8.6's parser); a number with more than 50 digits
/// or an exponent beyond 400; and exact powers whose exponents, multiplied along a chain of
/// nested powers, exceed 1000 ("10^99999999" or "((2^999)^999)^999" would be computed digit by
/// digit). A power inside an exponent is refused too, and so is a signed exponent without
/// parentheses (GiNaC reads x^-2+y as x^(-2+y)). Textbook expressions stay far below.
#include <ginac/ginac.h>

#include <string>

#include "symbolic/expression.hpp"

namespace wobble::sym {

/// Whether an expression may call `name`: sqrt, sin, .., log or ln, .., EllipticK.
bool is_function_name(const std::string& name);

/// @throws ExpressionError "FIELD: expression "SHOWN" is refused: WHY".
void check_expression_cost(const std::string& text, const std::string& field,
                           const std::string& shown, const GiNaC::symtab& symbols);

}  // namespace wobble::sym
