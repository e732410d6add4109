#pragma once
/// @file
/// Internal to the check layer: the LaTeX words the answer reader knows (latex_answer.hpp), and
/// a unit as LaTeX sets it.
#include <map>
#include <optional>
#include <set>
#include <string>

namespace wobble::check {

/// Commands that draw a mark over a letter (\dot, \hat, \vec, ...): the symbol is the letter
/// with the mark, whatever the braces.
const std::set<std::string>& accents();

/// Greek letters' commands, lower and upper case, with \varphi \vartheta \varepsilon \varrho.
const std::set<std::string>& greek();

/// The letter a Greek command names in ASCII: "varphi" -> "phi", "alpha" -> "alpha".
std::string greek_name(const std::string& command);

/// LaTeX's function commands and the names the expression reader knows them by ("ln" -> "log",
/// "arctan" -> "atan").
const std::map<std::string, std::string>& function_commands();

/// Function names as typed in letters, or inside \operatorname: sin, atan2, sqrt, EllipticK ...
const std::set<std::string>& function_names();

/// Spacing commands (\, \; \quad ...): nothing but a gap.
const std::set<std::string>& spacing();

/// Commands that set text upright around a unit or a name: \mathrm, \text, ...
const std::set<std::string>& text_wrappers();

/// Delimiter sizes: \big, \Bigl, \biggr, ...
const std::set<std::string>& sizes();

/// A unit as LaTeX sets it, in the unit grammar's words (symbolic/symbolic/units.hpp):
/// "\,\mathrm{kg\,m^{2}/s}" -> "kg m^2/s", "^\circ" -> "deg". nullopt for what no unit has (a
/// command other than spacing, \mathrm, \cdot between units; a start other than a unit's name
/// or 1/).
std::optional<std::string> latex_unit_text(const std::string& raw);

}  // namespace wobble::check
