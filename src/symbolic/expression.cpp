#include "symbolic/expression.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "core/characters.hpp"
#include "symbolic/canonical_print.hpp"
#include "symbolic/expression_guard.hpp"
#include "symbolic/factored.hpp"
#include "symbolic/memo.hpp"

namespace wobble::sym {

bool is_identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  }
  return true;
}

namespace {
// GiNaC's parse errors carry a source location on following lines; keep the first line.
std::string first_line(const std::string& s) {
  auto pos = s.find('\n');
  std::string line = s.substr(0, pos);
  const std::string prefix = "GiNaC: ";
  if (line.rfind(prefix, 0) == 0) line = line.substr(prefix.size());
  return line;
}

// The exact decimal that a double was typed as: its shortest round-trip text read as a rational
// ("0.1" -> 1/10, not the binary fraction nearest to it). Exact, so CLN's float contagion cannot
// drop later operations to double precision.
GiNaC::numeric shortest_decimal(double d) {
  char buf[40];
  const auto end = std::to_chars(buf, buf + sizeof buf, d).ptr;  // e.g. "-1.25e-07"
  const std::string text(buf, end);
  const auto e_pos = text.find('e');
  std::string mantissa = text.substr(0, e_pos);
  long exponent = e_pos == std::string::npos ? 0 : std::stol(text.substr(e_pos + 1));
  if (const auto dot = mantissa.find('.'); dot != std::string::npos) {
    exponent -= static_cast<long>(mantissa.size() - dot - 1);
    mantissa.erase(dot, 1);
  }
  return GiNaC::numeric(mantissa.c_str()) * GiNaC::numeric(10).power(exponent);
}

// Number literals with a decimal point or an exponent ("1.5", "0.5e-3") rewritten as exact
// rationals ("(15/10)", "(5/10^4)"). GiNaC's parser reads them as floating-point numbers, which
// its polynomial algorithms (normal, gcd) refuse: decimals in a problem file or an answer mean
// the decimal number, exactly. The guard has bounded the literals (digits, exponent) already.
std::string exact_literals(const std::string& text) {
  const auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
  const auto name_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const bool starts_number = (digit(text[i]) || (text[i] == '.' && i + 1 < text.size() &&
                                                   digit(text[i + 1]))) &&
                               (i == 0 || !name_char(text[i - 1]));
    if (!starts_number) {
      out += text[i++];
      continue;
    }
    std::string mantissa;
    long exponent = 0;
    bool inexact = false;
    const std::size_t first = i;
    for (; i < text.size() && (digit(text[i]) || text[i] == '.'); ++i) {
      if (text[i] == '.') {
        // "1.5.3", "0.333...": a typo or an ellipsis, never a number (GiNaC's reader would drop
        // the second point and read 1.53).
        if (inexact) {
          std::size_t end = i;
          while (end < text.size() && (digit(text[end]) || text[end] == '.')) ++end;
          throw ExpressionError("the number \"" + text.substr(first, end - first) +
                                "\" has more than one decimal point");
        }
        inexact = true;
      } else {
        mantissa += text[i];
        if (inexact) --exponent;
      }
    }
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
      std::size_t j = i + 1;
      const bool negative = j < text.size() && text[j] == '-';
      if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
      const std::size_t start = j;
      while (j < text.size() && digit(text[j])) ++j;
      if (j > start) {
        const long e = std::stol(text.substr(start, j - start));
        exponent += negative ? -e : e;
        inexact = true;
        i = j;
      }
    }
    if (!inexact) {
      out += mantissa;
    } else if (exponent >= 0) {
      out += "(" + mantissa + "*10^" + std::to_string(exponent) + ")";
    } else {
      out += "(" + mantissa + "/10^" + std::to_string(-exponent) + ")";
    }
  }
  return out;
}

// GiNaC's parser messages ("expected ')', got: ','") in words a student can act on.
std::string plain_parse_error(const std::string& text, const std::string& ginac_message) {
  int depth = 0;
  for (const char c : text) {
    if (c == '(') ++depth;
    if (c == ')' && --depth < 0) return "a ')' has no '(' before it";
  }
  if (depth > 0) return "a '(' is not closed";
  if (ginac_message.find("division by zero") != std::string::npos) {
    return "it divides by zero";
  }
  // "2^3^2": GiNaC's parser takes no power of a power, which reads either way; the guard takes
  // no power inside an exponent.
  if (ginac_message.find("power should have exactly 2 operands") != std::string::npos) {
    return "a power of a power needs brackets, (a^b)^c, or its exponent worked out";
  }
  if (ginac_message.find("pow(0,0) is undefined") != std::string::npos) {
    return "it raises zero to the power zero";
  }
  if (ginac_message.find("got: \",\"") != std::string::npos) {
    return "a ',' where one expression was expected (a vector is written [x, y, z])";
  }
  return "it is not a complete expression (products need '*': 2*m*R^2, not 2mR^2; powers '^'; "
         "vectors [x, y, z])";
}

