#include "check/euler_equations.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <string_view>

#include "check/answer_reading.hpp"
#include "check/brackets.hpp"
#include "check/latex_answer.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"
#include "symbolic/unicode_notation.hpp"

namespace wobble::check {

namespace {

// The rest of `s` after a name of ω, "omega" or "w"; nullopt where it starts with neither.
std::optional<std::string_view> after_omega(std::string_view s) {
  for (const std::string_view name : {"omega", "w"}) {
    if (s.starts_with(name)) return s.substr(name.size());
  }
  return std::nullopt;
}

// A component's index, "1" to "3", as a number; 0 for anything else.
int index_of(std::string_view s) {
  return s.size() == 1 && s[0] >= '1' && s[0] <= '3' ? s[0] - '0' : 0;
}

// The component a written derivative is of, 1 to 3, or 0: "domega1/dt", "dw_1/dt",
// "d(omega1)/dt", "omegadot1", "omega1dot", "omega1'", "w1'". (No <regex>: GCC 12's does not
// build warning-free under the sanitizers.)
int derivative_of(const std::string& side) {
  std::string s;
  for (char c : sym::to_ascii(side)) {
    if (c != ' ' && c != '_' && c != '(' && c != ')' && c != '{' && c != '}' && c != '*') s += c;
  }
  const std::string_view v = s;
  if (v.size() > 4 && v.starts_with("d") && v.ends_with("/dt")) {
    const auto rest = after_omega(v.substr(1, v.size() - 4));
    return rest ? index_of(*rest) : 0;
  }
  const auto rest = after_omega(v);
  if (!rest) return 0;
  if (rest->starts_with("dot")) return index_of(rest->substr(3));
  const std::string_view after = rest->substr(std::min<std::size_t>(1, rest->size()));
  return after == "dot" || after == "'" ? index_of(rest->substr(0, 1)) : 0;
}

// The component a factor is, 1 to 3, or 0: "omega2", "omega_2", "w2".
int component(std::string_view factor) {
  const auto rest = after_omega(factor);
  if (!rest) return 0;
  return index_of(rest->starts_with("_") ? rest->substr(1) : *rest);
}

// How many times a factor counts its component: "omega2" once, "omega2^2" twice; 0 for a
// factor that is no component or a power of one.
std::pair<int, int> component_power(const std::string& factor) {
  const auto caret = factor.find('^');
  const std::string_view base = std::string_view(factor).substr(0, caret);
  const int c = component(base);
  if (c == 0 || caret == std::string::npos) return {c, c == 0 ? 0 : 1};
  const std::string_view power = std::string_view(factor).substr(caret + 1);
  return power.size() == 1 && power[0] >= '1' && power[0] <= '9' ? std::pair{c, power[0] - '0'}
                                                                 : std::pair{0, 0};
}

// "omega2omega3" -> "omega2 omega3", "2w2w3" -> "2 w2 w3", "(I2-I3)omega2" -> "(I2-I3) omega2":
// components run together with what comes before them, parted.
std::string components_parted(const std::string& ascii) {
  std::string out;
  for (std::size_t i = 0; i < ascii.size(); ++i) {
    if (i > 0 && (std::isdigit(static_cast<unsigned char>(ascii[i - 1])) || ascii[i - 1] == ')') &&
        after_omega(std::string_view(ascii).substr(i)))
      out += ' ';
    out += ascii[i];
  }
  return out;
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

// "(2/3)", as ⅔ reads, without its brackets: the coefficients echoed read 2/3, not (2/3).
std::string plain_fraction_unbracketed(const std::string& factor) {
  if (factor.size() < 3 || factor.front() != '(' || factor.back() != ')') return factor;
  const std::string inside = factor.substr(1, factor.size() - 2);
  const bool plain = std::all_of(inside.begin(), inside.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '/';
  });
  return plain ? inside : factor;
}

// `s` as one factor of a product: as it is where it is a name, a number or one bracket, else
// in brackets.
std::string as_factor(const std::string& s) {
  const bool plain = std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
  });
  return plain || wrapped(s, '(') ? s : "(" + s + ")";
}

// A side read as a product: the factors besides ω's components, and how many times each
// component is a factor.
struct Product {
  std::string coefficient;    ///< "-0.9651", "(I2-I3)/I1"; "1" or "-1" where there is no other
  std::array<int, 4> seen{};  ///< seen[c]: the power of ω_c (index 0 unused)
  int derivative = 0;         ///< the component whose derivative is a factor (a left side), or 0
  bool has_components() const { return seen[1] + seen[2] + seen[3] > 0; }
};

