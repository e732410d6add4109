#pragma once
/// @file
/// Helpers shared by the renderers (not part of the public interface of render/).
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "solvers/key.hpp"

namespace wobble::detail {

/// Greek letter names and their Unicode letters ("alpha" -> "α").
const std::map<std::string, std::string>& greek();

/// GiNaC text made pleasant for a terminal: m*a^2 -> m·a², sqrt( -> √(, alpha -> α, Pi -> π.
std::string pretty(const std::string& ginac_text);

/// A unit for display: "kg m^2" -> "kg m²" (text) or "\mathrm{kg\,m^{2}}" (LaTeX).
std::string unit_text(const std::string& unit);
std::string unit_latex(const std::string& unit);

/// What a key says for its part's `i`-th answer that does not exist at these values, after the
/// answer's name: "none at these values (step 2 says why)", the step the one that says why
/// (PartKey::absent_why), else "(the steps say why)". `check` reads it back as "none".
std::string absent_answer_text(const PartKey& part, std::size_t i);

/// Numbers of a value: "3.5", "(1, 0, 0)", or matrix rows, one per line with the given indent.
std::string value_text(const Value& v, const std::string& indent);

/// An angle at a whole or half degree, in degrees ("15"), else nullopt: parameters given in
/// degrees are shown in degrees, with radians after.
std::optional<std::string> whole_degrees(const ParameterValue& p);

/// A parameter's value as a key shows it: "0.2 kg", "15° = 0.2617993878 rad" (Unicode text),
/// or the same in LaTeX math ("15^\circ = 0.2617993878\,\mathrm{rad}").
std::string parameter_value_text(const ParameterValue& p);
std::string parameter_value_latex(const ParameterValue& p);

/// A parameter's value and unit as a handout shows them: as typed, a variant's or --set's own
/// text with its unit ("22deg" -> {"22", "°"}, "5 cm" -> {"5", "cm"}), else the key's value (an
/// angle at whole degrees in degrees, unit "°"). `shown` names parameters by identifier.
std::pair<std::string, std::string> shown_value(
    const ParameterValue& p, const std::vector<std::pair<std::string, std::string>>& shown);

/// A formula's one pmatrix as the LaTeX key sets it: its fractions at full size (\dfrac), its
/// rows set apart (\\[2ex]); `latex` itself where no cell has a fraction (or there is no one
/// pmatrix).
std::string matrix_fractions_displayed(const std::string& latex);

/// Text for one Markdown table cell: '|' escaped, line breaks as spaces.
std::string markdown_cell(const std::string& s);

}  // namespace wobble::detail
