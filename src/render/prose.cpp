#include "render/prose.hpp"

#include <algorithm>
#include <array>
#include <cctype>

#include "symbolic/plain_text.hpp"
#include "symbolic/unicode_notation.hpp"

namespace wobble::detail {

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

// One letter as LaTeX math: "L", "w" as wobble's ASCII ω, a Greek letter's name ("Omega");
// nullopt for anything longer.
std::optional<std::string> name_latex_letter(const std::string& name) {
  if (name == "w") return "\\omega";
  if (sym::greek_letters().count(name)) return "\\" + name;
  if (name.size() == 1 && std::isalpha(static_cast<unsigned char>(name[0]))) return name;
  return std::nullopt;
}
}  // namespace

std::optional<std::string> name_latex(const std::string& name) {
  // "L_magnitude": the vector's size, as books write it, |L|.
  if (constexpr std::string_view size = "_magnitude";
      name.size() > size.size() && name.ends_with(size)) {
    if (const auto vector = name_latex_letter(name.substr(0, name.size() - size.size())))
      return "\\lvert " + *vector + "\\rvert";
  }
  // "dw_dt0": dω/dt at t = 0, as the question writes it, ω̇(0).
  if (name.size() >= 5 && name[0] == 'd' && name.find("_dt") == 2) {
    const std::string at = name.substr(5);
    const auto letter = name_latex_letter(name.substr(1, 1));
    if (letter && std::all_of(at.begin(), at.end(),
                              [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      return "\\dot{" + *letter + "}" + (at.empty() ? "" : "(" + at + ")");
  }
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

std::optional<std::string> answer_symbol_latex(const std::string& name) {
  if (name.find('_') != std::string::npos) return name_latex(name);
  // "I0", "omega3", "k": a letter and at most one digit of index. A trailing 2 is a square
  // ("k2" for k², as the catalog names it), which a subscript would misread.
  std::string stem = name, index;
  if (!stem.empty() && std::isdigit(static_cast<unsigned char>(stem.back()))) {
    index = stem.substr(stem.size() - 1);
    stem.pop_back();
  }
  const auto letter = name_latex_letter(stem);
  if (!letter || index == "2") return std::nullopt;
  return index.empty() ? *letter : *letter + "_" + index;
}

namespace {
// The Greek letter at i, as its name ("φ" -> "phi"), or "". A key's prose is read a byte at a
// time, and comparing each byte with each of 30 letters was a tenth of the three-atom
// molecule's solve (callgrind): only a byte that begins some letter is compared.
std::string greek_name_at(const std::string& s, std::size_t i) {
  static const std::array<bool, 256> begins_a_letter = [] {
    std::array<bool, 256> begins{};
    for (const auto& [name, letter] : sym::greek_letters())
      begins[static_cast<unsigned char>(letter.front())] = true;
    return begins;
  }();
  if (i >= s.size() || !begins_a_letter[static_cast<unsigned char>(s[i])]) return "";
  for (const auto& [name, letter] : sym::greek_letters()) {
    if (s.compare(i, letter.size(), letter) == 0) return name;
  }
  return "";
}

// At i: a Greek letter followed by a combining dot and/or digits ("θ̇0", "φ̇", "θ0"), as LaTeX
// math (without `$`), and the index after it; nullopt for anything else (a lone letter maps as usual).
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
  return std::make_pair(math, k);
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

// "s = |w(0)|", "at t = 0", "z = (..)", "K(k)": a lone Latin letter in prose (the word
// s[i, j)) is a variable, set in italic as the formulas beside it set it. Not the article a (or
// A); not a unit, after a number ("in 0.5 s") or a unit's '/' ("rad/s"); not a possessive's s
// ("Euler's"), a letter of a hyphenated word ("z-y-z") or of an abbreviation ("e.g."); not a
// part's label in brackets of its own ("(b)", "part (b)"; K(k)'s k is a variable).
bool lone_variable(const std::string& s, std::size_t i, std::size_t j, const std::string& word) {
  if (word.size() != 1 || !std::isalpha(static_cast<unsigned char>(word[0])) || word == "a" ||
      word == "A")
    return false;
  const auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
  const char prior = i > 0 ? s[i - 1] : ' ';
  if (prior == '-' || prior == '\'' || (j < s.size() && s[j] == '-')) return false;
  if (i >= 3 && s.compare(i - 3, 3, "’") == 0) return false;
  if (prior == '/' && i >= 2 && letter(s[i - 2])) return false;
  if (j + 1 < s.size() && s[j] == '.' && letter(s[j + 1])) return false;
  // "d²ω₂/dt²": a derivative's d, upright as its dt.
  if (word == "d" && s.compare(j, 2, "²") == 0 && j + 2 < s.size() && s[j + 2] != ' ') return false;
  // After a number (not a name's index, "c2 d"), a unit.
  std::size_t before = i;
  while (before > 0 && s[before - 1] == ' ') --before;
  std::size_t number = before;
  while (number > 0 &&
         (std::isdigit(static_cast<unsigned char>(s[number - 1])) || s[number - 1] == '.'))
    --number;
  if (number < before && (number == 0 || !ascii_word_char(s[number - 1]))) return false;
  const bool bracketed = prior == '(' && j < s.size() && s[j] == ')';
  return !(bracketed && (i < 2 || !std::isalnum(static_cast<unsigned char>(s[i - 2]))));
}

// A name in prose: as math (LaTeX without `$`, and the terminal's Unicode for it) or as an
// answer's name, and the index after it.
struct ProseWord {
  std::string latex;    // empty for an answer's name
  std::string unicode;  // the math in Unicode, or the answer's name as typed
  std::size_t end = 0;
};

// At the start of a word, the word as math or as an answer's name; nullopt for a word that stays
// prose (or that dotted_greek and the symbol map set: "ω3", "θ̇0").
std::optional<ProseWord> prose_word(const std::string& s, std::size_t i, const ProseNames& names) {
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
  // The math, and its Unicode unless math_to_unicode says it.
  const auto math = [&](const std::string& m, std::string unicode = "") {
    if (unicode.empty()) unicode = math_to_unicode(m);
    const bool primed = j < s.size() && s[j] == '\'';  // e2' (a turned axis): the prime in math
    const std::string prime = primed ? "'" : "";
    return ProseWord{m + prime, unicode + prime, j + (primed ? 1 : 0)};
  };
  if (const auto p = names.parameter_latex.find(word);
      p != names.parameter_latex.end() && (has_index(word) || sym::greek_letters().count(word))) {
    return math(p->second);
  }
  if (auto symbol = name_latex(word)) {
    // In Unicode, the name with its Greek names as letters: "Omega_space" -> "Ω_space",
    // "p_phi" -> "p_φ", "L0_space" as it is (a subscript that is a word reads best as typed).
    const auto letter = [](const std::string& part) {
      const auto g = sym::greek_letters().find(part);
      return g == sym::greek_letters().end() ? part : g->second;
    };
    const auto us = word.find('_');
    std::string stem = letter(word.substr(0, us));
    if (stem == "w") {  // "w_i": wobble's ASCII ω
      stem = "ω";
      *symbol = "\\omega" + symbol->substr(1);
    }
    return math(*symbol, stem + "_" + letter(word.substr(us + 1)));
  }
  if (has_index(word) &&
      std::find(names.answers.begin(), names.answers.end(), word) != names.answers.end()) {
    return ProseWord{"", word, j};
  }
  if (indexed_letter(word)) return math(letter_latex(word[0]) + "_{" + word.substr(1) + "}");
  // "dw1/dt": the time derivative of an indexed letter.
  if (word.size() >= 3 && word[0] == 'd' && indexed_letter(word.substr(1)) &&
      s.compare(j, 3, "/dt") == 0) {
    j += 3;
    const std::string symbol = letter_latex(word[1]) + "_{" + word.substr(2) + "}";
    return math("\\mathrm{d}" + symbol + "/\\mathrm{d}t", "d" + math_to_unicode(symbol) + "/dt");
  }
  if (word == "w") return math("\\omega");
  if (lone_variable(s, i, j, word)) return math(word);
  return std::nullopt;
}
}  // namespace

namespace {
// An answer's name in typewriter type, its underscores escaped: "angles_zxz".
std::string typewriter(const std::string& name) {
  std::string typed;
  for (const char c : name) typed += c == '_' ? std::string("\\_") : std::string(1, c);
  return typed;
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
      out += word->latex.empty() ? "\\texttt{" + typewriter(word->unicode) + "}"
                                 : "$" + word->latex + "$";
      i = word->end;
      continue;
    }
    // A Greek letter with a dot above (a time derivative) and digits: θ̇0 -> $\dot{\theta}_{0}$.
    if (const auto greek = dotted_greek(s, i)) {
      out += "$" + greek->first + "$";
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

std::string unicode_text(const std::string& s, const ProseNames& names,
                         AnswerNameStyle answer_names) {
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    if (const auto word = prose_word(s, i, names)) {
      const bool code = word->latex.empty() && answer_names == AnswerNameStyle::code;
      out += code ? "`" + word->unicode + "`" : word->unicode;
      i = word->end;
    } else if (const auto greek = dotted_greek(s, i)) {
      out += math_to_unicode(greek->first);
      i = greek->second;
    } else {
      out += s[i++];
    }
  }
  return out;
}

}  // namespace wobble::detail
