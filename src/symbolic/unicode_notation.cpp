#include "symbolic/unicode_notation.hpp"

#include <algorithm>
#include <array>
#include <boost/locale/utf.hpp>
#include <cctype>
#include <iterator>
#include <utility>
#include <vector>

#include "core/characters.hpp"
#include "symbolic/glued_numbers.hpp"
#include "symbolic/plain_text.hpp"

namespace wobble::sym {

namespace {
bool is_name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

const char* const kSuperscripts[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
const char* const kSubscripts[] = {"₀", "₁", "₂", "₃", "₄", "₅", "₆", "₇", "₈", "₉"};
constexpr const char* kCombiningDot = "\u0307";

std::string superscript(const std::string& digits) {
  std::string out;
  for (char c : digits) out += c == '-' ? "⁻" : kSuperscripts[c - '0'];
  return out;
}

// "theta0" -> "θ0", "phidot0" -> "φ̇0", "psidot" -> "ψ̇": a Greek name, an optional "dot" (a time
// derivative) and digits; any other word stays as it is.
std::string greek_word(const std::string& word) {
  if (const auto it = greek_letters().find(word); it != greek_letters().end()) return it->second;
  std::size_t digits = word.size();
  while (digits > 0 && is_digit(word[digits - 1])) --digits;
  std::string stem = word.substr(0, digits);
  const bool dot = stem.size() > 3 && stem.compare(stem.size() - 3, 3, "dot") == 0;
  if (dot) stem.resize(stem.size() - 3);
  const auto it = greek_letters().find(stem);
  if (it == greek_letters().end() || (!dot && digits == word.size())) return word;
  return it->second + (dot ? kCombiningDot : "") + word.substr(digits);
}

// Unicode spellings read as ASCII, longest first where one is a prefix of another. Greek
// letters come from greek_letters(); superscripts, subscripts, √ and the combining dot are
// handled by to_ascii itself.
const std::vector<std::pair<std::string, std::string>>& replacements() {
  static const std::vector<std::pair<std::string, std::string>> r = [] {
    std::vector<std::pair<std::string, std::string>> v{
        {"·", "*"},
        {"×", "*"},
        {"⋅", "*"},
        {"∙", "*"},
        // The division sign and the slashes of typeset fractions, as a calculator or a PDF has
        // them: m·R²÷4, 1⁄4.
        {"÷", "/"},
        {"∕", "/"},
        {"⁄", "/"},
        {"−", "-"},
        {"–", "-"},
        // º (the ordinal sign) and ˚ (the ring above) as keyboards without a degree sign type it.
        {"°", " deg"},
        {"º", " deg"},
        {"˚", " deg"},
        {"\u00a0", " "},
        {"\u2009", " "},
        {"\u202f", " "},
        {"µ", "mu"},
        // A fraction in one character, as a phone's keyboard offers it: ½·m·R².
        {"½", "(1/2)"},
        {"¼", "(1/4)"},
        {"¾", "(3/4)"},
        {"⅓", "(1/3)"},
        {"⅔", "(2/3)"}};
    for (const auto& [name, letter] : greek_letters()) {
      if (name != "Pi") v.emplace_back(letter, name);  // π reads as pi
    }
    return v;
  }();
  return r;
}

using boost::locale::utf::code_point;
using Utf8 = boost::locale::utf::utf_traits<char>;

// The Greek of the Mathematical Alphanumeric Symbols: each of its five styles (bold, italic,
// bold italic, sans-serif bold, sans-serif bold italic) runs through these 58 characters.
constexpr std::array<code_point, 58> kStyledGreek{
    0x391, 0x392,  0x393, 0x394,  0x395, 0x396, 0x397, 0x398, 0x399, 0x39A, 0x39B, 0x39C,
    0x39D, 0x39E,  0x39F, 0x3A0,  0x3A1, 0x3F4, 0x3A3, 0x3A4, 0x3A5, 0x3A6, 0x3A7, 0x3A8,
    0x3A9, 0x2207, 0x3B1, 0x3B2,  0x3B3, 0x3B4, 0x3B5, 0x3B6, 0x3B7, 0x3B8, 0x3B9, 0x3BA,
    0x3BB, 0x3BC,  0x3BD, 0x3BE,  0x3BF, 0x3C0, 0x3C1, 0x3C2, 0x3C3, 0x3C4, 0x3C5, 0x3C6,
    0x3C7, 0x3C8,  0x3C9, 0x2202, 0x3F5, 0x3D1, 0x3F0, 0x3D5, 0x3F1, 0x3D6};

// The plain letter or digit a styled one stands for; 0 for any other character.
code_point plain_letter(code_point c) {
  if (c >= 0x1D400 && c <= 0x1D6A3) {  // thirteen styles of A-Z a-z
    const code_point k = (c - 0x1D400) % 52;
    return k < 26 ? 'A' + k : 'a' + (k - 26);
  }
  if (c >= 0x1D6A8 && c <= 0x1D7C9) return kStyledGreek[(c - 0x1D6A8) % 58];
  if (c >= 0x1D7CE && c <= 0x1D7FF) return '0' + (c - 0x1D7CE) % 10;  // five styles of 0-9
  if (c == 0x210E) return 'h';  // italic h, which the block leaves to Letterlike Symbols
  return 0;
}

// A Greek letter's variant form, as the letter every reader knows; 0 for any other character.
code_point usual_greek(code_point c) {
  switch (c) {
    case 0x3F5:
      return 0x3B5;  // ϵ ε
    case 0x3D1:
      return 0x3B8;  // ϑ θ
    case 0x3F4:
      return 0x398;  // ϴ Θ
    case 0x3D5:
      return 0x3C6;  // ϕ φ
    case 0x3F1:
      return 0x3C1;  // ϱ ρ
    case 0x3F0:
      return 0x3BA;  // ϰ κ
    case 0x3C2:
      return 0x3C3;  // ς σ
    default:
      return 0;
  }
}

// Which of `table` starts text at i; its index, or -1.
int match_at(const std::string& text, std::size_t i, const char* const* table, int n) {
  for (int k = 0; k < n; ++k) {
    const std::string s = table[k];
    if (text.compare(i, s.size(), s) == 0) return k;
  }
  return -1;
}
}  // namespace

const std::map<std::string, std::string>& greek_letters() {
  static const std::map<std::string, std::string> g{
      {"alpha", "α"}, {"beta", "β"},  {"gamma", "γ"}, {"delta", "δ"},  {"epsilon", "ε"},
      {"zeta", "ζ"},  {"eta", "η"},   {"theta", "θ"}, {"kappa", "κ"},  {"lambda", "λ"},
      {"mu", "μ"},    {"nu", "ν"},    {"xi", "ξ"},    {"rho", "ρ"},    {"sigma", "σ"},
      {"tau", "τ"},   {"phi", "φ"},   {"chi", "χ"},   {"psi", "ψ"},    {"omega", "ω"},
      {"Gamma", "Γ"}, {"Delta", "Δ"}, {"Theta", "Θ"}, {"Lambda", "Λ"}, {"Sigma", "Σ"},
      {"Phi", "Φ"},   {"Psi", "Ψ"},   {"Omega", "Ω"}, {"Pi", "π"},     {"pi", "π"}};
  return g;
}

std::string to_unicode(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    if (std::isalpha(static_cast<unsigned char>(c))) {
      std::size_t j = i;
      while (j < s.size() && is_name_char(s[j])) ++j;
      const std::string word = s.substr(i, j - i);
      out += word == "sqrt" ? "√" : greek_word(word);
      i = j;
    } else if (c == '^' && i + 1 < s.size() && is_digit(s[i + 1])) {
      std::size_t j = i + 1;
      while (j < s.size() && is_digit(s[j])) ++j;
      out += superscript(s.substr(i + 1, j - i - 1));
      i = j;
    } else if (c == '^' && s.compare(i, 3, "^(-") == 0 && i + 3 < s.size() && is_digit(s[i + 3])) {
      // "s^(-1)" -> "s⁻¹", as to_ascii reads a signed run of superscripts back.
      std::size_t j = i + 3;
      while (j < s.size() && is_digit(s[j])) ++j;
      if (j < s.size() && s[j] == ')') {
        out += superscript("-" + s.substr(i + 3, j - i - 3));
        i = j + 1;
      } else {
        out += c;
        ++i;
      }
    } else if (c == '^' && s.compare(i, 2, "^-") == 0 && i + 2 < s.size() && is_digit(s[i + 2])) {
      // "s^-1", as a unit is written (GiNaC writes no such power): "s⁻¹".
      std::size_t j = i + 2;
      while (j < s.size() && is_digit(s[j])) ++j;
      out += superscript("-" + s.substr(i + 2, j - i - 2));
      i = j;
    } else if (c == '*') {
      out += "·";
      ++i;
    } else {
      out += c;
      ++i;
    }
  }
  return out;
}

namespace {
// Whether `out` ends in a count of minutes or seconds of arc: a number after no name, or the
// digits right after a mark read already ("44°41′37″": 41 after "deg", 37 after "arcmin");
// "ψ₀′" is no count.
bool ends_in_arc_count(const std::string& out) {
  if (ends_in_number(out)) return true;
  std::size_t k = out.size();
  while (k > 0 && (is_digit(out[k - 1]) || out[k - 1] == '.')) --k;
  const auto after = [&](const std::string& mark) {
    return k >= mark.size() && out.compare(k - mark.size(), mark.size(), mark) == 0;
  };
  return k < out.size() && (after("deg") || after("arcmin"));
}
}  // namespace

namespace {
// What to_ascii's first pass writes for a √.
constexpr char kRoot = '\x01';

// The second pass: √( -> sqrt(, √x -> sqrt(x) for a number or a name, √√x -> sqrt(sqrt(x)) and
// √√(..) -> sqrt(sqrt(..)). Without recursion: a typed answer may hold thousands of roots.
std::string roots_spelt(const std::string& text) {
  std::string result;
  int depth = 0;  // of the brackets
  // The brackets opened after roots of roots, by their depth, and the closes each owes after its
  // own: "√√(" owes one.
  std::vector<std::pair<int, std::size_t>> owed;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != kRoot) {
      result += text[i];
      if (text[i] == '(') {
        ++depth;
      } else if (text[i] == ')') {
        --depth;
        if (!owed.empty() && owed.back().first == depth) {
          result.append(owed.back().second, ')');
          owed.pop_back();
        }
      }
      continue;
    }
    std::size_t roots = 0;
    for (; i < text.size() && text[i] == kRoot; ++i) ++roots;
    if (i < text.size() && text[i] == '(') {
      for (std::size_t k = 1; k < roots; ++k) result += "sqrt(";
      result += "sqrt(";
      if (roots > 1) owed.emplace_back(depth, roots - 1);
      ++depth;
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && (is_name_char(text[end]) || text[end] == '.')) ++end;
    for (std::size_t k = 0; k < roots; ++k) result += "sqrt(";
    result += text.substr(i, end - i);
    result.append(roots, ')');
    i = end - 1;
  }
  return result;
}
}  // namespace