// `side` as a product ("-0.9651 omega2 omega3" -> "-0.9651", ω₂ and ω₃ once each;
// "(I2-I3) omega2 omega3/I1" -> "(I2-I3)/I1"; "I1 domega1/dt" -> "I1", the derivative of ω₁), or
// nullopt where it is none (a sum outside brackets, an empty factor, ω or two derivatives in a
// denominator).
std::optional<Product> product_of(const std::string& side) {
  const std::string ascii = components_parted(sym::to_ascii(side));
  bool negative = false;
  std::vector<std::string> numerator, denominator;
  Product p;
  for (const auto& word : space_separated_entries(ascii)) {
    for (std::string factor : top_level(word, '*')) {
      if (factor.empty()) return std::nullopt;
      if (factor[0] == '-' || factor[0] == '+') {
        negative ^= factor[0] == '-';
        factor = trim(factor.substr(1));
      }
      if (factor.empty()) continue;
      if (const int d = derivative_of(factor); d != 0) {  // "domega1/dt": its '/' is no quotient
        if (p.derivative != 0) return std::nullopt;
        p.derivative = d;
        continue;
      }
      const std::vector<std::string> quotient = top_level(factor, '/');
      for (std::size_t q = 0; q < quotient.size(); ++q) {
        const std::string& f = quotient[q];
        if (f.empty() || sum_outside_brackets(f)) return std::nullopt;
        if (const auto [c, power] = component_power(f); c != 0) {
          if (q > 0) return std::nullopt;
          p.seen.at(c) += power;
        } else {
          (q == 0 ? numerator : denominator).push_back(plain_fraction_unbracketed(f));
        }
      }
    }
  }
  p.coefficient = negative ? "-" : "";
  if (numerator.empty()) p.coefficient += "1";
  for (std::size_t i = 0; i < numerator.size(); ++i) p.coefficient += (i ? "*" : "") + numerator[i];
  for (const auto& d : denominator) p.coefficient += "/" + as_factor(d);
  return p;
}

constexpr std::array<const char*, 4> kSubscripts{"", "₁", "₂", "₃"};

// "ω₁ ω₃", "ω₂²": the components a product has, as the feedback writes them.
std::string components_written(const std::array<int, 4>& seen) {
  static constexpr std::array<const char*, 10> kSup{"", "", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string out;
  for (int c = 1; c <= 3; ++c) {
    if (seen.at(c) == 0) continue;
    out += std::string(out.empty() ? "" : " ") + "ω" + kSubscripts.at(c) +
           kSup.at(std::min(seen.at(c), 9));
  }
  return out;
}

std::string derivative_written(int i) {
  return std::string("dω") + kSubscripts.at(i) + "/dt";
}

// "\mathrm{d}\omega_{1}/\mathrm{d}t" (and d\omega_1/dt) as "\dot{\omega}_{1}": as a LaTeX key
// sets the derivative in a line of text, where the LaTeX reader takes a derivative as a \frac
// or a dot, and d here for no symbol.
std::string slashed_derivatives_dotted(std::string s) {
  for (const std::string d : {"\\mathrm{d}", "\\text{d}"}) {
    for (auto at = s.find(d); at != std::string::npos; at = s.find(d, at + 1))
      s.replace(at, d.size(), "d");
  }
  static constexpr std::string_view kOmega = "\\omega_";
  std::string out;
  std::size_t copied = 0;
  for (std::size_t at = s.find(kOmega); at != std::string::npos; at = s.find(kOmega, at + 1)) {
    std::size_t start = at;  // back over spaces to the d
    while (start > copied && s[start - 1] == ' ') --start;
    if (start == copied || s[start - 1] != 'd') continue;
    --start;
    if (start > 0 &&
        (std::isalpha(static_cast<unsigned char>(s[start - 1])) || s[start - 1] == '\\'))
      continue;
    std::size_t i = at + kOmega.size();
    const auto skip_spaces = [&] {
      while (i < s.size() && s[i] == ' ') ++i;
    };
    const auto take = [&](char c) {
      skip_spaces();
      if (i >= s.size() || s[i] != c) return false;
      ++i;
      return true;
    };
    const bool braced = i < s.size() && s[i] == '{';
    if (braced) ++i;
    if (i >= s.size() || index_of(std::string_view(s).substr(i, 1)) == 0) continue;
    const char index = s[i++];
    if ((braced && !take('}')) || !take('/') || !take('d') || !take('t')) continue;
    if (i < s.size() && std::isalpha(static_cast<unsigned char>(s[i]))) continue;  // "/dtheta"
    out += s.substr(copied, start - copied) + "\\dot{\\omega}_{" + index + "}";
    copied = i;
  }
  return out + s.substr(copied);
}

}  // namespace