// d rounded once from a rational multiple of pi with a small denominator (pi, 104.5 deg = 209 pi
// / 360, ...): that multiple. Half-degrees need 360; 720 leaves room for quarter degrees.
std::optional<GiNaC::ex> pi_multiple(double d) {
  constexpr int kMaxDenominator = 720;
  const long double ratio = static_cast<long double>(d) / 3.14159265358979323846264338327950288L;
  constexpr long double kLargestNumerator = 1e6L;
  for (int den = 1; den <= kMaxDenominator; ++den) {
    // Past this every numerator would be too large, at this denominator and all larger ones.
    if (std::fabs(ratio) * den > kLargestNumerator + 1) break;
    // Nearest integer by floor(x + 1/2): 3 ns where nearbyint of a long double takes 90 (it
    // saves and restores the floating-point environment), and 720 of them were 5% of a keys
    // check. The two differ only at a half, which the slack test below rejects anyway.
    const long double num = std::floor(ratio * den + 0.5L);
    // A double nearest a rational multiple of pi is within ~1e-16 of it; 1e-12 leaves room for
    // a value computed in a few steps, and is far below the gap 1/720^2 between candidates.
    constexpr long double kPiMultipleSlack = 1e-12L;
    if (num == 0 || std::fabs(num) > kLargestNumerator ||
        std::fabs(ratio * den - num) > kPiMultipleSlack * den) {
      continue;
    }
    const GiNaC::ex candidate = GiNaC::numeric(static_cast<long>(num), den) * GiNaC::Pi;
    if (evaluate(candidate, GiNaC::lst{}, "value") == d) return candidate;
  }
  return std::nullopt;
}
}  // namespace

std::uint64_t SymbolTable::next_version() {
  static std::atomic<std::uint64_t> last{0};
  return ++last;
}

GiNaC::ex SymbolTable::declare(const std::string& name, const std::string& latex, SymbolSign sign) {
  if (!is_identifier(name)) throw std::invalid_argument("'" + name + "' is not an identifier");
  if (name == "pi" || name == "Pi" || contains(name)) {
    throw std::invalid_argument("symbol '" + name + "' is declared twice or is reserved");
  }
  GiNaC::ex s = sign == SymbolSign::positive ? GiNaC::ex(GiNaC::possymbol(name))
                                             : GiNaC::ex(GiNaC::realsymbol(name));
  index_[name] = names_.size();
  names_.push_back(name);
  symbols_.push_back(s);
  latex_.push_back(latex.empty() ? name : latex);
  version_ = next_version();
  return s;
}

void SymbolTable::set_dimension(const std::string& name, const Dimension& dimension) {
  (void)index_.at(name);
  dimensions_[name] = dimension;
}

std::map<std::string, SymbolTable::Dimension> SymbolTable::dimensions() const {
  return dimensions_.size() == names_.size() ? dimensions_ : std::map<std::string, Dimension>{};
}

const GiNaC::ex& SymbolTable::at(const std::string& name) const {
  return symbols_.at(index_.at(name));
}

std::string SymbolTable::latex_of(const std::string& name) const {
  auto it = index_.find(name);
  if (it != index_.end()) return latex_[it->second];
  // Auxiliary symbols (lambda of the characteristic polynomial, ...): Greek names as letters.
  static const std::set<std::string> greek{"alpha", "beta",  "gamma", "delta", "theta", "lambda",
                                           "mu",    "sigma", "phi",   "psi",   "omega", "Omega"};
  return greek.count(name) ? "\\" + name : name;
}

std::size_t SymbolTable::order_of(const std::string& name) const {
  auto it = index_.find(name);
  return it == index_.end() ? names_.size() : it->second;
}

namespace {
// "4.3e-403" for a real number of any size (CLN's exponent range is far wider than double's).
std::string shown_size(const GiNaC::numeric& n) {
  if (n.is_zero()) return "0";
  const GiNaC::numeric re = n.real();
  char buf[64];
  const double d = re.to_double();
  if (std::isfinite(d) && std::abs(d) >= std::numeric_limits<double>::min()) {
    std::snprintf(buf, sizeof buf, "%.2g", d);
    return buf;
  }
  const double l10 = GiNaC::log(GiNaC::abs(re)).to_double() / std::log(10.0);
  double e = std::floor(l10), mantissa = std::pow(10.0, l10 - e);
  if (mantissa >= 9.95) mantissa /= 10, e += 1;  // so that it prints as 1.0, not 10
  std::snprintf(buf, sizeof buf, "%s%.2ge%+.0f", re.csgn() < 0 ? "-" : "", mantissa, e);
  return buf;
}
}  // namespace

namespace {
// GiNaC folds exp of a number as soon as it is built, and CLN returns 1.0 for exp of a float
// beyond its range: exp(exp(exp(10))) would read as 1. So exp, sinh and cosh of a number larger
// than kMaxGrowthArgument (e^100000 = 10^43429, far beyond any value a key holds) are refused
// when read, and again when evaluated (an argument that becomes such a number at the values).
constexpr double kMaxGrowthArgument = 1e5;
// The digits of an evaluation, before rounding once to double.
constexpr long kBaseDigits = 40;

bool grows_too_far(const GiNaC::ex& argument) {
  if (!GiNaC::is_a<GiNaC::numeric>(argument)) return false;
  const GiNaC::numeric& x = GiNaC::ex_to<GiNaC::numeric>(argument);
  return GiNaC::abs(x.real()) > kMaxGrowthArgument;
}

std::string too_far_message(const char* name, const GiNaC::ex& argument) {
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "%s of a number about %s is beyond any value wobble evaluates (arguments of exp, "
                "sinh and cosh must stay below 1e5 in size)",
                name, shown_size(GiNaC::ex_to<GiNaC::numeric>(argument)).c_str());
  return buf;
}

