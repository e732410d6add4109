#include "render/common.hpp"

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

std::optional<std::string> name_latex(const std::string& name) {
  const auto us = name.find('_');
  if (us == std::string::npos || us == 0 || us + 1 >= name.size() ||
      name.find('_', us + 1) != std::string::npos) {
    return std::nullopt;
  }
  std::string stem = name.substr(0, us), digits;
  while (!stem.empty() && std::isdigit(static_cast<unsigned char>(stem.back()))) {
    digits.insert(digits.begin(), stem.back());
    stem.pop_back();
  }
  const std::string sub = name.substr(us + 1);
  const auto& greek = sym::greek_letters();
  const bool greek_stem = greek.count(stem) != 0;
  if (stem.empty() || (!greek_stem && stem.size() > 2)) return std::nullopt;
  for (const char c : stem + sub) {
    if (!std::isalnum(static_cast<unsigned char>(c))) return std::nullopt;
  }
  const std::string base = greek_stem ? "\\" + stem : stem;
  std::string subscript;
  if (greek.count(sub)) {
    subscript = "\\" + sub;
  } else if (sub.size() <= 2) {
    subscript = sub;  // I_xy: indices
  } else {
    subscript = "\\mathrm{" + sub + "}";
  }
  return base + "_{" + (digits.empty() ? "" : digits + ",") + subscript + "}";
}

namespace {
// The Greek letter at i, as its name ("φ" -> "phi"), or "".
std::string greek_name_at(const std::string& s, std::size_t i) {
  for (const auto& [name, letter] : sym::greek_letters()) {
    if (s.compare(i, letter.size(), letter) == 0) return name;
  }
  return "";
}

// At i: a Greek letter followed by a combining dot and/or digits ("θ̇0", "φ̇", "θ0"), as LaTeX
// math, and the index after it; nullopt for anything else (a lone letter maps as usual).
std::optional<std::pair<std::string, std::size_t>> dotted_greek(const std::string& s,
                                                                std::size_t i) {
  const std::string name = greek_name_at(s, i);
  if (name.empty() || name == "Pi") return std::nullopt;
  std::size_t j = i + sym::greek_letters().at(name).size();
  const bool dot = s.compare(j, 2, "\u0307") == 0;
  if (dot) j += 2;
  std::size_t k = j;
  while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) ++k;
  std::string subscript = s.substr(j, k - j);
  if (k == j && k + 1 < s.size() && s[k] == '_') {  // Ω_i, Ω_ij: a one- or two-letter index
    std::size_t e = k + 1;
    while (e < s.size() && e - k - 1 < 3 && std::isalnum(static_cast<unsigned char>(s[e]))) ++e;
    if (e - k - 1 >= 1 && e - k - 1 <= 2 &&
        (e == s.size() || !std::isalnum(static_cast<unsigned char>(s[e])))) {
      subscript = s.substr(k + 1, e - k - 1);
      k = e;
    }
  }
  if (!dot && subscript.empty()) return std::nullopt;
  const std::string symbol = "\\" + (name == "pi" ? std::string("pi") : name);
  std::string math = dot ? "\\dot{" + symbol + "}" : symbol;
  if (!subscript.empty()) math += "_{" + subscript + "}";
  return std::make_pair("$" + math + "$", k);
}

bool ascii_word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

bool has_index(const std::string& word) {
  return std::any_of(word.begin(), word.end(), [](char c) {
    return c == '_' || std::isdigit(static_cast<unsigned char>(c));
  });
}

