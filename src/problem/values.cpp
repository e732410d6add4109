#include "problem/values.hpp"

#include <map>

#include <cmath>
#include <cstdio>
#include <limits>

namespace wobble {

namespace {
std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

std::string shortest(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

// A constant expression ("pi/6", "1e-3"), or +-inf.
double constant_value(const std::string& text, const std::string& field) {
  const std::string t = trim(text);
  if (t == "inf" || t == "+inf") return std::numeric_limits<double>::infinity();
  if (t == "-inf") return -std::numeric_limits<double>::infinity();
  static const sym::SymbolTable no_symbols;
  return sym::evaluate(no_symbols.parse(t, field), GiNaC::lst{}, field);
}
}  // namespace

Interval parse_interval(const std::string& text, const std::string& field) {
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
  r.lo = constant_value(t.substr(1, comma - 1), field);
  r.hi = constant_value(t.substr(comma + 1, t.size() - comma - 2), field);
  if (!(r.lo < r.hi)) throw InputError(field + ": empty interval \"" + text + "\"");
  return r;
}

double parse_parameter_value(const Parameter& p, const std::string& text,
                             const std::string& field) {
  std::string t = trim(text);
  bool degrees = false;
  for (const std::string suffix : {"deg", "°"}) {
    if (t.size() > suffix.size() &&
        t.compare(t.size() - suffix.size(), suffix.size(), suffix) == 0) {
      if (!p.is_angle()) {
        throw InputError(field + ": '" + text + "' is in degrees but " + p.name + " is in " +
                         p.unit);
      }
      degrees = true;
      t = trim(t.substr(0, t.size() - suffix.size()));
      break;
    }
  }
  if (t == "inf" || t == "-inf" || t == "+inf" || t == "nan" || t == "NaN") {
    throw InputError(field + ": value must be finite, got '" + text + "'");
  }
  double v = 0.0;
  try {
    // Degrees are converted exactly (x*pi/180, rounded once), so 90deg is the double of pi/2.
    v = degrees ? constant_value("(" + t + ")*pi/180", field) : constant_value(t, field);
  } catch (const InputError& e) {
    const std::string why = e.what();
    if (why.find("characters long") != std::string::npos ||
        why.find("outside the range of double") != std::string::npos ||
        why.find("beyond any value") != std::string::npos ||
        why.find("nested deeper") != std::string::npos ||
        why.find("is refused") != std::string::npos) {
      throw InputError(why);
    }
    throw InputError(field + ": '" + text + "' is not a number" +
                     (p.is_angle() ? " (an angle: radians, or degrees as 30deg)" : ""));
  }
  if (!std::isfinite(v)) throw InputError(field + ": value must be finite, got '" + text + "'");
  if (!p.range.contains(v)) {
    throw InputError(field + ": " + p.name + " = " + shortest(v) +
                     (p.unit.empty() ? "" : " " + p.unit) + " is outside its range " +
                     p.range.text);
  }
  return v;
}

sym::Values parameter_values(const Problem& problem, const std::vector<std::string>& assignments) {
  sym::Values values;
  for (const auto& p : problem.parameters) values[p.name] = p.default_value;
  for (const auto& a : assignments) {
    // A value is a number or a short constant expression; a million digits is refused unread.
    if (a.size() > 1000) {
      throw InputError("--set: " + std::to_string(a.size()) +
                       " characters; NAME=VALUE may have at most 1000");
    }
    const auto eq = a.find('=');
    if (eq == std::string::npos || trim(a.substr(0, eq)).empty()) {
      throw InputError("--set: expected NAME=VALUE, got '" + a + "'");
    }
    const std::string name = trim(a.substr(0, eq));
    const Parameter& p = problem.parameter(name);
    values[name] = parse_parameter_value(p, a.substr(eq + 1), "--set " + name);
  }
  return values;
}

void require_each_set_once(const std::vector<std::string>& assignments) {
  std::map<std::string, std::string> seen;
  for (const auto& a : assignments) {
    const auto eq = a.find('=');
    if (eq == std::string::npos) continue;  // parameter_values says what is wrong with it
    const std::string name = trim(a.substr(0, eq));
    const auto [it, fresh] = seen.emplace(name, trim(a.substr(eq + 1)));
    if (!fresh) {
      throw InputError("--set " + name + ": given twice ('" + it->second + "' and '" +
                       trim(a.substr(eq + 1)) + "'); give each parameter once");
    }
  }
}

}  // namespace wobble