const GiNaC::ex& checked_argument(const char* name, const GiNaC::exvector& args) {
  const DigitsGuard guard(kBaseDigits);
  if (grows_too_far(GiNaC::evalf(args.at(0)))) {
    throw ExpressionError(too_far_message(name, GiNaC::evalf(args[0])));
  }
  return args[0];
}
GiNaC::ex guarded_exp(const GiNaC::exvector& a) { return GiNaC::exp(checked_argument("exp", a)); }
GiNaC::ex guarded_sinh(const GiNaC::exvector& a) { return GiNaC::sinh(checked_argument("sinh", a)); }
GiNaC::ex guarded_cosh(const GiNaC::exvector& a) { return GiNaC::cosh(checked_argument("cosh", a)); }

const GiNaC::prototype_table& guarded_reader() {
  static const GiNaC::prototype_table table = [] {
    GiNaC::prototype_table t = GiNaC::get_default_reader();
    t[GiNaC::prototype("exp", 1)] = guarded_exp;
    t[GiNaC::prototype("sinh", 1)] = guarded_sinh;
    t[GiNaC::prototype("cosh", 1)] = guarded_cosh;
    // The names people write for these (ln, arcsin, ...): the same functions, so a key that
    // prints atan still reads an answer written arctan.
    for (const auto& [alias, name] : kFunctionAliases) {
      t[GiNaC::prototype(std::string(alias), 1)] = t.at(GiNaC::prototype(std::string(name), 1));
    }
    return t;
  }();
  return table;
}

// The same at the values: each exp, sinh, cosh argument evaluated (innermost first) before the
// substitution folds it.
void check_growth(const GiNaC::ex& e, const GiNaC::lst& at, const std::string& field) {
  for (std::size_t i = 0; i < e.nops(); ++i) check_growth(e.op(i), at, field);
  if (!GiNaC::is_a<GiNaC::function>(e)) return;
  const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
  if (name != "exp" && name != "sinh" && name != "cosh") return;
  const DigitsGuard guard(kBaseDigits);
  const GiNaC::ex x = GiNaC::evalf(e.op(0).subs(at));
  if (grows_too_far(x)) throw ExpressionError(field + ": " + too_far_message(name.c_str(), x));
}
}  // namespace

GiNaC::ex SymbolTable::parse(const std::string& text, const std::string& field) const {
  if (text.find_first_not_of(" \t") == std::string::npos) {
    throw ExpressionError(field + ": empty expression");
  }
  // Shown in messages as typed, at most the first 40 characters; a control character (ESC
  // would drive the terminal) or a byte that is no UTF-8 shows as '?'.
  const std::string shown = printable(text, 40);
  if (text.size() > kMaxExpressionLength) {
    throw ExpressionError(field + ": expression \"" + shown + "\" is " +
                          std::to_string(text.size()) + " characters long; the limit is " +
                          std::to_string(kMaxExpressionLength));
  }
  int depth = 0;
  for (char c : text) {
    if (c == '(' || c == '[' || c == '{') ++depth;
    if (c == ')' || c == ']' || c == '}') --depth;
    if (depth > kMaxExpressionDepth) {
      throw ExpressionError(field + ": expression \"" + shown + "\" is nested deeper than " +
                            std::to_string(kMaxExpressionDepth) + " levels");
    }
  }
  GiNaC::symtab tab;
  for (std::size_t i = 0; i < names_.size(); ++i) tab[names_[i]] = symbols_[i];
  tab["pi"] = GiNaC::Pi;
  tab["Pi"] = GiNaC::Pi;
  check_expression_cost(text, field, shown, tab);
  GiNaC::parser reader(tab, /*strict=*/true, guarded_reader());
  try {
    return reader(exact_literals(text));
  } catch (const ExpressionError& e) {
    throw ExpressionError(field + ": " + e.what());
  } catch (const std::exception& e) {
    throw ExpressionError(field + ": cannot read expression \"" + shown + "\": " +
                          plain_parse_error(text, first_line(e.what())));
  }
}

GiNaC::ex exact_value(double d) {
  if (d == 0.0 || !std::isfinite(d)) return GiNaC::numeric(0);
  if (auto p = pi_multiple(d)) return *p;
  return shortest_decimal(d);
}

GiNaC::lst substitution(const SymbolTable& table, const Values& values) {
  GiNaC::lst subs;
  for (const auto& name : table.names()) {
    auto it = values.find(name);
    if (it == values.end()) continue;
    subs.append(table.at(name) == exact_value(it->second));
  }
  return subs;
}

