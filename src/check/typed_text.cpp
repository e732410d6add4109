#include "check/typed_text.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <string_view>
#include <utility>
#include <vector>

#include "check/answer_reading.hpp"
#include "check/brackets.hpp"
#include "check/latex_answer.hpp"
#include "check/program_notation.hpp"
#include "check/written_forms.hpp"
#include "core/characters.hpp"
#include "symbolic/expression_guard.hpp"
#include "symbolic/glued_numbers.hpp"
#include "symbolic/unicode_notation.hpp"

namespace wobble::check {

// typed_text.hpp: the functions a hand writes without brackets about one factor.
const std::vector<std::string>& bare_call_functions() {
  static const std::vector<std::string> names{"sin",  "cos",  "tan",  "asin", "acos", "atan",
                                              "sinh", "cosh", "tanh", "exp",  "ln",   "sqrt"};
  return names;
}

namespace {
// "cos (θ)" -> "cos(θ)": a function's name, a space, its argument's parentheses, as a PDF's
// text and some typists set a call. Only the functions an expression may call, so "m (R^2)"
// stays a symbol times a bracket.
std::string calls_unspaced(const std::string& s) {
  std::string out;
  std::size_t done = 0;
  for (const auto& [start, length] : identifiers(s)) {
    const std::string name = s.substr(start, length);
    std::size_t open = start + length;
    while (open < s.size() && s[open] == ' ') ++open;
    if (open == start + length || open >= s.size() || s[open] != '(' ||
        !sym::is_function_name(name)) {
      continue;
    }
    out += s.substr(done, start - done) + name;
    done = open;
  }
  return out + s.substr(done);
}

// "sqrt2" -> "sqrt(2)", "1/sqrt3": a root of a number typed as √2 is printed, without brackets.
// Only sqrt: "cos2 x" may mean cos(2x) or cos(2) x, and stays an unknown name.
std::string roots_of_numbers(const std::string& s) {
  std::string out;
  std::size_t done = 0;
  for (const auto& [start, length] : identifiers(s)) {
    constexpr std::string_view kRoot = "sqrt";
    const std::string_view name = std::string_view(s).substr(start, length);
    if (name.size() <= kRoot.size() || name.substr(0, kRoot.size()) != kRoot ||
        name.find_first_not_of("0123456789", kRoot.size()) != std::string_view::npos)
      continue;
    std::size_t end = start + length;  // a decimal part too: "sqrt2.5"
    if (end + 1 < s.size() && s[end] == '.' &&
        std::isdigit(static_cast<unsigned char>(s[end + 1]))) {
      ++end;
      while (end < s.size() && std::isdigit(static_cast<unsigned char>(s[end]))) ++end;
    }
    out += s.substr(done, start - done) + "sqrt(" +
           s.substr(start + kRoot.size(), end - start - kRoot.size()) + ")";
    done = end;
  }
  return out + s.substr(done);
}

// "cos^2(alpha)" -> "cos(alpha)^2", as textbooks write a power of a trigonometric or hyperbolic
// function (and "cos²(α)" arrives here so). Only a positive whole power: cos^-1 is arccos in
// some books and cos(x)^(-1) in others, so it stays an error.
std::string function_powers(const std::string& s) {
  static const std::vector<std::string> kFunctions{"sin",  "cos",  "tan",  "asin", "acos",
                                                   "atan", "sinh", "cosh", "tanh"};
  std::string out;
  std::size_t done = 0;
  for (const auto& [start, length] : identifiers(s)) {
    if (start < done) continue;
    const std::string name = s.substr(start, length);
    std::size_t k = start + length;
    if (std::find(kFunctions.begin(), kFunctions.end(), name) == kFunctions.end() ||
        k >= s.size() || s[k] != '^')
      continue;
    ++k;
    const bool bracketed = k < s.size() && s[k] == '(';
    if (bracketed) ++k;
    const std::size_t digits = k;
    while (k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]))) ++k;
    if (k == digits || (bracketed && (k >= s.size() || s[k++] != ')'))) continue;
    const std::string power = s.substr(digits, k - digits - (bracketed ? 1 : 0));
    while (k < s.size() && s[k] == ' ') ++k;
    // "sin^2 alpha", "sin²α": an argument of one name or number, no power or call after it.
    if (const std::string arg = k < s.size() ? sym::name_at(s, k) : "";
        !arg.empty() &&
        (k + arg.size() >= s.size() || (s[k + arg.size()] != '^' && s[k + arg.size()] != '('))) {
      out += s.substr(done, start - done) + name + "(" + arg + ")^" + power;
      done = k + arg.size();
      continue;
    }
    if (k >= s.size() || s[k] != '(') continue;
    const std::size_t close = matching(s, k);
    if (close == std::string::npos) continue;
    out += s.substr(done, start - done) + name + "(" +
           function_powers(s.substr(k + 1, close - k - 1)) + ")^" + power;
    done = close + 1;
  }
  return out + s.substr(done);
}