std::string to_ascii(const std::string& typed) {
  const std::string text = letters_folded(typed);
  // First pass: everything but √, which becomes a marker (its operand is only known after the
  // letters around it are read).
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (static_cast<unsigned char>(text[i]) < 0x80) {
      out += text[i++];
      continue;
    }
    if (text.compare(i, 3, "√") == 0) {
      out += kRoot;
      i += 3;
      continue;
    }
    if (text.compare(i, 2, kCombiningDot) == 0) {  // θ̇: the name gets "dot" before its digits
      out += "dot";
      i += 2;
      continue;
    }
    // A run of superscripts, optionally signed: an exponent.
    if (match_at(text, i, kSuperscripts, 10) >= 0 || text.compare(i, 3, "⁻") == 0 ||
        text.compare(i, 3, "⁺") == 0) {
      std::string digits;
      bool negative = false;
      for (;;) {
        if (text.compare(i, 3, "⁻") == 0 || text.compare(i, 3, "⁺") == 0) {
          negative = negative || text.compare(i, 3, "⁻") == 0;
          i += 3;
          continue;
        }
        const int d = match_at(text, i, kSuperscripts, 10);
        if (d < 0) break;
        digits += static_cast<char>('0' + d);
        i += std::string(kSuperscripts[d]).size();
      }
      out += negative ? "^(-" + digits + ")" : "^" + digits;
      continue;
    }
    if (const int d = match_at(text, i, kSubscripts, 10); d >= 0) {
      out += static_cast<char>('0' + d);
      i += std::string(kSubscripts[d]).size();
      continue;
    }
    // 0.2″, 12′: seconds and minutes of arc after a number (after a name a prime is no unit,
    // though the name end in a digit: "ψ₀′" is psi0′, a rate in Lagrange's notation).
    if (ends_in_arc_count(out) && (text.compare(i, 3, "″") == 0 || text.compare(i, 3, "′") == 0)) {
      out += text.compare(i, 3, "″") == 0 ? " arcsec" : " arcmin";
      i += 3;
      continue;
    }
    bool replaced = false;
    for (const auto& [from, to] : replacements()) {
      if (text.compare(i, from.size(), from) == 0) {
        out += to;
        i += from.size();
        replaced = true;
        break;
      }
    }
    if (!replaced) out += text[i++];  // unknown: left for the expression guard to name
  }
  return out.find(kRoot) == std::string::npos ? out : roots_spelt(out);
}

