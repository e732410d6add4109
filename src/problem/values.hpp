#pragma once
/// @file
/// Parameter values: the defaults of a problem, overridden by `--set NAME=VALUE`.
///
/// A value is a number or a constant expression in the parameter's unit, SI ("0.5", "pi/6",
/// "sqrt(2)/10"), or with a unit of its own, converted exactly (symbolic/units.hpp): "5 cm",
/// "500 g", "30deg", "30°", "1432 rpm", "9.81 m/s²". Whatever a key prints as a parameter's
/// value reads back: the terminal's Unicode ("π/6") and both sides of "30° = 0.5235987756 rad"
/// (they must agree to the printed digits; the first is taken). A unit of another dimension, or
/// an angle for a pure number, is refused. Every value must be finite and inside the
/// parameter's range.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "problem/problem.hpp"

namespace wobble {

/// Reads one value for parameter p. `field` names the source in messages ("--set alpha").
/// @throws InputError naming the field and the text: not a number, not finite, out of range.
double parse_parameter_value(const Parameter& p, const std::string& text, const std::string& field);

/// Where an angle typed as `typed` is refused and `typed` is a number alone ("30", not "30 rad" or
/// "pi/6"), which reads as radians, while its degrees would be taken: "; a bare number is in
/// radians: for degrees write " and `written` ("theta0=30deg", "\"30deg\""); "" otherwise.
std::string degrees_meant_hint(const std::string& typed, bool degrees_taken,
                               const std::string& written);

/// "5%" or "0.5 %" as the fraction it is (0.05, 0.005), as a tolerance is said; nullopt for a
/// text that is not a number and a percent sign.
std::optional<double> percent_as_fraction(const std::string& text);

/// A value as typed, split for a handout to show it as given: its text and the unit it carries,
/// both in ASCII ("5 cm" and "5 [cm]" -> {"5", "cm"}, "30°" -> {"30", "deg"}, "0.05" ->
/// {"0.05", ""}); of a key's two sides, the first.
std::pair<std::string, std::string> typed_value_parts(const std::string& text);

/// The longest assignment --set reads: a value is a number or a short constant expression, and a
/// million digits is refused unread.
inline constexpr std::size_t kMaxSetLength = 1000;

/// One assignment "NAME=VALUE": the parameter it names (as Problem::parameter reads the name) and
/// the value's text, both trimmed; the value is not read here.
/// @throws InputError for a malformed or overlong assignment, or an unknown name.
struct Assignment {
  const Parameter& parameter;
  std::string value;
};
Assignment assignment_of(const Problem& problem, const std::string& text);

/// The problem's defaults with the assignments "NAME=VALUE" applied in order (NAME as
/// Problem::parameter reads it: "theta0", "θ0", "theta_0").
/// @throws InputError for a malformed assignment, an unknown name or a bad value.
sym::Values parameter_values(const Problem& problem, const std::vector<std::string>& assignments);

/// Reads an interval "(lo, hi)", "[lo, hi]", half-open either way; bounds are constant
/// expressions, `inf` or `-inf`. @throws InputError naming the field.
Interval parse_interval(const std::string& text, const std::string& field);
/// The same for a parameter's range, whose bounds may carry a unit as its default does
/// ("[0, 90deg]" for an angle in rad), converted exactly to the parameter's (SI) unit.
Interval parse_interval(const std::string& text, const std::string& field, const Parameter& p);

/// The user's --set assignments name each parameter once, however spelt (a variant's values may
/// be overridden by them, but "--set m=1 --set m=2" is a slip, not a choice).
/// @throws InputError naming the parameter and both values, or an unknown parameter.
void require_each_set_once(const Problem& problem, const std::vector<std::string>& assignments);

}  // namespace wobble