// "8.1x10^-2" or "8.1 X 10^-2" -> "8.1*10^-2": the letter x for the times sign, as typed where
// there is no ×. Only between a digit and "10^", where no expression could mean a symbol x.
std::string times_ten(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if ((s[i] == 'x' || s[i] == 'X') && !out.empty()) {
      std::size_t before = out.find_last_not_of(' ');
      std::size_t after = s.find_first_not_of(' ', i + 1);
      if (before != std::string::npos && std::isdigit(static_cast<unsigned char>(out[before])) &&
          after != std::string::npos && s.compare(after, 3, "10^") == 0) {
        out.erase(before + 1);
        out += '*';
        i = after - 1;
        continue;
      }
    }
    out += s[i];
  }
  return out;
}

// NumPy's "array([[10., 0., 0.], ...])", "matrix([[..]])" and SymPy's "Matrix([[10, 0, 0],
// ...])", as Python shows a result or a student writes one in an expression, `m*a**2*np.array(
// [[..]])`: the bracketed list inside. Only a call of a list ('[' first inside), whose name no
// letter, digit or '.' comes before ("myarray(" stays), so no expression is touched.
std::string without_python_wrapper(std::string s) {
  static const std::vector<std::string> kWrappers{"np.array(",  "numpy.array(",  "array(",
                                                  "np.matrix(", "numpy.matrix(", "matrix(",
                                                  "sp.Matrix(", "sympy.Matrix(", "Matrix("};
  for (std::size_t at = 0; at < s.size(); ++at) {
    if (at > 0 && (is_letter(s[at - 1]) || is_digit(s[at - 1]) || s[at - 1] == '.')) continue;
    for (const auto& w : kWrappers) {
      if (s.compare(at, w.size(), w) != 0) continue;
      const std::size_t open = at + w.size() - 1, close = matching(s, open);
      const std::size_t first = s.find_first_not_of(' ', open + 1);
      if (close == std::string::npos || first == std::string::npos || s[first] != '[') continue;
      s.erase(close, 1);
      s.erase(at, w.size());
      break;
    }
  }
  return s;
}

// NumPy 2's scalars as Python shows them, "np.float64(0.00072)", alone or in a list, as
// "(0.00072)". No expression has a '.' inside a name, so none is touched.
std::string numpy_scalars_unwrapped(std::string s) {
  static const std::vector<std::string> kTypes{"float64", "float32", "float16", "longdouble",
                                               "int64",   "int32",   "int16",   "int8"};
  for (const std::string module : {"np.", "numpy."}) {
    for (auto at = s.find(module); at != std::string::npos; at = s.find(module, at)) {
      const std::size_t type_at = at + module.size();
      const auto type = std::find_if(kTypes.begin(), kTypes.end(), [&](const std::string& t) {
        return s.compare(type_at, t.size() + 1, t + "(") == 0;
      });
      const bool name_before = at > 0 && (is_letter(s[at - 1]) || is_digit(s[at - 1]));
      if (type == kTypes.end() || name_before) {
        ++at;
        continue;
      }
      s.erase(at, module.size() + type->size());
    }
  }
  return s;
}

