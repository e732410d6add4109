#pragma once
/// @file
/// Helpers shared by the renderers (not part of the public interface of render/).
#include <map>
#include <string>

#include "solvers/key.hpp"

namespace wobble::detail {

/// Greek letter names and their Unicode letters ("alpha" -> "α").
const std::map<std::string, std::string>& greek();

/// GiNaC text made pleasant for a terminal: m*a^2 -> m·a², sqrt( -> √(, alpha -> α, Pi -> π.
std::string pretty(const std::string& ginac_text);

/// A unit for display: "kg m^2" -> "kg m²" (text) or "\mathrm{kg\,m^{2}}" (LaTeX).
std::string unit_text(const std::string& unit);
std::string unit_latex(const std::string& unit);

/// Numbers of a value: "3.5", "(1, 0, 0)", or matrix rows, one per line with the given indent.
std::string value_text(const Value& v, const std::string& indent);

/// Plain text with Unicode symbols for LaTeX text mode: escapes specials, maps Σ -> $\Sigma$ ...
std::string latex_text(const std::string& s);

}  // namespace wobble::detail