std::string letters_folded(const std::string& text) {
  std::string out;
  bool after_styled = false;  // the last character was a styled letter
  bool after_letter = false;  // the last character was a letter, Latin or Greek, styled or not
  for (auto it = text.begin(); it != text.end();) {
    const auto start = it;
    const code_point c = Utf8::decode(it, text.end());
    if (c == boost::locale::utf::illegal || c == boost::locale::utf::incomplete) {
      it = start + 1;  // no UTF-8: left for the expression guard to name
      out += *start;
      after_styled = after_letter = false;
      continue;
    }
    // The character as the letter it is: unstyled, then in its usual Greek form.
    const code_point unstyled = plain_letter(c);
    code_point plain = unstyled != 0 ? unstyled : c;
    if (const code_point usual = usual_greek(plain); usual != 0) plain = usual;
    const bool styled = unstyled != 0 && !(plain >= '0' && plain <= '9');
    if (styled && after_styled) out += ' ';
    after_styled = styled;
    const bool was_after_letter = after_letter;
    after_letter =
        (plain < 0x80 && is_letter(static_cast<char>(plain))) || (plain >= 0x391 && plain <= 0x3C9);
    if (c == 0x2D9 && was_after_letter) {
      out += kCombiningDot;  // "φ˙", as a PDF gives \dot\phi when copied: φ̇
    } else if (c == 0x2061 || c == 0x2063) {
      out += ' ';
    } else if (c == 0x2062) {
      out += '*';
    } else if (c == 0x200B) {
      // nothing: a zero-width space only marks where a line may break
    } else if (plain != c) {
      Utf8::encode(plain, std::back_inserter(out));
    } else {
      out.append(start, it);
    }
  }
  return out;
}

std::string typed_spelling(const std::string& latex) {
  std::string typed = to_ascii(math_to_unicode(latex));
  typed.erase(
      std::remove_if(typed.begin(), typed.end(), [](char c) { return c == '_' || c == ' '; }),
      typed.end());
  return typed;
}

}  // namespace wobble::sym