// "Hω", "πR", "cosα", "I₁ω₁²": a Greek letter is one symbol, so one after a name or a number,
// or before a Latin letter, is a product (or a function's argument), never a longer name
// ("Homega", "I1omega1"); likewise a root after a factor ("ω√(..)"). μ stays glued: "μs" is a
// microsecond as often as μ times s.
// What belongs to the letter before it: a dot above (θ̇) and subscript digits (θ₀).
constexpr std::array<std::string_view, 11> kLetterMarks{"\u0307", "₀", "₁", "₂", "₃", "₄",
                                                        "₅",      "₆", "₇", "₈", "₉"};

std::string greek_letters_apart(const std::string& typed) {
  const auto greek_at = [&](std::size_t i) -> std::size_t {
    for (const auto& [name, letter] : sym::greek_letters()) {
      if (name != "mu" && typed.compare(i, letter.size(), letter) == 0) return letter.size();
    }
    return 0;
  };
  // What ends a name or a number: a letter, a digit, a subscript or superscript digit, a dot
  // above (θ̇), a Greek letter.
  const auto ends_factor = [&](const std::string& out) {
    if (out.empty()) return false;
    const char last = out.back();
    if (std::isalnum(static_cast<unsigned char>(last)) || last == '_') return true;
    for (const std::string_view mark : kLetterMarks) {
      if (out.size() >= mark.size() &&
          out.compare(out.size() - mark.size(), mark.size(), mark) == 0)
        return true;
    }
    for (const std::string mark : {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"}) {
      if (out.size() >= mark.size() &&
          out.compare(out.size() - mark.size(), mark.size(), mark) == 0)
        return true;
    }
    return std::any_of(
        sym::greek_letters().begin(), sym::greek_letters().end(), [&](const auto& g) {
          const std::string& l = g.second;
          return out.size() >= l.size() && out.compare(out.size() - l.size(), l.size(), l) == 0;
        });
  };
  std::string out;
  for (std::size_t i = 0; i < typed.size();) {
    const std::size_t length = static_cast<unsigned char>(typed[i]) >= 0x80 ? greek_at(i) : 0;
    if (length == 0) {
      // "ω√(..)", "R√2": a root after a factor is a product too ("omegasqrt" is no function).
      if (typed.compare(i, 3, "√") == 0 && ends_factor(out)) out += ' ';
      out += typed[i++];
      continue;
    }
    // After '_' the letter is the name's subscript ("p_ψ", "ω_φ"), not a factor of its own.
    if (ends_factor(out) && out.back() != '_') out += ' ';
    out += typed.substr(i, length);
    i += length;
    // "φ̇cos θ": the letter's dot above and subscript digits are its own, then a factor apart.
    for (bool more = true; more;) {
      more = false;
      for (const std::string_view mark : kLetterMarks) {
        if (typed.compare(i, mark.size(), mark) == 0) {
          out += mark;
          i += mark.size();
          more = true;
        }
      }
    }
    if (i < typed.size() && std::isalpha(static_cast<unsigned char>(typed[i]))) out += ' ';
  }
  return out;
}

// 0.2056" and 12': seconds and minutes of arc after a number, typed without ″ and ′ (which
// sym::to_ascii reads so); after a name a prime is no unit ("E'", "psidot0'").
std::string arc_marks_read(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    // The number before is looked for at a mark only: a run of digits is not walked back over
    // at each of its own.
    const bool mark = s[i] == '"' || s[i] == '\'';
    if (!mark || !sym::ends_in_number(out)) {
      out += s[i];
      continue;
    }
    const bool seconds = s[i] == '"' || (i + 1 < s.size() && s[i + 1] == '\'');
    if (s[i] == '\'' && seconds) ++i;  // '' for a second of arc
    out += seconds ? " arcsec" : " arcmin";
  }
  return out;
}

