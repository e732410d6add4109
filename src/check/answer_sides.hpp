#pragma once
/// @file
/// An answer's line parted as a student writes it (inside the check layer only: judge.cpp):
/// its sides at each '=' ("I0 = m·R²/4 = 0.00072 kg m²", a key's line pasted back), a label
/// of one name ("θ_L", "|L|", "E′", "ω̇(0)"), a squared label ("λ² = 83.38 s⁻²") and its root,
/// a value said to be approximate ("≈", "about"), and where principal axes stand in a list.
/// How a side reads, not whether it is right: that is the judge's.
#include <optional>
#include <string>
#include <vector>

#include "check/axes_judge.hpp"
#include "check/judge.hpp"
#include "symbolic/units.hpp"

namespace wobble::check::detail {

/// The sides of an answer as a key line shows it, "I0 = m·R²/4 = 0.00072 kg m²": split at each
/// '=' outside brackets (brackets.hpp's top_level), each trimmed, the answer's own name (or
/// nothing) on the left dropped.
std::vector<std::string> sides(const std::string& text, const std::string& name);

/// "cos" for "cos θ_max", "cos(theta_max)" where `a` is the angle theta_max (sin, tan alike),
/// else "": a side that is a function of the answer's own name.
std::string function_of_answer(const std::string& side, const Answer& a);

/// "≈ 4.995 rad/s", "φ̇ ≈ 4.995 rad/s", "~4.995", "about 4.995": a value given as approximate is
/// judged as given with '=' (every number is judged to a tolerance). A '~' only first: in LaTeX it
/// is a space.
std::string approximations_as_equal(const std::string& text);

/// "theta_L", "θ_L", "\theta_{L}", "E′", "ω̇(0)": one name, with no operator or number that would
/// make it an expression.
bool is_one_name(const std::string& side);

/// What a side squared gives: the root as the reader takes it, or, for a value whose unit has an
/// odd power ("λ² = 83.38 1/s"), no root and that unit (no square is in it) with the number.
struct SquaredLabel {
  std::string root;
  std::optional<Unit> odd_unit;
  std::string number;
};

/// "λ² = 83.38 s⁻²", "rate^2 = 83.38": a side that is one name squared, a label of the student's
/// (no symbol of the problem) or the answer's own name, gives the square of a scalar answer. Its
/// square root as the reader takes it, the unit's powers halved ("s^-2" -> "s^-1"); nothing for
/// any other side or a label that names a key's answer ("k² = .." is k2).
std::optional<SquaredLabel> root_of_squared_label(const std::string& label,
                                                  const std::string& value, const Context& ctx,
                                                  const Answer& a);

/// Where the axes are in a matrix written as `text`: vectors listed one by one, "[1, 1, 0], [1,
/// -1, 0], [0, 0, 1]", "(1, 0, 1)/√2, ..", "[x̂ + ẑ, x̂ − ẑ, ŷ]", are its rows; a matrix of rows
/// in one bracket, "[[..], [..], [..]]" as the key prints one, either way.
AxesLayout listed_layout(const std::string& text);

}  // namespace wobble::check::detail
