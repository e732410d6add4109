#include "symbolic/expression_guard.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "core/characters.hpp"
#include "symbolic/unicode_notation.hpp"

namespace wobble::sym {

namespace {
bool ident_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

// "; the symbols here are m, R, omega (ω), alpha (α), pi (π)": what a student may write instead.
std::string known_symbols(const GiNaC::symtab& symbols) {
  std::string list;
  for (const auto& [name, value] : symbols) {
    if (name == "Pi") continue;  // the same constant as pi
    const auto letter = greek_letters().find(name);
    list += (list.empty() ? "" : ", ") + name +
            (letter != greek_letters().end() ? " (" + letter->second + ")" : "");
  }
  return "; the symbols here are " + list;
}

// name from `from` on as a product of known names, "mR" -> "m*R", "omegasqrt" -> "omega*sqrt"
// (a function only last, before its call); "" when there is none. The longest name first at
// each place, then backtracking; `dead` marks the places already found to have no split, so the
// search is linear in the places however the names overlap ("a", "aa", ...).
std::string as_product(const std::string& name, std::size_t from, const GiNaC::symtab& symbols,
                       const std::set<std::string>& functions, bool call, std::vector<bool>& dead) {
  if (dead[from]) return "";
  for (std::size_t length = name.size() - from; length > 0; --length) {
    const std::string head = name.substr(from, length);
    const bool last = from + length == name.size();
    const bool known = last && call ? functions.count(head) != 0 : symbols.count(head) != 0;
    if (!known) continue;
    if (last) return head;
    const std::string tail = as_product(name, from + length, symbols, functions, call, dead);
    if (!tail.empty()) return head + "*" + tail;
  }
  dead[from] = true;
  return "";
}

// Names longer than any a student types run together are not split (nor searched).
constexpr std::size_t kLongestSplit = 64;

// What the writer of an unknown name probably meant: factors without their '*' ("mR"), or a
// symbol in the other case ("r" for R). "" if neither.
std::string probably_meant(const std::string& name, const GiNaC::symtab& symbols,
                           const std::set<std::string>& functions, bool call) {
  std::vector<bool> dead(name.size() + 1, false);
  if (const std::string product = name.size() <= kLongestSplit
                                      ? as_product(name, 0, symbols, functions, call, dead)
                                      : std::string();
      product.find('*') != std::string::npos) {
    return " (products need '*': " + product + ")";
  }
  for (const auto& [known, value] : symbols) {
    if (!call && known != name && ascii_lower(known) == ascii_lower(name))
      return " (names are case-sensitive: " + known + "?)";
  }
  if (call || name.size() > kLongestSplit) return "";
  // "MR" where the mass is m: the symbols run together, one in the other case. Only names no
  // two symbols share in lower case ("M" and "m" both symbols: which one is not for us to say).
  std::map<std::string, std::string> by_lower;
  std::set<std::string> shared;
  GiNaC::symtab lowered;
  for (const auto& [known, value] : symbols) {
    const std::string lower = ascii_lower(known);
    if (!by_lower.emplace(lower, known).second) shared.insert(lower);
    lowered.emplace(lower, value);
  }
  for (const auto& lower : shared) lowered.erase(lower);
  std::fill(dead.begin(), dead.end(), false);
  const std::string product = as_product(ascii_lower(name), 0, lowered, functions, false, dead);
  if (product.find('*') == std::string::npos) return "";
  std::string written;
  for (std::size_t from = 0; from <= product.size();) {
    const std::size_t star = std::min(product.find('*', from), product.size());
    written += (written.empty() ? "" : "*") + by_lower.at(product.substr(from, star - from));
    from = star + 1;
  }
  return " (names are case-sensitive: " + written + "?)";
}

struct Scanner {
  const std::string& text;
  const std::string& field;
  const std::string& shown;
  const GiNaC::symtab& symbols;

  [[noreturn]] void fail(const std::string& why) const {
    throw ExpressionError(field + ": expression \"" + shown + "\" is refused: " + why);
  }

  // The end of the group that opens at text[open] ('(' ... matching ')'), or npos.
  std::size_t group_end(std::size_t open) const {
    int depth = 0;
    for (std::size_t i = open; i < text.size(); ++i) {
      if (text[i] == '(') ++depth;
      if (text[i] == ')' && --depth == 0) return i;
    }
    return std::string::npos;
  }

