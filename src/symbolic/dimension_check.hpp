#pragma once
/// @file
/// A file's quantity against the dimension its field wants, from its parameters' units: with
/// `mass = "R"` and R a length, the key would be computed from so many kg. The dimension is
/// found from the value alone: at the table's probe values (a problem's defaults) the units of
/// mass, length and time are resized (1.7, 0.6, 2.3 times), all at once to test, one at a time to
/// name what it is. A sum is judged term by term, and a term that is a bare number has no unit
/// to tell (`m + 0.05` is a mass and 50 g more, in SI); so has a value that is zero or has none
/// at the probe. Inside the quantity a bare number takes the unit of the terms it is added to
/// (`m*(1 + R)` is in kg m), and a sum of unlike terms, a function's argument with a unit (but
/// abs's; atan2's two of one unit) and an exponent with one are refused wherever they stand.
/// A table without dimensions (SymbolTable::set_dimension) tells nothing.
#include <ginac/ginac.h>

#include <array>
#include <optional>
#include <string>

#include "symbolic/expression.hpp"

namespace wobble::sym {

/// The dimension of `e` (powers of kg, m, s) read from its form, as refuse_other_dimension takes
/// it before evaluating anything: a symbol's own; a number's none in a product; the sum of a
/// product's; a power's where the exponent makes whole powers; a sum's where every term names a
/// symbol and all have the same; a function's none where its arguments have none (abs its
/// argument's, atan2 two alike). nullopt anywhere else, or for a table without dimensions.
std::optional<std::array<int, 3>> dimension_by_form(const SymbolTable& table, const GiNaC::ex& e);

/// @throws ExpressionError naming `field` and `text` (the quantity as written) where `e`, or a
///   term of its sum, has a dimension other than `si_unit`'s ("kg", "rad/s"; "" a pure number),
///   or a part of it has none that can be right (above).
void refuse_other_dimension(const SymbolTable& table, const GiNaC::ex& e, const std::string& text,
                            const std::string& field, const std::string& si_unit);

}  // namespace wobble::sym