namespace {
// evalf from the leaves up. GiNaC's EllipticK and EllipticE evaluate only a floating-point
// argument, and evalf() hands them the exact one (EllipticK(3/10*sqrt(10)) stays as it is).
// A power's exponent stays exact: evalf() would make (pi - 6)^(-1) a float to the power -1.0,
// which CLN takes through a complex logarithm, leaving an imaginary part of 1e-60 that made the
// modulus of a top's elliptic functions "not a real number".
struct DeepEvalf : GiNaC::map_function {
  GiNaC::ex operator()(const GiNaC::ex& e) override {
    if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
        GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_rational()) {
      return GiNaC::evalf(GiNaC::pow((*this)(e.op(0)), e.op(1)));
    }
    return GiNaC::evalf(e.map(*this));
  }
};

// A number for a message: 6 significant digits.
std::string shown_number(const GiNaC::ex& k) {
  if (!GiNaC::is_a<GiNaC::numeric>(k) || !GiNaC::ex_to<GiNaC::numeric>(k).is_real()) {
    return "not a real number";
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", GiNaC::ex_to<GiNaC::numeric>(k).to_double());
  return buf;
}

// EllipticK(k) is finite for -1 < k < 1 only and EllipticE(k) real for -1 <= k <= 1; GiNaC
// evaluates EllipticK(1) forever (a student's answer hung the grader). Each argument is
// evaluated first and an out-of-range one refused.
//
// Near the separatrix of a top k is within 1e-80 or 1e-300 of 1 (a wobble 1e-40 of the spin),
// where K(k) ~ log(4 / sqrt(1 - k^2)) is perfectly finite but 40 digits round k to 1. So k is
// evaluated with more digits until 1 - |k| shows (up to kMaxDigits), and the whole expression
// then gets those digits plus the usual 40. Returns the digits needed.
constexpr long kMaxDigits = 1200;

long elliptic_digits(const GiNaC::ex& e, const std::string& field) {
  long need = kBaseDigits;
  for (std::size_t i = 0; i < e.nops(); ++i) need = std::max(need, elliptic_digits(e.op(i), field));
  if (!GiNaC::is_a<GiNaC::function>(e)) return need;
  const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
  if (name != "EllipticK" && name != "EllipticE") return need;
  const bool is_k = name == "EllipticK";
  GiNaC::ex k;
  for (long digits = kBaseDigits; digits <= kMaxDigits; digits *= 3) {
    // Evaluated with 10 guard digits: a gap within 10^-digits of 0 is rounding, either sign.
    const DigitsGuard guard(digits + 10);
    DeepEvalf deep;
    k = deep(e.op(0));
    if (!GiNaC::is_a<GiNaC::numeric>(k) || !GiNaC::ex_to<GiNaC::numeric>(k).is_real()) break;
    const GiNaC::numeric gap = 1 - GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(k));
    const GiNaC::numeric resolution = GiNaC::numeric(10).power(-digits);
    if (gap < -resolution) break;
    if (gap > resolution) {
      // 1 - |k| = 10^-n: n more digits keep 40 of them in 1 - k^2 (n <= digits here).
      const double n = -std::log10(std::max(gap.to_double(), 1e-300));
      const long extra = gap.to_double() > 1e-300 ? static_cast<long>(std::ceil(n)) : digits;
      return std::max(need, kBaseDigits + extra);
    }
    if (!is_k && GiNaC::abs(gap) < resolution) return need;  // EllipticE(±1) = 1
  }
  throw ExpressionError(field + ": " + name + "(k) is " +
                        (is_k ? "finite only for -1 < k < 1" : "real only for -1 <= k <= 1") +
                        "; here k = " + shown_number(k));
}
}  // namespace


namespace {
double evaluate_once(const GiNaC::ex& e, const GiNaC::lst& at, const std::string& field) {
  GiNaC::ex v;
  try {
    check_growth(e, at, field);
    const GiNaC::ex exact = e.subs(at);
    DigitsGuard guard(elliptic_digits(exact, field));
    v = GiNaC::evalf(exact);
    if (!GiNaC::is_a<GiNaC::numeric>(v)) {
      DeepEvalf deep;
      v = deep(exact);
    }
  } catch (const ExpressionError&) {
    throw;
  } catch (const std::exception& x) {
    // GiNaC and CLN report a division by zero (0^m/0^m at m > 0) or a floating-point overflow
    // by exceptions of their own: at these values the expression has no value.
    throw ExpressionError(field + ": expression has no value at these values (" +
                          first_line(x.what()) + ")");
  }
  if (!GiNaC::is_a<GiNaC::numeric>(v)) {
    throw ExpressionError(field + ": expression does not evaluate to a number: " +
                          GiNaC::ex_to<GiNaC::basic>(v).class_name());
  }
  const auto& n = GiNaC::ex_to<GiNaC::numeric>(v);
  if (!n.is_real()) throw ExpressionError(field + ": expression is not real");
  const double d = n.to_double();
  // Beyond double's range the value is refused, never replaced by infinity, 0 or a subnormal
  // with fewer digits than the key prints.
  if (!std::isfinite(d) || (!n.is_zero() && std::abs(d) < std::numeric_limits<double>::min())) {
    throw ExpressionError(field + ": its value, about " + shown_size(n) +
                          ", is outside the range of double precision (1e-308 to 1e308 in size)");
  }
  return d;
}
}  // namespace

double evaluate(const GiNaC::ex& e, const GiNaC::lst& at, const std::string& field) {
  // Each answer's value is taken more than once (the answer, its check against the numeric
  // route, the sign of an axis): 80 of the three-atom molecule's 116 evaluations repeat one.
  thread_local Memo<double, std::pair<GiNaC::ex, GiNaC::ex>, ExPairLess> known;
  return known.get({e, at}, [&] { return evaluate_once(e, at, field); });
}


