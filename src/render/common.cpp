#include "render/common.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <vector>

#include "solvers/key.hpp"
#include "symbolic/unicode_notation.hpp"

namespace wobble::detail {

const std::map<std::string, std::string>& greek() { return sym::greek_letters(); }

std::string pretty(const std::string& s) { return sym::to_unicode(s); }

std::optional<std::string> whole_degrees(const ParameterValue& p) {
  if (p.unit != "rad" || p.value == 0.0) return std::nullopt;
  const double half_degrees = p.value * 360 / M_PI;
  const double rounded = std::round(half_degrees);
  // A value typed as "15deg" is the double nearest 15 pi/180: within a few ulps of it.
  if (std::abs(half_degrees - rounded) > 1e-9 * std::max(1.0, std::abs(rounded))) {
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
    return *deg + "^\\circ = " + format_number(p.value) + unit_latex(p.unit);
  }
  return format_number(p.value) + unit_latex(p.unit);
}

std::size_t display_width(const std::string& s) {
  std::size_t width = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto b = static_cast<unsigned char>(s[i]);
    if ((b & 0xC0) == 0x80) continue;  // a continuation byte
    // Combining diacritical marks U+0300..U+036F: bytes CC 80..CD AF.
    if ((b == 0xCC || b == 0xCD) && i + 1 < s.size()) continue;
    ++width;
  }
  return width;
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

namespace {
// "I_xy", "I_cm", "e_k" in prose: a letter, '_', then one to two lower-case letters or digits.
bool subscript_at(const std::string& s, std::size_t i, std::size_t& length) {
  if (i == 0 || i + 1 >= s.size() || s[i] != '_' ||
      !std::isalpha(static_cast<unsigned char>(s[i - 1]))) {
    return false;
  }
  if (i >= 2 && std::isalnum(static_cast<unsigned char>(s[i - 2]))) return false;
  std::size_t j = i + 1;
  while (j < s.size() && j - i - 1 < 3 &&
         (std::islower(static_cast<unsigned char>(s[j])) ||
          std::isdigit(static_cast<unsigned char>(s[j])))) {
    ++j;
  }
  length = j - i - 1;
  return length >= 1 && length <= 2 &&
         (j == s.size() || !std::isalnum(static_cast<unsigned char>(s[j])));
}
}  // namespace

std::string latex_text(const std::string& s) {
  static const std::vector<std::pair<std::string, std::string>> map{{"\\", "\\textbackslash{}"},
                                                                    {"&", "\\&"},
                                                                    {"%", "\\%"},
                                                                    {"#", "\\#"},
                                                                    {"_", "\\_"},
                                                                    {"{", "\\{"},
                                                                    {"}", "\\}"},
                                                                    {"~", "\\textasciitilde{}"},
                                                                    {"^", "\\textasciicircum{}"},
                                                                    {"Σ", "$\\Sigma$"},
                                                                    {"∫", "$\\int$"},
                                                                    {"δ", "$\\delta$"},
                                                                    {"λ", "$\\lambda$"},
                                                                    {"θ", "$\\theta$"},
                                                                    {"α", "$\\alpha$"},
                                                                    {"β", "$\\beta$"},
                                                                    {"γ", "$\\gamma$"},
                                                                    {"ω", "$\\omega$"},
                                                                    {"Ω", "$\\Omega$"},
                                                                    {"π", "$\\pi$"},
                                                                    {"φ", "$\\phi$"},
                                                                    {"ψ", "$\\psi$"},
                                                                    {"ε", "$\\epsilon$"},
                                                                    {"Δ", "$\\Delta$"},
                                                                    {"½", "$\\frac12$"},
                                                                    {"≈", "$\\approx$"},
                                                                    {"∝", "$\\propto$"},
                                                                    {"°", "$^\\circ$"},
                                                                    {"⁴", "$^4$"},
                                                                    {"⁻¹", "$^{-1}$"},
                                                                    {"̇", "$^{\\cdot}$"},
                                                                    {"≠", "$\\neq$"},
                                                                    {"²", "$^2$"},
                                                                    {"³", "$^3$"},
                                                                    {"ᵀ", "$^T$"},
                                                                    {"−", "$-$"},
                                                                    {"×", "$\\times$"},
                                                                    {"±", "$\\pm$"},
                                                                    {"·", "$\\cdot$"},
                                                                    {"√", "$\\surd$"},
                                                                    {"—", "---"},
                                                                    {"–", "--"},
                                                                    {"≥", "$\\geq$"},
                                                                    {"≤", "$\\leq$"},
                                                                    {"→", "$\\to$"}};
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    std::size_t sub = 0;
    if (subscript_at(s, i, sub)) {  // the letter before is already out: make it math
      out.back() = '$';
      out += std::string(1, s[i - 1]) + "_{" + s.substr(i + 1, sub) + "}$";
      i += 1 + sub;
      continue;
    }
    bool matched = false;
    for (const auto& [from, to] : map) {
      if (s.compare(i, from.size(), from) == 0) {
        out += to;
        i += from.size();
        matched = true;
        break;
      }
    }
    if (!matched) out += s[i++];
  }
  return out;
}

}  // namespace wobble::detail