// "|x|" -> "abs(x)", as a student writes a magnitude ("π/|Ω|", "m |R|^2/4"; "‖x‖" alike): a bar
// after an operand closes the one open at its bracket depth, any other opens one. Bars that do
// not pair are left as typed, for the reader to refuse.
std::string bars_as_abs(const std::string& text) {
  std::string s = text;
  for (auto at = s.find("‖"); at != std::string::npos; at = s.find("‖", at))
    s.replace(at, std::string_view("‖").size(), "|");
  if (s.find('|') == std::string::npos) return text;
  std::string out;
  std::vector<int> open_at_depth;
  int depth = 0;
  for (const char c : s) {
    if (c == '(' || c == '[' || c == '{') ++depth;
    if (c == ')' || c == ']' || c == '}') --depth;
    if (c != '|') {
      out += c;
      continue;
    }
    const std::size_t last = out.find_last_not_of(' ');
    const char before = last == std::string::npos ? '\0' : out[last];
    const bool after_operand = std::isalnum(static_cast<unsigned char>(before)) || before == ')' ||
                               before == ']' || before == '.';
    if (after_operand && !open_at_depth.empty() && open_at_depth.back() == depth) {
      out += ')';
      open_at_depth.pop_back();
    } else {
      out += after_operand ? " abs(" : "abs(";  // "2|x|": a product, as "2 abs(x)" reads
      open_at_depth.push_back(depth);
    }
  }
  return open_at_depth.empty() ? out : text;
}

}  // namespace

// ASCII, one line, a numeric exponent's sign in parentheses.
std::string prepared(const std::string& typed, const std::string& field) {
  // Angle brackets, as calculus writes a vector ("⟨1, 2, 3⟩", "<1, 2, 3>"): no expression
  // compares, so they can be nothing else.
  std::string bracketed = typed;
  for (const auto& [angle, square] :
       {std::pair{"⟨", "["}, std::pair{"⟩", "]"}, std::pair{"〈", "["}, std::pair{"〉", "]"}}) {
    for (auto at = bracketed.find(angle); at != std::string::npos; at = bracketed.find(angle, at))
      bracketed.replace(at, std::string(angle).size(), square);
  }
  std::string s = bars_as_abs(
      arc_marks_read(sym::to_ascii(greek_letters_apart(sym::letters_folded(bracketed)))));
  // "Sqrt[m]", "np.sqrt(m)", "R.^2": as Mathematica, Python and MATLAB write them.
  s = as_programs_mean(s);
  for (char& c : s) {
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    // Mathematica's lists, "{{10, 0, 0}, {0, 6, 1}, ...}", and angle brackets: brackets here.
    if (c == '{' || c == '<') c = '[';
    if (c == '}' || c == '>') c = ']';
  }
  // "$m*R^2/4$": the math delimiters of a LaTeX or Markdown source around plain text.
  s = without_python_wrapper(numpy_scalars_unwrapped(without_math_delimiters(s)));
  // "diag(a, b, c)", "M/12 diag(..)": the matrix as rows (check/written_forms.hpp).
  s = diagonals_written_out(s, field);
  // Python's and Fortran's power, "R**2": GiNaC's '^'.
  for (std::size_t at = s.find("**"); at != std::string::npos; at = s.find("**", at))
    s.replace(at, 2, "^");
  s = function_powers(sym::numbers_times_constants(times_ten(calls_unspaced(roots_of_numbers(s)))));
  // "10^-4" -> "10^(-4)": a signed number after '^' (no std::regex: GCC 12 warns inside it).
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    out += s[i];
    if (s[i] != '^') continue;
    std::size_t j = i + 1;
    while (j < s.size() && s[j] == ' ') ++j;
    if (j >= s.size() || (s[j] != '-' && s[j] != '+')) continue;
    const char sign = s[j++];
    while (j < s.size() && s[j] == ' ') ++j;
    const std::size_t start = j;
    while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.')) ++j;
    if (j == start) continue;
    out += "(" + std::string(1, sign) + s.substr(start, j - start) + ")";
    i = j - 1;
  }
  return trim(out);
}

}  // namespace wobble::check
