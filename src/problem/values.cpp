#include "problem/values.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "core/characters.hpp"
#include "symbolic/glued_numbers.hpp"
#include "symbolic/quantity.hpp"
#include "symbolic/unicode_notation.hpp"
#include "symbolic/units.hpp"

namespace wobble {

namespace {

std::string shortest(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

// A constant expression ("pi/6", "1e-3") times an exact factor (a unit's, "1/100"), rounded
// once; or +-inf. Messages show the text alone.
double constant_value(const std::string& text, const std::string& field,
                      const std::string& factor = "1") {
  const std::string t = trim(text);
  if (t == "inf" || t == "+inf") return std::numeric_limits<double>::infinity();
  if (t == "-inf") return -std::numeric_limits<double>::infinity();
  static const sym::SymbolTable no_symbols;
  return sym::evaluate(no_symbols.parse(t, field) * no_symbols.parse(factor, "unit factor"),
                       GiNaC::lst{}, field);
}
}  // namespace

namespace {
// "(lo, hi)" with each bound read by `bound`.
template <typename ReadBound>
Interval interval_of(const std::string& text, const std::string& field, ReadBound bound) {
  const std::string t = trim(text);
  const auto comma = t.find(',');
  if (t.size() < 5 || (t.front() != '(' && t.front() != '[') ||
      (t.back() != ')' && t.back() != ']') || comma == std::string::npos) {
    throw InputError(field +
                     ": expected an interval such as \"(0, inf)\" or \"[0, pi/2)\", got \"" + text +
                     "\"");
  }
  Interval r;
  r.text = t;
  r.lo_open = t.front() == '(';
  r.hi_open = t.back() == ')';
  r.lo = bound(t.substr(1, comma - 1));
  r.hi = bound(t.substr(comma + 1, t.size() - comma - 2));
  if (!(r.lo < r.hi)) throw InputError(field + ": empty interval \"" + text + "\"");
  return r;
}
}  // namespace

Interval parse_interval(const std::string& text, const std::string& field) {
  return interval_of(text, field,
                     [&](const std::string& bound) { return constant_value(bound, field); });
}

namespace {
// Two sides of a parameter as a key prints it, "30° = 0.5235987756 rad": the printed side has
// ten significant digits (format_number), so it is within half a unit of its tenth digit,
// 5e-10 of the value, of the exact side; twice that allows for the rounding of either.
constexpr double kPrintedSidesAgree = 1e-9;

// The unit of p's values, "" a pure number.
Unit unit_of(const Parameter& p) {
  return p.unit.empty() ? Unit{} : parse_unit(p.unit, "the unit of " + p.name);
}

// One side: a constant expression, in p's unit or with a unit of its own, converted exactly.
double one_value(const Parameter& p, const std::string& side, const std::string& text,
                 const std::string& field) {
  const std::string t = trim(side);
  if (t == "inf" || t == "-inf" || t == "+inf" || t == "nan" || t == "NaN") {
    throw InputError(field + ": value must be finite, got '" + text + "'");
  }
  const auto [value, unit] = split_value_unit(t);
  std::string factor = "1";
  if (!unit.empty()) {
    const Unit given = parse_unit(unit, field), wanted = unit_of(p);
    if (!unit_fits(given, wanted)) {
      // Shown as the expression reader shows a text: 40 characters at most.
      throw InputError(field + ": '" + printable(text, 40) + "' is in " + printable(unit, 40) +
                       " (" + given.dimension_words() + "), but " + p.name +
                       (p.unit.empty()
                            ? " is a pure number"
                            : " is in " + p.unit + " (" + wanted.dimension_words() + ")"));
    }
    factor = "(" + given.to_si_exact + ")/(" + wanted.to_si_exact + ")";
  }
  try {
    return constant_value(value, field, factor);
  } catch (const InputError& e) {
    const std::string why = e.what();
    if (why.find("characters long") != std::string::npos ||
        why.find("outside the range of double") != std::string::npos ||
        why.find("beyond any value") != std::string::npos ||
        why.find("nested deeper") != std::string::npos ||
        why.find("is refused") != std::string::npos) {
      throw InputError(why);
    }
    // "0.16 parsecs": a number and a word that is no unit; say which.
    if (const auto space = t.rfind(' '); unit.empty() && space != std::string::npos) {
      const std::string tail = trim(t.substr(space));
      bool number = false;
      try {
        (void)constant_value(t.substr(0, space), field);
        number = !tail.empty() && std::isalpha(static_cast<unsigned char>(tail[0]));
      } catch (const InputError&) {
      }
      if (number) (void)parse_unit(tail, field);  // throws its error
    }
    if (looks_like_decimal_comma(t)) {
      throw InputError(field + ": '" + text + "' is not a number (" + kDecimalCommaHint + ")");
    }
    // "90deg + 14.5deg": as in a file, "(90 + 14.5) deg".
    sym::refuse_unit_inside(sym::SymbolTable{}, sym::to_ascii(t), text, field, p.unit);
    throw InputError(field + ": '" + text + "' is not a number" +
                     (p.is_angle()     ? " (an angle: radians, or degrees as 30deg)"
                      : p.unit.empty() ? ""
                                       : " (a value in " + p.unit + ", or with its unit, as '0.5 " +
                                             p.unit + "')"));
  }
}
}  // namespace

Interval parse_interval(const std::string& text, const std::string& field, const Parameter& p) {
  return interval_of(text, field, [&](const std::string& bound) {
    const std::string b = trim(bound);
    if (b == "inf" || b == "+inf" || b == "-inf") return constant_value(b, field);
    return one_value(p, b, b, field);
  });
}

std::pair<std::string, std::string> typed_value_parts(const std::string& text) {
  const std::string t = sym::numbers_times_constants(sym::to_ascii(text));
  const auto [value, unit] = split_value_unit(trim(t.substr(0, t.find('='))));
  // The unit as the grammar read it: "[cm]" is cm.
  return {value, unit.empty() ? unit : parse_unit(unit, "").text};
}

std::optional<double> percent_as_fraction(const std::string& text) {
  const std::string t = trim(text);
  if (t.size() < 2 || t.back() != '%') return std::nullopt;
  const std::string number = trim(t.substr(0, t.size() - 1));
  double value = 0.0;
  const char* end = number.data() + number.size();
  const auto [rest, error] = std::from_chars(number.data(), end, value);
  if (error != std::errc() || rest != end || number.empty()) return std::nullopt;
  return value / 100.0;
}

std::string degrees_meant_hint(const std::string& typed, bool degrees_taken,
                               const std::string& written) {
  char* end = nullptr;
  const bool bare = !typed.empty() && (std::strtod(typed.c_str(), &end), *end == '\0');
  return bare && degrees_taken ? "; a bare number is in radians: for degrees write " + written : "";
}

double parse_parameter_value(const Parameter& p, const std::string& text,
                             const std::string& field) {
  // As a key prints it: "θ0 = 30° = 0.5235987756 rad", "g = 9.81 m/s²", "π/6".
  const std::string t = sym::numbers_times_constants(sym::to_ascii(text));
  double v = 0.0;
  if (const auto eq = t.find('='); eq != std::string::npos) {
    if (t.find('=', eq + 1) != std::string::npos) {
      throw InputError(field + ": '" + text + "' has more than two sides; give one value");
    }
    v = one_value(p, compound_quantity(sexagesimal_degrees(t.substr(0, eq), field)), text, field);
    const double printed =
        one_value(p, compound_quantity(sexagesimal_degrees(t.substr(eq + 1), field)), text, field);
    if (!(std::abs(printed - v) <= kPrintedSidesAgree * std::abs(v))) {
      throw InputError(field + ": the two sides of '" + text + "' differ (" + shortest(v) +
                       " and " + shortest(printed) + (p.unit.empty() ? "" : " " + p.unit) +
                       "); give one value");
    }
  } else {
    v = one_value(p, compound_quantity(sexagesimal_degrees(t, field)), text,
                  field);  // "30°15′": "(30 + 15/60) deg"
  }
  if (!std::isfinite(v)) throw InputError(field + ": value must be finite, got '" + text + "'");
  if (!p.range.contains(v)) {
    // "alpha = 90deg = 1.570796327 rad": as typed too, where that is not the value in SI (and
    // as typed alone where it already has both sides).
    const std::string typed = trim(text), si = shortest(v) + (p.unit.empty() ? "" : " " + p.unit);
    const std::string shown = typed.find('=') != std::string::npos  ? typed
                              : typed == si || typed == shortest(v) ? si
                                                                    : typed + " = " + si;
    // "theta0=30" for 30 degrees.
    throw InputError(field + ": " + p.name + " = " + shown + " is outside its range " +
                     p.range.text +
                     degrees_meant_hint(typed, p.is_angle() && p.range.contains(v * M_PI / 180.0),
                                        field.starts_with("--") ? p.name + "=" + typed + "deg"
                                                                : "\"" + typed + "deg\""));
  }
  return v;
}

namespace {
// Whether `rest` begins "NAME=" for one of the problem's parameters ("R=0.1", " R = 0.1" after a
// comma). After a space, only "NAME=" with nothing between: "500 g = 0.5 kg" is one value's two
// sides, not the parameter g.
bool starts_assignment(const Problem& problem, const std::string& rest, bool after_space) {
  const auto eq = rest.find('=');
  if (eq == std::string::npos || eq == 0 || (after_space && rest[eq - 1] == ' ')) return false;
  const std::string name = trim(rest.substr(0, eq));
  if (name.empty() || (after_space && name.find(' ') != std::string::npos)) return false;
  try {
    (void)problem.parameter(name);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

// "--set m=0.5,R=0.1" (or with ';' or a space): several parameters in one, as some tools take
// them. Read as one value it would be refused as "not a number"; say what to type instead.
void refuse_several_at_once(const Problem& problem, const std::string& text, std::size_t eq) {
  for (const char separator : {',', ';', ' '}) {
    std::vector<std::size_t> cuts;  // where another NAME=VALUE begins, just past a separator
    for (std::size_t at = text.find(separator, eq); at != std::string::npos;
         at = text.find(separator, at + 1)) {
      if (starts_assignment(problem, text.substr(at + 1), separator == ' ')) cuts.push_back(at);
    }
    if (cuts.empty()) continue;
    cuts.push_back(text.size());
    // Each as a shell takes it: quoted where it has a space ("R=5 cm").
    const auto option = [](const std::string& one) {
      return one.find(' ') == std::string::npos ? "--set " + one : "--set '" + one + "'";
    };
    std::string each = option(trim(text.substr(0, cuts[0])));
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
      each += " " + option(trim(text.substr(cuts[k] + 1, cuts[k + 1] - cuts[k] - 1)));
    throw InputError("--set: '" + text +
                     "' sets several parameters; give each its own --set: " + each);
  }
}
}  // namespace

Assignment assignment_of(const Problem& problem, const std::string& text) {
  if (text.size() > kMaxSetLength) {
    throw InputError("--set: " + std::to_string(text.size()) +
                     " characters; NAME=VALUE may have at most " + std::to_string(kMaxSetLength));
  }
  const auto eq = text.find('=');
  if (eq == std::string::npos || trim(text.substr(0, eq)).empty()) {
    throw InputError("--set: expected NAME=VALUE, got '" + text + "'");
  }
  const Parameter& parameter = [&]() -> const Parameter& {
    try {
      return problem.parameter(trim(text.substr(0, eq)));
    } catch (const InputError& e) {
      throw InputError("--set " + text + ": " + e.what());  // the option and what was typed
    }
  }();
  const std::string value = trim(text.substr(eq + 1));
  refuse_several_at_once(problem, text, eq);
  return {parameter, value};
}

namespace {
// assignment_of the k-th --set, where a word without '=' after another --set is most likely the
// rest of that one's value, which the shell split off at a space: "--set omega=10 rpm".
Assignment assignment_in(const Problem& problem, const std::vector<std::string>& assignments,
                         std::size_t k) {
  const std::string& text = assignments[k];
  if (k > 0 && text.find('=') == std::string::npos && !trim(text).empty() &&
      text.size() <= kMaxSetLength && assignments[k - 1].find('=') != std::string::npos) {
    const std::string whole = assignments[k - 1] + " " + text;
    throw InputError("--set: expected NAME=VALUE, got '" + text + "' (the rest of '" +
                     assignments[k - 1] + "', split at its space? quote it: --set '" + whole +
                     "')");
  }
  return assignment_of(problem, text);
}
}  // namespace

sym::Values parameter_values(const Problem& problem, const std::vector<std::string>& assignments) {
  sym::Values values;
  for (const auto& p : problem.parameters) values[p.name] = p.default_value;
  // Every assignment's shape before any value: a word the shell split off ("--set omega=10
  // rpm") is named as such, not the value it left behind.
  std::vector<Assignment> each;
  for (std::size_t k = 0; k < assignments.size(); ++k)
    each.push_back(assignment_in(problem, assignments, k));
  for (const Assignment& a : each) {
    values[a.parameter.name] =
        parse_parameter_value(a.parameter, a.value, "--set " + a.parameter.name);
  }
  return values;
}

void require_each_set_once(const Problem& problem, const std::vector<std::string>& assignments) {
  std::map<std::string, std::string> seen;
  for (std::size_t k = 0; k < assignments.size(); ++k) {
    const Assignment a = assignment_in(problem, assignments, k);  // "θ0" is theta0
    const auto [it, fresh] = seen.emplace(a.parameter.name, a.value);
    if (!fresh) {
      throw InputError("--set " + a.parameter.name + ": given twice ('" + it->second + "' and '" +
                       a.value + "'); give each parameter once");
    }
  }
}

}  // namespace wobble