  // A number literal at i: checks its size; returns its end.
  std::size_t number_end(std::size_t i, double* value) const {
    const std::size_t start = i;
    std::size_t digits = 0;
    while (i < text.size() &&
           (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.')) {
      digits += text[i] != '.';
      ++i;
    }
    if (digits > 50) fail("a number with more than 50 digits");
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
      std::size_t j = i + 1;
      if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
      const std::size_t exp_start = j;
      while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) ++j;
      if (j > exp_start) {
        // Doubles end near 1e308; GiNaC would write out 1e8888888 digit by digit.
        if (j - exp_start > 3 || std::atoi(text.substr(exp_start, j - exp_start).c_str()) > 400) {
          fail("a number with an exponent beyond 400 (not finite in double precision)");
        }
        i = j;
      }
    }
    if (value != nullptr) *value = std::strtod(text.substr(start, i - start).c_str(), nullptr);
    return i;
  }

  // The size of the exponent that starts after '^' at i (1 for a symbolic one), and its end.
  double exponent(std::size_t i, std::size_t* end) const {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    // GiNaC reads x^-2+y as x^(-2+y): a sign after '^' takes the rest of the sum into the
    // exponent, which this scan could not bound (2^+4+22^423 ran out of memory).
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) {
      fail("a signed exponent must be in parentheses: x^(-2), not x^-2");
    }
    if (i >= text.size()) {
      *end = i;
      return 1;
    }
    if (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.') {
      double v = 1;
      *end = number_end(i, &v);
      return std::abs(v);
    }
    std::size_t j = i;
    while (j < text.size() && ident_char(text[j])) ++j;
    if (j < text.size() && text[j] == '(') {
      const std::size_t close = group_end(j);
      if (close == std::string::npos) {
        // Unbalanced: GiNaC's parser says so, but only after computing the powers it read
        // before it got there ("0^((6666^666666666 -" ran out of memory): the group is the rest.
        if (text.find('^', j + 1) != std::string::npos) fail("a power inside an exponent");
        *end = text.size();
        return 1;
      }
      const std::string inside = text.substr(j + 1, close - j - 1);
      if (inside.find('^') != std::string::npos) fail("a power inside an exponent");
      *end = close + 1;
      if (j > i) return 1;  // a function's value: not computed exactly
      // A group without powers is cheap to read exactly; a number there is the exponent.
      try {
        GiNaC::parser reader(symbols, true);
        const GiNaC::ex e = reader(inside);
        if (GiNaC::is_a<GiNaC::numeric>(e)) {
          return std::abs(GiNaC::ex_to<GiNaC::numeric>(e).to_double());
        }
      } catch (const std::exception&) {
        // a malformed exponent: GiNaC's parser reports it with the whole expression
      }
      return 1;
    }
    *end = j;
    return 1;
  }
};
// The functions an expression may call. GiNaC's parser knows many more, some of which compute
// exactly (tgamma(100000) digit by digit).
constexpr std::array<std::string_view, 16> kFunctions{
    "sqrt", "sin", "cos",  "tan",  "asin", "acos", "atan",      "atan2",
    "exp",  "log", "sinh", "cosh", "tanh", "abs",  "EllipticK", "EllipticE"};

// kFunctions and the other names they are read by (ln for log).
const std::set<std::string>& function_names() {
  static const std::set<std::string> names = [] {
    std::set<std::string> f;
    for (const auto function : kFunctions) f.emplace(function);
    for (const auto& [alias, name] : kFunctionAliases) f.emplace(alias);
    return f;
  }();
  return names;
}

}  // namespace

bool is_function_name(const std::string& name) {
  return function_names().count(name) != 0;
}