int sign_of(const GiNaC::ex& e, const GiNaC::lst& at, const std::string& field) {
  const GiNaC::ex exact = e.subs(at);
  if (GiNaC::is_a<GiNaC::numeric>(exact) && GiNaC::ex_to<GiNaC::numeric>(exact).is_rational()) {
    const int s = GiNaC::ex_to<GiNaC::numeric>(exact).csgn();
    if (s != 0) return s;
  }
  GiNaC::numeric previous;
  for (long digits = kBaseDigits; digits <= kMaxDigits; digits *= 3) {
    GiNaC::ex v;
    {
      const DigitsGuard guard(std::max(digits, elliptic_digits(exact, field)));
      DeepEvalf deep;
      v = deep(exact);
    }
    if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) {
      throw ExpressionError(field + ": expression is not real");
    }
    const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(v);
    if (digits > kBaseDigits && !n.is_zero() && !previous.is_zero() &&
        n.csgn() == previous.csgn() && GiNaC::abs(n - previous) < GiNaC::abs(n) / 100) {
      return n.csgn();
    }
    previous = n;
  }
  throw ExpressionError(field + ": its sign is not decided within 1080 digits (it is 0 or "
                                "closer to 0 than that)");
}

namespace {
// Nodes of e, and powers with a non-numeric exponent (which normal() treats as new symbols),
// counted up to the limits.
struct Size {
  int nodes = 0, symbolic_powers = 0;
  int depth = 0;              ///< the deepest nesting of sums, products and powers
  double expanded_terms = 0;  ///< the most terms one power of a sum expands to
};
// Terms of (k terms)^n expanded: C(n + k - 1, k - 1), saturating far above any limit.
double expanded_terms(double k, double n) {
  double c = 1;
  for (double i = 1; i < k && c < 1e12; ++i) c = c * (n + i) / i;
  return c;
}
void measure(const GiNaC::ex& e, Size& s, int level = 1) {
  s.depth = std::max(s.depth, level);
  if (++s.nodes > 400) return;
  if (GiNaC::is_a<GiNaC::power>(e) && !GiNaC::is_a<GiNaC::numeric>(e.op(1))) ++s.symbolic_powers;
  if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::add>(e.op(0)) &&
      e.op(1).info(GiNaC::info_flags::integer)) {
    const double n = std::abs(GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_double());
    s.expanded_terms = std::max(s.expanded_terms,
                                expanded_terms(static_cast<double>(e.op(0).nops()), n));
  }
  for (std::size_t i = 0; i < e.nops() && s.nodes <= 400; ++i) measure(e.op(i), s, level + 1);
}
}  // namespace

namespace {
bool is_identically_zero_once(const GiNaC::ex& e) {
  // normal() of a large expression, or of a sum of many powers such as 2^m/26^m, grows without
  // bound (fuzzing found an out-of-memory and a 44 s case); beyond these sizes nothing is proved.
  Size size;
  measure(e, size);
  // normal() expands powers of sums: (m+R+omega+alpha)^400 would have 1e7 terms (6 GB).
  constexpr double kMaxExpandedTerms = 2000;
  // Fractions nested in sums nested in products, 97 deep in 334 nodes ("5/m" under runs of
  // minus signs, found by fuzzing), took normal() 1.5 s (41 s under the sanitizers); the
  // catalog's answers nest 12 deep at most, and a student's rarely more than a bracket or two.
  constexpr int kMaxDepth = 32;
  if (size.nodes > 400 || size.symbolic_powers > 4 || size.expanded_terms > kMaxExpandedTerms ||
      size.depth > kMaxDepth) {
    return false;
  }
  try {
    return GiNaC::normal(e).is_zero();
  } catch (const std::exception&) {
    return false;  // normal() divided by zero: not shown to be zero (the evaluation decides)
  }
}
}  // namespace

bool is_identically_zero(const GiNaC::ex& e) {
  // Kept under the one of e and -e that orders first: whether two moments are equal is asked
  // as a - b and as b - a (the three-atom molecule asks 18 times about 15 expressions, 9 up to
  // their sign).
  thread_local Memo<bool> known;
  const GiNaC::ex negated = -e;
  return known.get(e.compare(negated) <= 0 ? e : negated,
                   [&] { return is_identically_zero_once(e); });
}

GiNaC::ex normal_kept(const GiNaC::ex& e) {
  // normal() maps itself over a function's arguments and stands a symbol in for the function;
  // a number c times it gives c*symbol over 1 (c an integer) or over c's denominator, so the
  // result is c*f(normal(x)) (a test compares both with GiNaC's).
  if (GiNaC::is_a<GiNaC::function>(e)) {
    return e.map([](const GiNaC::ex& x) { return normal_kept(x); });
  }
  if (GiNaC::is_a<GiNaC::mul>(e) && e.nops() == 2 && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
      GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_rational() &&
      GiNaC::is_a<GiNaC::function>(e.op(0))) {
    return normal_kept(e.op(0)) * e.op(1);
  }
  thread_local Memo<GiNaC::ex> known;
  return known.get(e, [&] { return GiNaC::normal(e); });
}