std::string euler_equations_as_text(const std::string& typed, const sym::SymbolTable& table) {
  // No \omega, no equations of its components: every other LaTeX vector answer passes here, and
  // is spared a copy of the table and a second reading.
  if (!looks_like_latex(typed) || typed.find("\\omega") == std::string::npos) return typed;
  sym::SymbolTable with_components = table;
  for (const char i : {'1', '2', '3'}) {
    for (const auto& [name, latex] :
         {std::pair{std::string("omega") + i, std::string("\\omega_{") + i + "}"},
          std::pair{std::string("omegadot") + i, std::string("\\dot{\\omega}_{") + i + "}"}}) {
      if (!with_components.contains(name))
        with_components.declare(name, latex, sym::SymbolSign::real);
    }
  }
  // "$\mathrm{d}\omega_{1}/\mathrm{d}t$ = $-$0.5 $\omega_2$ $\omega_3$, ..": the LaTeX key's
  // source of its step, prose with math in it; without the dollars, one formula.
  std::string math = typed;
  std::erase(math, '$');
  const std::string dotted = slashed_derivatives_dotted(math);
  try {
    return latex_as_text(dotted, with_components, "answer");
  } catch (const InputError&) {
    return typed;  // the reader proper says what it cannot read
  }
}

std::optional<EulerEquations> read_euler_equations(const std::string& typed,
                                                   const std::string& field) {
  std::vector<std::string> items;
  for (const char sep : {',', ';', '\n'}) {
    items = top_level(without_closing_punctuation(typed), sep);
    if (items.size() > 1) break;
  }
  if (items.empty() || items.size() > 3) return std::nullopt;
  std::array<std::string, 3> coefficients;
  std::array<int, 4> given{};
  EulerEquations read;
  for (const auto& item : items) {
    const std::vector<std::string> sides = top_level(item, '=');
    if (sides.size() != 2) return std::nullopt;
    // "dω₁/dt", or a factor times it, "I₁ dω₁/dt", as the key's first step writes them.
    int i = derivative_of(sides[0]);
    std::string left_factor = "1";
    if (i == 0) {
      const auto left = product_of(sides[0]);
      if (!left || left->derivative == 0 || left->has_components()) return std::nullopt;
      i = left->derivative;
      left_factor = left->coefficient;
    }
    const auto product = product_of(sides[1]);
    // No component of ω on the right ("ω̇₁ = -0.5, .."): the coefficients labelled by their
    // equations, which the labelled components' reader takes.
    if (!product || product->derivative != 0 || !product->has_components()) return std::nullopt;
    const int j = i % 3 + 1, k = (i + 1) % 3 + 1;
    std::array<int, 4> want{};
    want.at(j) = want.at(k) = 1;
    if (product->seen != want) {
      read.wrong_products.push_back(derivative_written(i) + " = c" + kSubscripts.at(i) + " " +
                                    components_written(want) + ", and yours has " +
                                    components_written(product->seen));
    }
    ++given.at(i);
    coefficients.at(i - 1) = left_factor == "1"
                                 ? product->coefficient
                                 : as_factor(product->coefficient) + "/" + as_factor(left_factor);
  }
  std::vector<std::string> unlike;  // "dω₃/dt missing", "dω₁/dt twice"
  for (int i = 1; i <= 3; ++i) {
    if (given.at(i) != 1)
      unlike.push_back(derivative_written(i) + (given.at(i) ? " twice" : " missing"));
  }
  if (!unlike.empty()) {
    std::string which;
    for (const auto& u : unlike) which += (which.empty() ? "" : ", ") + u;
    throw InputError(field +
                     ": Euler's equations: give one for each component, dω₁/dt = c₁ ω₂ "
                     "ω₃, dω₂/dt = c₂ ω₃ ω₁, dω₃/dt = c₃ ω₁ ω₂ (" +
                     which + ")");
  }
  if (read.wrong_products.empty())
    read.coefficients =
        "[" + coefficients[0] + ", " + coefficients[1] + ", " + coefficients[2] + "]";
  return read;
}

}  // namespace wobble::check
