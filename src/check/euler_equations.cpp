#include "check/euler_equations.hpp"

#include <array>
#include <cctype>
#include <regex>
#include <string_view>

#include "check/answer_reading.hpp"
#include "check/brackets.hpp"
#include "check/latex_answer.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"
#include "symbolic/unicode_notation.hpp"

namespace wobble::check {

namespace {

// The component a written derivative is of, 1 to 3, or 0: "domega1/dt", "dw_1/dt",
// "d(omega1)/dt", "omegadot1", "omega1dot", "omega1'", "w1'".
int derivative_of(const std::string& side) {
  std::string s;
  for (char c : sym::to_ascii(side)) {
    if (c != ' ' && c != '_' && c != '(' && c != ')' && c != '{' && c != '}' && c != '*') s += c;
  }
  static const std::regex kForms(
      R"(^(?:d(?:omega|w)([123])/dt|(?:omega|w)dot([123])|(?:omega|w)([123])(?:dot|'))$)");
  std::smatch m;
  if (!std::regex_match(s, m, kForms)) return 0;
  for (std::size_t g = 1; g < m.size(); ++g) {
    if (m[g].matched) return m[g].str()[0] - '0';
  }
  return 0;
}

// The component a factor is, 1 to 3, or 0: "omega2", "omega_2", "w2".
int component(const std::string& factor) {
  static const std::regex kComponent(R"(^(?:omega|w)_?([123])$)");
  std::smatch m;
  return std::regex_match(factor, m, kComponent) ? m[1].str()[0] - '0' : 0;
}

// Whether `factor` adds or subtracts outside brackets ("a - b", not "(a - b)", "-a" or "9.9e-05"):
// a sum beside the components multiplies only its last term ("a - b ω₂ ω₃" is a − b ω₂ ω₃).
bool sum_outside_brackets(const std::string& factor) {
  int depth = 0;
  for (std::size_t i = 0; i < factor.size(); ++i) {
    const char c = factor[i];
    depth += opens(c) ? 1 : closes(c) ? -1 : 0;
    if (depth == 0 && i > 0 && (c == '+' || c == '-') &&
        std::string_view("eE^*/(").find(factor[i - 1]) == std::string_view::npos)
      return true;
  }
  return false;
}

// The coefficient of ω_j ω_k in `side` ("-0.9651 omega2 omega3" -> "-0.9651"), or "" where the
// side is no coefficient times exactly those two components.
std::string coefficient(const std::string& side, int j, int k) {
  // "omega2omega3", "2w2w3": components run together are parted first.
  const std::string ascii = std::regex_replace(sym::to_ascii(side),
                                               std::regex(R"(([0-9])(omega|w))"), "$1 $2");
  bool negative = false;
  std::vector<std::string> rest;
  std::array<int, 4> seen{};
  for (const auto& word : space_separated_entries(ascii)) {
    for (std::string factor : top_level(word, '*')) {
      if (factor.empty()) return "";
      if (factor[0] == '-' || factor[0] == '+') {
        negative ^= factor[0] == '-';
        factor = trim(factor.substr(1));
      }
      if (const int c = component(factor); c != 0) {
        ++seen.at(c);
      } else if (sum_outside_brackets(factor)) {
        return "";
      } else if (!factor.empty()) {
        rest.push_back(factor);
      }
    }
  }
  std::array<int, 4> want{};
  want.at(j) = want.at(k) = 1;
  if (seen != want) return "";
  std::string c = negative ? "-" : "";
  if (rest.empty()) return c + "1";
  for (std::size_t i = 0; i < rest.size(); ++i) c += (i ? "*" : "") + rest[i];
  return c;
}

}  // namespace

std::string euler_equations_as_text(const std::string& typed, const sym::SymbolTable& table) {
  if (!looks_like_latex(typed)) return typed;
  sym::SymbolTable with_components = table;
  for (const char i : {'1', '2', '3'}) {
    for (const auto& [name, latex] :
         {std::pair{std::string("omega") + i, std::string("\\omega_{") + i + "}"},
          std::pair{std::string("omegadot") + i, std::string("\\dot{\\omega}_{") + i + "}"}}) {
      if (!with_components.contains(name))
        with_components.declare(name, latex, sym::SymbolSign::real);
    }
  }
  // "\mathrm{d}\omega_{1}/\mathrm{d}t", as a LaTeX key sets the derivative in a line of text: the
  // reader takes a derivative as a \frac or a dot, and d here for no symbol. Spaces bounded: an
  // unbounded run recurses in std::regex, one frame a character.
  static const std::regex kSlashed(
      R"((?:\\mathrm\{d\}|\\text\{d\}|d) {0,3}\\omega_\{?([123])\}? {0,3}/ {0,3}(?:\\mathrm\{d\}|\\text\{d\}|d) {0,3}t)");
  // "$\mathrm{d}\omega_{1}/\mathrm{d}t$ = $-$0.5 $\omega_2$ $\omega_3$, ..": the LaTeX key's
  // source of its step, prose with math in it; without the dollars, one formula.
  std::string math = typed;
  std::erase(math, '$');
  const std::string dotted = std::regex_replace(math, kSlashed, "\\dot{\\omega}_{$1}");
  try {
    return latex_as_text(dotted, with_components, "answer");
  } catch (const InputError&) {
    return typed;  // the reader proper says what it cannot read
  }
}

std::optional<std::string> euler_equation_coefficients(const std::string& typed,
                                                       const std::string& field) {
  std::vector<std::string> items;
  for (const char sep : {',', ';', '\n'}) {
    items = top_level(without_closing_punctuation(typed), sep);
    if (items.size() > 1) break;
  }
  if (items.empty() || items.size() > 3) return std::nullopt;
  std::array<std::string, 3> coefficients;
  bool repeated = false;
  for (const auto& item : items) {
    const std::vector<std::string> sides = top_level(item, '=');
    if (sides.size() != 2) return std::nullopt;
    const int i = derivative_of(sides[0]);
    if (i == 0) return std::nullopt;
    const std::string c = coefficient(sides[1], i % 3 + 1, (i + 1) % 3 + 1);
    if (c.empty()) return std::nullopt;
    repeated = repeated || !coefficients.at(i - 1).empty();
    coefficients.at(i - 1) = c;
  }
  if (items.size() < 3 || repeated) {
    throw InputError(field +
                     ": Euler's equations: give one for each component, dω₁/dt = c₁ ω₂ "
                     "ω₃, dω₂/dt = c₂ ω₃ ω₁, dω₃/dt = c₃ ω₁ ω₂ (" +
                     std::to_string(items.size()) + " given" + (repeated ? ", one twice" : "") +
                     ")");
  }
  return "[" + coefficients[0] + ", " + coefficients[1] + ", " + coefficients[2] + "]";
}

}  // namespace wobble::check