namespace {
// n = s^2 k, for a positive integer n, with the squares of the primes below 1000 in s: GiNaC
// evaluates the root of a perfect square but leaves sqrt(8) and sqrt(23328) as they are. Bounded,
// as a decimal typed with many digits can make n large; a larger prime's square stays in k.
std::pair<GiNaC::numeric, GiNaC::numeric> split_square(GiNaC::numeric n) {
  GiNaC::numeric s = 1;
  constexpr int kLargestPrime = 1000;
  for (int p = 2; p < kLargestPrime && p * p <= n; ++p) {
    const GiNaC::numeric p2 = p * p;
    while (GiNaC::irem(n, p2).is_zero()) {
      s *= p;
      n = GiNaC::iquo(n, p2);
    }
  }
  return {s, n};
}
}  // namespace

GiNaC::ex simplified_sqrt(const GiNaC::ex& e) {
  // factor() works on polynomials: stand symbols in for sin(alpha) etc., and factor numerator
  // and denominator separately. numer_denom() is normal() without the division (see simplify).
  GiNaC::exmap functions;
  const GiNaC::ex normal_nd = GiNaC::numer_denom(e);
  const GiNaC::ex nd = GiNaC::lst{normal_nd.op(0).to_rational(functions),
                                  normal_nd.op(1).to_rational(functions)};
  GiNaC::ex outside = 1, inside = 1;
  // The numbers under the root, gathered (their signs left inside), to come out once at the end:
  // sqrt(8/75) is 2 sqrt(6)/15, where taking out 8 and 75 apart would leave 2 sqrt(2) sqrt(3)/15.
  GiNaC::numeric number = 1;
  const auto take_number = [&](GiNaC::numeric base, const GiNaC::numeric& n, int sign) {
    // A negative number's sign stays inside, with the sum GiNaC gave the other sign: which of
    // -4 (-X) and 4 X normal() gives follows GiNaC's run-dependent term order, and the root
    // is to take 2 out of both alike (one key was printed two ways from run to run).
    if (base.is_negative()) {
      if (n.is_odd()) inside *= -1;
      base = -base;
    }
    number *= GiNaC::ex_to<GiNaC::numeric>(GiNaC::pow(base, sign * n));
  };
  // Moves the even part of each positive factor^n (n = +-exponent) out of the root.
  const auto take = [&](const GiNaC::ex& factor, int sign) {
    GiNaC::ex base = factor;
    GiNaC::numeric n = 1;
    if (GiNaC::is_a<GiNaC::power>(factor) && factor.op(1).info(GiNaC::info_flags::posint)) {
      base = factor.op(0);
      n = GiNaC::ex_to<GiNaC::numeric>(factor.op(1));
    }
    // GiNaC distributes a number over a sum (16 (x + y) is 16 x + 16 y), so factored() cannot
    // keep a sum's integer content apart: it is taken out here as a number of its own.
    if (GiNaC::is_a<GiNaC::add>(base) && base.info(GiNaC::info_flags::rational_polynomial)) {
      const GiNaC::numeric content = base.integer_content();
      if (!content.is_zero() && content != 1) {
        take_number(content, n, sign);
        base = GiNaC::expand(base / content);
      }
    }
    if (GiNaC::is_a<GiNaC::numeric>(base) && GiNaC::ex_to<GiNaC::numeric>(base).is_rational() &&
        !GiNaC::ex_to<GiNaC::numeric>(base).is_zero()) {
      take_number(GiNaC::ex_to<GiNaC::numeric>(base), n, sign);
    } else if (base.info(GiNaC::info_flags::positive)) {
      const GiNaC::numeric half = GiNaC::iquo(n, 2);
      outside *= GiNaC::pow(base, sign * half);
      inside *= GiNaC::pow(base, sign * (n - 2 * half));
    } else {
      inside *= GiNaC::pow(base, sign * n);
    }
  };
  for (const int sign : {1, -1}) {
    const GiNaC::ex f = factored(nd.op(sign > 0 ? 0 : 1));
    if (GiNaC::is_a<GiNaC::mul>(f)) {
      for (std::size_t i = 0; i < f.nops(); ++i) take(f.op(i), sign);
    } else {
      take(f, sign);
    }
  }
  // sqrt(p/q) = sqrt(p q)/q.
  const auto [square_root, rest] = split_square(number.numer() * number.denom());
  outside *= square_root * GiNaC::sqrt(GiNaC::ex(rest)) / number.denom();
  return (outside * GiNaC::sqrt(inside)).subs(functions);
}

