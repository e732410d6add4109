#pragma once
/// @file
/// A quantity written in a problem or scene file: an expression in the file's parameters, in the
/// SI unit its field takes, or a value followed by a unit of its own, converted exactly.
///
/// "2", "2*pi/omega", "M", "500 ms", "200 g", "4 cm", "1432 rpm", "30deg", "30°",
/// "(90 - 15) deg", "5 [cm]" (units: symbolic/units.hpp). The conversion multiplies the value by
/// the unit's exact factor, so "4 cm" is the rational 1/25 m: a key built from it stays exact,
/// and its value is rounded once (30 deg is the double nearest pi/6).
/// The expression is read first: a parameter named like a unit ("m", "g") stays the parameter in
/// "2*m", while "0.5 m", which is no expression (a product needs '*'), is half a metre.
#include <ginac/ginac.h>

#include <string>

#include "symbolic/expression.hpp"

namespace wobble::sym {

/// `text` (Unicode or ASCII notation) as an expression in SI `si_unit` ("kg", "m", "s",
/// "rad/s", "m/s^2", "kg m^2"; "rad" for an angle; "" for a pure number).
/// @throws ExpressionError naming `field`: an expression that does not read and has no unit
///   after it (the parser's own message), a unit of another dimension ("'2 m' is in m (length);
///   it must be in s (time)"), a word after a value that is no unit ("cannot read the unit
///   'parsecs'"), a unit inside the expression (refuse_unit_inside).
GiNaC::ex parse_quantity(const SymbolTable& table, const std::string& text,
                         const std::string& field, const std::string& si_unit);

/// @throws ExpressionError naming `field` and `text` (as written; `ascii` is it read as ASCII)
///   where one unit stands inside the expression, "(10deg)*(pi/3)", a file and --set taking one
///   only after the whole value: "'deg' is a unit inside the expression; a unit goes once, after
///   the whole value", with the value so written ("((10)*(pi/3)) deg") where the unit multiplies
///   all of it and is of `si_unit`'s kind. Nothing where a name in it is neither a unit nor one
///   of `table`'s, or two units are.
void refuse_unit_inside(const SymbolTable& table, const std::string& ascii, const std::string& text,
                        const std::string& field, const std::string& si_unit);

/// The same quantity as ASCII expression text in SI, for a caller that builds a larger
/// expression from it (a problem's motion turned into a scene's): the text itself when it is an
/// expression, else "(value)*(factor)/(factor)" with the units' exact factors.
/// @throws as parse_quantity.
std::string quantity_expression(const SymbolTable& table, const std::string& text,
                                const std::string& field, const std::string& si_unit);

}  // namespace wobble::sym