void check_expression_cost(const std::string& text, const std::string& field,
                           const std::string& shown, const GiNaC::symtab& symbols) {
  const Scanner s{text, field, shown, symbols};
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto u = static_cast<unsigned char>(text[i]);
    if (u < 0x20 && text[i] != '\t') s.fail("it contains " + character_name(text, i));
    if (u > 0x7e) {
      // A byte that is no UTF-8 came from a terminal or file in another encoding (Latin-1's °
      // is the byte 0xB0): what to change is the encoding, not the expression.
      const std::string name = character_name(text, i);
      s.fail("it contains " + name +
             (name.starts_with("the byte ")
                  ? " (a terminal or file in another encoding, as Latin-1? set it to UTF-8)"
                  : ", which no expression uses"));
    }
  }
  // Names: a function only from kFunctions, anything else a declared symbol (GiNaC would also
  // accept its constants Catalan, Euler and the imaginary unit I).
  const std::set<std::string>& functions = function_names();
  // "sqrt, ..., atan or arctan, ...": each function with the other name it is read by.
  static const std::string known = [] {
    std::string list;
    for (const auto& f : kFunctions) {
      list += list.empty() ? "" : ", ";
      list += f;
      for (const auto& [alias, name] : kFunctionAliases) {
        if (name == f) list += " or " + std::string(alias);
      }
    }
    return list;
  }();
  for (std::size_t i = 0; i < text.size();) {
    if (!std::isalpha(static_cast<unsigned char>(text[i])) && text[i] != '_') {
      // skip a number (with its exponent letter) or any other character
      if (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.') {
        i = s.number_end(i, nullptr);
      } else {
        ++i;
      }
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && ident_char(text[j])) ++j;
    const std::string name = text.substr(i, j - i);
    std::size_t k = j;
    while (k < text.size() && (text[k] == ' ' || text[k] == '\t')) ++k;
    if (k < text.size() && text[k] == '(') {
      if (!functions.count(name)) {
        // "m(R^2": a symbol against a bracket, where the product did not read either.
        if (symbols.count(name)) {
          s.fail("'" + name + "' is one of the problem's symbols, not a function: a product " +
                 "needs '*' (" + name + "*(..))");
        }
        if (const std::string meant = probably_meant(name, symbols, functions, true);
            !meant.empty()) {
          s.fail("unknown function '" + name + "'" + meant);
        }
        s.fail("unknown function '" + name + "' (known: " + known + ")");
      }
    } else if (!symbols.count(name) && functions.count(name)) {
      // "cos^-1(x)" is arccos in most books and 1/cos in some: the line says how to write each.
      const bool trigonometric = name == "sin" || name == "cos" || name == "tan";
      if (trigonometric && (text.compare(k, 5, "^(-1)") == 0 || text.compare(k, 3, "^-1") == 0)) {
        throw ExpressionError(field + ": cannot read expression \"" + shown + "\": " + name +
                              "^-1 reads two ways: write a" + name + "(x) for the inverse " +
                              "function, 1/" + name + "(x) for the reciprocal");
      }
      // "cos alpha": a function without its call right after it.
      throw ExpressionError(field + ": cannot read expression \"" + shown + "\": " + name +
                            " is a function: its argument comes in parentheses right after it (" +
                            name + "(x), " + name + "(x)^2" +
                            (trigonometric ? "; a" + name + "(x) for the inverse" : "") + ")");
    } else if (!symbols.count(name)) {
      throw ExpressionError(
          field + ": cannot read expression \"" + shown + "\": undefined symbol '" + name + "'" +
          probably_meant(name, symbols, functions, false) + known_symbols(symbols));
    }
    i = j;
  }
  // f(): GiNaC's parser crashes on a call without arguments (GiNaC 1.8.6), wherever it is.
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '(') continue;
    std::size_t k = i + 1;
    while (k < text.size() && (text[k] == ' ' || text[k] == '\t')) ++k;
    std::size_t b = i;
    while (b > 0 && (text[b - 1] == ' ' || text[b - 1] == '\t')) --b;
    if (k < text.size() && text[k] == ')' && b > 0 && ident_char(text[b - 1])) {
      s.fail("a function called without arguments");
    }
  }
  // Exact powers: the product of the exponents along each chain of nested powers is the
  // number of digits it multiplies, so it is bounded; GiNaC would compute 2^(10^9) exactly.
  constexpr double kMaxTower = 1000;
  std::vector<double> group_tower{1};  // the largest tower in each open group
  double operand = 1;                  // the tower of the operand just read
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '(') {
      group_tower.push_back(1);
      ++i;
    } else if (c == ')') {
      operand = group_tower.back();
      if (group_tower.size() > 1) group_tower.pop_back();
      group_tower.back() = std::max(group_tower.back(), operand);
      ++i;
    } else if (c == '^') {
      std::size_t end = i + 1;
      const double e = s.exponent(i + 1, &end);
      const double tower = operand * std::max(1.0, e);
      if (!(tower <= kMaxTower)) {
        s.fail("an exact power too large to compute (exponents multiply to more than 1000)");
      }
      group_tower.back() = std::max(group_tower.back(), tower);
      operand = tower;
      i = end;
    } else if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      if (i > 0 && ident_char(text[i - 1])) {  // a digit inside a name such as d1
        ++i;
        continue;
      }
      i = s.number_end(i, nullptr);
      operand = 1;
    } else {
      if (ident_char(c)) operand = 1;
      ++i;
    }
  }
}

}  // namespace wobble::sym