// "I1", "e3", "w2": one letter and a one- or two-digit index.
bool indexed_letter(const std::string& word) {
  return word.size() >= 2 && word.size() <= 3 &&
         std::isalpha(static_cast<unsigned char>(word[0])) &&
         std::all_of(word.begin() + 1, word.end(),
                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

// wobble's ASCII name for ω is w (the problems' w1 is \omega_1; the keys' symbolic forms write
// w1): in prose, "w" and "w1" mean ω and ω₁, as the formulas beside them show.
std::string letter_latex(char letter) {
  return letter == 'w' ? "\\omega" : std::string(1, letter);
}

// At the start of a word, the word as math or typewriter type, and the index after it; nullopt
// for a word that stays prose (or that dotted_greek and the symbol map set: "ω3", "θ̇0").
std::optional<std::pair<std::string, std::size_t>> prose_word(const std::string& s, std::size_t i,
                                                              const ProseNames& names) {
  if (i > 0 && ascii_word_char(s[i - 1])) return std::nullopt;
  std::string word;  // Greek letters by name: "Ω_space" -> "Omega_space"
  std::size_t j = i;
  bool greek_first = false;
  while (j < s.size()) {
    if (ascii_word_char(s[j])) {
      word += s[j++];
    } else if (const std::string g = greek_name_at(s, j); !g.empty()) {
      greek_first = greek_first || j == i;
      word += g;
      j += sym::greek_letters().at(g).size();
    } else {
      break;
    }
  }
  if (word.empty() || std::isdigit(static_cast<unsigned char>(word[0])) ||
      (greek_first && word.find('_') == std::string::npos)) {
    return std::nullopt;
  }
  const auto math = [&](const std::string& m) {
    const bool primed = j < s.size() && s[j] == '\'';  // e2' (a turned axis): the prime in math
    return std::make_pair("$" + m + (primed ? "'" : "") + "$", j + (primed ? 1 : 0));
  };
  if (const auto p = names.parameter_latex.find(word);
      p != names.parameter_latex.end() && (has_index(word) || sym::greek_letters().count(word))) {
    return math(p->second);
  }
  if (const auto symbol = name_latex(word)) return math(*symbol);
  if (has_index(word) &&
      std::find(names.answers.begin(), names.answers.end(), word) != names.answers.end()) {
    std::string typed;
    for (const char c : word) typed += c == '_' ? std::string("\\_") : std::string(1, c);
    return std::make_pair("\\texttt{" + typed + "}", j);
  }
  if (indexed_letter(word)) return math(letter_latex(word[0]) + "_{" + word.substr(1) + "}");
  // "dw1/dt": the time derivative of an indexed letter.
  if (word.size() >= 3 && word[0] == 'd' && indexed_letter(word.substr(1)) &&
      s.compare(j, 3, "/dt") == 0) {
    j += 3;
    return math("\\mathrm{d}" + letter_latex(word[1]) + "_{" + word.substr(2) + "}/\\mathrm{d}t");
  }
  if (word == "w") return math("\\omega");
  return std::nullopt;
}
}  // namespace

ProseNames prose_names(const Key& key) {
  ProseNames names;
  for (const auto& p : key.parameters) names.parameter_latex[p.name] = p.latex;
  for (const auto& part : key.parts) {
    for (const auto& a : part.answers) names.answers.push_back(a.name);
  }
  return names;
}

std::string latex_text(const std::string& s, const ProseNames& names) {
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
    // A number in e-notation in prose: "4.4e-16" -> 4.4 $\times 10^{-16}$.
    if (std::isdigit(static_cast<unsigned char>(s[i])) &&
        (i == 0 || !std::isalnum(static_cast<unsigned char>(s[i - 1])))) {
      std::size_t j = i;
      while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.')) ++j;
      std::size_t k = j + 1;
      const bool negative = k < s.size() && s[k] == '-';
      if (k < s.size() && (s[k] == '-' || s[k] == '+')) ++k;
      while (k < s.size() && s[k] == '0' && k + 1 < s.size() &&
             std::isdigit(static_cast<unsigned char>(s[k + 1]))) {
        ++k;  // "e-05" -> 10^{-5}
      }
      const std::size_t digits = k;
      while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) ++k;
      if (j < s.size() && (s[j] == 'e' || s[j] == 'E') && k > digits) {
        out += s.substr(i, j - i) + "$\\times 10^{" + (negative ? "-" : "") +
               s.substr(digits, k - digits) + "}$";
        i = k;
        continue;
      }
    }
    // A negative number's sign as a minus, not a hyphen: "by -0.03%", "= -0.5 w2 w3".
    if (s[i] == '-' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])) &&
        (i == 0 || s[i - 1] == ' ' || s[i - 1] == '(' || s[i - 1] == '[')) {
      out += "$-$";
      ++i;
      continue;
    }
    // A name as a whole word (Omega_body, p_φ, I1, w2, angles_zxz): math or typewriter type.
    if (const auto word = prose_word(s, i, names)) {
      out += word->first;
      i = word->second;
      continue;
    }
    // A Greek letter with a dot above (a time derivative) and digits: θ̇0 -> $\dot{\theta}_{0}$.
    if (const auto greek = dotted_greek(s, i)) {
      out += greek->first;
      i = greek->second;
      continue;
    }
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