namespace {
// Replaces every even power of `from` (cos or sin) by powers of 1 - other^2: one fixed reduction
// modulo sin^2 + cos^2 = 1, so the expanded result is a canonical form.
struct PythagoreanReduction : GiNaC::map_function {
  bool cos_to_sin;
  explicit PythagoreanReduction(bool c) : cos_to_sin(c) {}
  GiNaC::ex operator()(const GiNaC::ex& x) override {
    if (GiNaC::is_a<GiNaC::power>(x) && x.op(1).info(GiNaC::info_flags::posint)) {
      const GiNaC::ex& f = x.op(0);
      using namespace GiNaC;  // is_ex_the_function is a macro that names GiNaC's function ids
      const bool match = cos_to_sin ? is_ex_the_function(f, cos) : is_ex_the_function(f, sin);
      const int n = GiNaC::ex_to<GiNaC::numeric>(x.op(1)).to_int();
      if (match && n >= 2) {
        const GiNaC::ex other = cos_to_sin ? GiNaC::sin(f.op(0)) : GiNaC::cos(f.op(0));
        return GiNaC::pow(1 - GiNaC::pow(other, 2), n / 2) * GiNaC::pow(f, n % 2);
      }
    }
    return x.map(*this);
  }
};

// True if `holds` is true of e or of any subexpression of e.
template <class Predicate>
bool any_node(const GiNaC::ex& e, const Predicate& holds) {
  if (holds(e)) return true;
  for (std::size_t i = 0; i < e.nops(); ++i) {
    if (any_node(e.op(i), holds)) return true;
  }
  return false;
}

bool has_function(const GiNaC::ex& e) {
  return any_node(e, [](const GiNaC::ex& x) { return GiNaC::is_a<GiNaC::function>(x); });
}

// Where neither occurs, both reductions leave a polynomial as it is (expanded).
bool has_sin_or_cos(const GiNaC::ex& e) {
  return any_node(e, [](const GiNaC::ex& x) {
    using namespace GiNaC;  // is_ex_the_function is a macro that names GiNaC's function ids
    return is_ex_the_function(x, sin) || is_ex_the_function(x, cos);
  });
}

GiNaC::ex reduced(const GiNaC::ex& polynomial, bool cos_to_sin) {
  // The reduction rebuilds every node of the expression (GiNaC's map() does), to no effect
  // where there is nothing to reduce: most of the catalog's expressions.
  if (!has_sin_or_cos(polynomial)) return GiNaC::expand(polynomial);
  PythagoreanReduction r(cos_to_sin);
  return GiNaC::expand(r(GiNaC::expand(polynomial)));
}

// True if e has a power with a negative integer exponent (a written denominator) anywhere.
bool has_written_denominator(const GiNaC::ex& e) {
  return any_node(e, [](const GiNaC::ex& x) {
    return GiNaC::is_a<GiNaC::power>(x) && x.op(1).info(GiNaC::info_flags::negint);
  });
}

// A term as numerator and denominator, as written: the factors with a negative integer power
// (their inverses) below, the rest above. No gcd is taken.
std::pair<GiNaC::ex, GiNaC::ex> written_fraction(const GiNaC::ex& term) {
  GiNaC::ex num = 1, den = 1;
  const auto one = [&](const GiNaC::ex& f) {
    if (GiNaC::is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::negint)) {
      den *= GiNaC::pow(f.op(0), -f.op(1));
    } else {
      num *= f;
    }
  };
  if (GiNaC::is_a<GiNaC::mul>(term)) {
    for (const auto& f : term) one(f);
  } else {
    one(term);
  }
  return {num, den};
}

// e with every sum whose terms are written over one denominator (P/D - Q/D, from entries of a
// tensor about the centre of mass) written as one fraction, (P - Q)/D, innermost first. The same
// rational function, so normal() finds the same numerator and denominator, in one gcd with the
// denominator instead of one for each term and one for the sum: the three-atom molecule's
// ((A - B)/2)^2 + C^2 took 2.8 ms, written so 2.2 ms.
GiNaC::ex over_one_denominator(const GiNaC::ex& e) {
  // Without a denominator nothing is rewritten: e as it is, not rebuilt node by node by map().
  if ((!GiNaC::is_a<GiNaC::add>(e) && !GiNaC::is_a<GiNaC::mul>(e) &&
       !GiNaC::is_a<GiNaC::power>(e)) ||
      !has_written_denominator(e)) {
    return e;
  }
  const GiNaC::ex inner = e.map([](const GiNaC::ex& x) { return over_one_denominator(x); });
  if (!GiNaC::is_a<GiNaC::add>(inner)) return inner;
  GiNaC::ex num = 0, den;
  for (std::size_t i = 0; i < inner.nops(); ++i) {
    const auto [n, d] = written_fraction(inner.op(i));
    if (i == 0) {
      den = d;
    } else if (!d.is_equal(den)) {
      return inner;
    }
    num += n;
  }
  return den.is_equal(1) ? inner : num / den;
}
}  // namespace

