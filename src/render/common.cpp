#include "render/common.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <vector>

#include "problem/values.hpp"
#include "solvers/key.hpp"
#include "symbolic/unicode_notation.hpp"

namespace wobble::detail {

const std::map<std::string, std::string>& greek() { return sym::greek_letters(); }

std::string pretty(const std::string& s) { return sym::to_unicode(s); }

std::optional<std::string> whole_degrees(const ParameterValue& p) {
  if (p.unit != "rad" || p.value == 0.0) return std::nullopt;
  const double half_degrees = p.value * 360 / M_PI;
  const double rounded = std::round(half_degrees);
  // A value typed as "15deg" is the double nearest 15 pi/180: within a few ulps of it; a value
  // 1e-9 away from whole half degrees was not typed in degrees.
  constexpr double kTypedInDegrees = 1e-9;
  if (std::abs(half_degrees - rounded) > kTypedInDegrees * std::max(1.0, std::abs(rounded))) {
    return std::nullopt;
  }
  return format_number(rounded / 2);
}

std::string parameter_value_text(const ParameterValue& p) {
  if (const auto deg = whole_degrees(p)) return *deg + "° = " + format_number(p.value) + " rad";
  return format_number(p.value) + unit_text(p.unit);
}

std::string parameter_value_latex(const ParameterValue& p) {
  if (const auto deg = whole_degrees(p)) {
    return *deg + "^\\circ = " + number_latex(p.value) + unit_latex(p.unit);
  }
  // A page shows no e-notation: 8.034e+37 as 8.034 \times 10^{37}.
  return number_latex(p.value) + unit_latex(p.unit);
}

std::pair<std::string, std::string> shown_value(
    const ParameterValue& p, const std::vector<std::pair<std::string, std::string>>& shown) {
  for (const auto& [name, text] : shown) {
    if (name != p.name) continue;
    // As typed, with the unit it was typed in: "22deg" as 22°, "5 cm" as 5 cm.
    const auto [value, unit] = typed_value_parts(text);
    if (unit == "deg") return {value, "°"};
    return {value, unit.empty() ? p.unit : unit};
  }
  if (const auto deg = whole_degrees(p)) return {*deg, "°"};
  return {format_number(p.value), p.unit};
}

std::string markdown_cell(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '|') {
      out += "\\|";
    } else if (c == '\n') {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out;
}

std::string unit_text(const std::string& unit) {
  std::string out = pretty(unit);
  if (!out.empty()) out.insert(out.begin(), ' ');
  return out;
}

std::string unit_latex(const std::string& unit) {
  if (unit.empty()) return "";
  std::string out = "\\,\\mathrm{";
  for (std::size_t i = 0; i < unit.size(); ++i) {
    if (unit[i] == ' ') {
      out += "\\,";
    } else if (unit[i] == '^') {
      std::size_t j = i + 1;
      while (j < unit.size() &&
             (std::isdigit(static_cast<unsigned char>(unit[j])) || unit[j] == '-'))
        ++j;
      out += "^{" + unit.substr(i + 1, j - i - 1) + "}";
      i = j - 1;
    } else {
      out += unit[i];
    }
  }
  return out + "}";
}

std::string value_text(const Value& v, const std::string& indent) {
  if (v.shape == Value::Shape::scalar) return format_number(v.data.at(0));
  if (v.shape == Value::Shape::vector) {
    std::string s = "(";
    for (std::size_t i = 0; i < v.data.size(); ++i) s += (i ? ", " : "") + format_number(v.data[i]);
    return s + ")";
  }
  std::vector<std::size_t> width(v.cols, 0);
  for (std::size_t i = 0; i < v.rows; ++i) {
    for (std::size_t j = 0; j < v.cols; ++j) {
      width[j] = std::max(width[j], format_number(v.at(i, j)).size());
    }
  }
  std::string s;
  for (std::size_t i = 0; i < v.rows; ++i) {
    s += (i ? "\n" + indent : "") + "[";
    for (std::size_t j = 0; j < v.cols; ++j) {
      const std::string n = format_number(v.at(i, j));
      s.append(1 + width[j] - n.size(), ' ');
      s += n;
    }
    s += " ]";
  }
  return s;
}

std::string absent_answer_text(const PartKey& part, std::size_t i) {
  const std::string why = i < part.absent_why.size() ? part.absent_why[i] : "";
  for (std::size_t k = 0; k < part.steps.size() && !why.empty(); ++k) {
    if (part.steps[k].text == why)
      return fmt::format("none at these values (step {} says why)", k + 1);
  }
  return "none at these values (the steps say why)";
}

}  // namespace wobble::detail