namespace {
// e with a real symbol standing in for each function in it (sin(alpha), atan2(..)), the same
// symbol for the same function in every call: then an expression met again is the same
// polynomial, which tidy() finds among those it has factored (to_rational() makes new symbols
// each time). back maps the symbols to the functions.
struct FunctionsAsSymbols : GiNaC::map_function {
  GiNaC::exmap& back;
  explicit FunctionsAsSymbols(GiNaC::exmap& b) : back(b) {}
  GiNaC::ex operator()(const GiNaC::ex& x) override {
    if (!GiNaC::is_a<GiNaC::function>(x)) return x.map(*this);
    thread_local std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> symbols;
    constexpr std::size_t kMaxKept = 4096;  // bounded, as the memos are
    if (symbols.size() > kMaxKept) symbols.clear();
    auto found = symbols.find(x);
    if (found == symbols.end()) found = symbols.emplace(x, GiNaC::realsymbol()).first;
    back[found->second] = x;
    return found->second;
  }
};

GiNaC::ex functions_as_symbols(const GiNaC::ex& e, GiNaC::exmap& back) {
  FunctionsAsSymbols f(back);
  return f(e);
}

// num / den (each expanded) with the content of each, a number times a monomial, taken out of
// its sum, symbols standing in for sin(alpha) etc. while it is found: the three-atom molecule's
// M m2 d2^2 sin^2 alpha + m1 m2 d2^2 sin^2 alpha is m2 d2^2 sin^2 alpha (M + m1). Factoring the
// sums that remain as well (tidy()) found nothing more in any key, and proving them irreducible
// took half of what this candidate cost the molecule's solve (18.5 of 34 million
// instructions). A fraction whose functions cancelled, or with a number such as pi or sqrt(2)
// among its coefficients, is factored whole.
GiNaC::ex with_content_out(const GiNaC::ex& num, const GiNaC::ex& den) {
  GiNaC::exmap back;
  const GiNaC::ex n = functions_as_symbols(num, back), d = functions_as_symbols(den, back);
  const auto polynomial = [](const GiNaC::ex& p) {
    return p.info(GiNaC::info_flags::rational_polynomial);
  };
  if (back.empty() || !polynomial(n) || !polynomial(d)) return tidy(n / d).subs(back);
  const auto content_out = [](const GiNaC::ex& p) {
    if (!GiNaC::is_a<GiNaC::add>(p)) return p;
    const auto [content, rest] = split_content(p);
    return content * rest;
  };
  // Reducing sin^2 + cos^2 may leave a factor of the denominator in the numerator (the sum of
  // the masses), which the exact divisions find.
  const auto [numerator, denominator] = sums_divided_out(n, d);
  return (content_out(numerator) / denominator).subs(back);
}
}  // namespace

GiNaC::ex simplify(const GiNaC::ex& e) {
  // normal() gives numerator and denominator, unique up to a sign; each candidate below is a
  // canonical form of them, and the canonical printer's text does not depend on GiNaC's
  // run-dependent term order and signs, so the same candidate wins in every run (and any
  // form of the same rational function, as over_one_denominator's, gives the same).
  // numer_denom() returns the numerator and denominator normal() finds; numer_denom(normal())
  // divided them and normalised the quotient again, proving once more by a gcd that the two
  // are coprime (18% of the three-atom molecule's solve).
  const GiNaC::ex nd = GiNaC::numer_denom(over_one_denominator(e));
  const GiNaC::ex num = reduced(nd.op(0), true), den = reduced(nd.op(1), true);
  std::vector<GiNaC::ex> candidates{num / den};  // cos^2 -> 1 - sin^2
  // sin^2 -> 1 - cos^2, which differs from the first only where sin or cos occurs (a copy of
  // the first could never be shorter than it).
  if (has_sin_or_cos(nd)) {
    candidates.push_back(reduced(nd.op(0), false) / reduced(nd.op(1), false));
  }
  if (!has_function(e)) {
    candidates.push_back(tidy(e));  // factored numerator and denominator
  } else {
    candidates.push_back(with_content_out(num, den));
  }
  // The one with fewest minus signs, then the shortest: cos²α + 1, not 2 − sin²α, and √(3
  // sin²α + 1), not √(4 − 3 cos²α) (the printer writes a sum's positive terms first, so that
  // length alone no longer tells them apart).
  static const SymbolTable no_table;
  const auto rank = [](const GiNaC::ex& c) {
    const std::string text = to_text(c, no_table);
    return std::pair{std::count(text.begin(), text.end(), '-'), text.size()};
  };
  GiNaC::ex best = candidates[0];
  auto best_rank = rank(best);
  for (std::size_t i = 1; i < candidates.size(); ++i) {
    if (const auto r = rank(candidates[i]); r < best_rank) {
      best = candidates[i];
      best_rank = r;
    }
  }
  return best;
}

namespace {
// factor() can leave an irreducible factor partly collected (a^2*(e^2 + w^2) + c^2*w^2 + ...),
// grouped differently from run to run (it follows GiNaC's term order). Expanded, each factor
// has one form, which the canonical printer prints the same way in every run.
GiNaC::ex expand_factors(const GiNaC::ex& f) {
  if (GiNaC::is_a<GiNaC::mul>(f)) {
    GiNaC::ex out = 1;
    for (std::size_t i = 0; i < f.nops(); ++i) out *= expand_factors(f.op(i));
    return out;
  }
  if (GiNaC::is_a<GiNaC::power>(f)) return GiNaC::pow(expand_factors(f.op(0)), f.op(1));
  if (GiNaC::is_a<GiNaC::add>(f)) return GiNaC::expand(f);
  return f;
}
}  // namespace

GiNaC::ex tidy(const GiNaC::ex& e) {
  // The tennis racket's key tidies the same expression 35 times of 65.
  thread_local Memo<GiNaC::ex> known;
  return known.get(e, [&] {
    const GiNaC::ex nd = GiNaC::numer_denom(e);
    return expand_factors(factored(nd.op(0))) / expand_factors(factored(nd.op(1)));
  });
}

}  // namespace wobble::sym
