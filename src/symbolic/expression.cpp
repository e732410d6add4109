#include "symbolic/expression.hpp"

#include <cctype>
#include <array>
#include <cmath>
#include <sstream>

namespace wobble::sym {

namespace {
bool is_identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  }
  return true;
}

// GiNaC's parse errors carry a source location on following lines; keep the first line.
std::string first_line(const std::string& s) {
  auto pos = s.find('\n');
  std::string line = s.substr(0, pos);
  const std::string prefix = "GiNaC: ";
  if (line.rfind(prefix, 0) == 0) line = line.substr(prefix.size());
  return line;
}

// Restores GiNaC's global precision on scope exit.
struct DigitsGuard {
  long saved = static_cast<long>(GiNaC::Digits);
  explicit DigitsGuard(long digits) { GiNaC::Digits = digits; }
  ~DigitsGuard() { GiNaC::Digits = saved; }
  DigitsGuard(const DigitsGuard&) = delete;
  DigitsGuard& operator=(const DigitsGuard&) = delete;
};
// The double's exact value as a rational: CLN's float contagion would otherwise drop every later
// operation to double precision, defeating the 40-digit evaluation.
GiNaC::numeric exact_rational(double d) {
  int exponent = 0;
  const double mantissa = std::frexp(d, &exponent);  // d = mantissa * 2^exponent, |mantissa| < 1
  const auto integer = static_cast<long>(std::ldexp(mantissa, 53));
  return GiNaC::numeric(integer) * GiNaC::numeric(2).power(exponent - 53);
}
}  // namespace

GiNaC::ex SymbolTable::declare(const std::string& name, const std::string& latex,
                               SymbolSign sign) {
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
  return s;
}

const GiNaC::ex& SymbolTable::at(const std::string& name) const {
  return symbols_.at(index_.at(name));
}

std::string SymbolTable::latex_of(const std::string& name) const {
  auto it = index_.find(name);
  return it == index_.end() ? name : latex_[it->second];
}

std::size_t SymbolTable::order_of(const std::string& name) const {
  auto it = index_.find(name);
  return it == index_.end() ? names_.size() : it->second;
}

GiNaC::ex SymbolTable::parse(const std::string& text, const std::string& field) const {
  if (text.find_first_not_of(" \t") == std::string::npos) {
    throw ExpressionError(field + ": empty expression");
  }
  GiNaC::symtab tab;
  for (std::size_t i = 0; i < names_.size(); ++i) tab[names_[i]] = symbols_[i];
  tab["pi"] = GiNaC::Pi;
  tab["Pi"] = GiNaC::Pi;
  GiNaC::parser reader(tab, /*strict=*/true);
  try {
    return reader(text);
  } catch (const std::exception& e) {
    std::string why = first_line(e.what());
    const std::string missing = "find_or_insert_symbol: symbol \"";
    if (auto p = why.find(missing); p != std::string::npos) {
      auto name = why.substr(p + missing.size());
      name = name.substr(0, name.find('"'));
      why = "undefined symbol '" + name + "'";
    }
    throw ExpressionError(field + ": cannot read expression \"" + text + "\": " + why);
  }
}

GiNaC::lst substitution(const SymbolTable& table, const Values& values) {
  GiNaC::lst subs;
  for (const auto& name : table.names()) {
    auto it = values.find(name);
    if (it == values.end()) continue;
    subs.append(table.at(name) == exact_rational(it->second));
  }
  return subs;
}

double evaluate(const GiNaC::ex& e, const GiNaC::lst& at, const std::string& field) {
  DigitsGuard guard(40);
  GiNaC::ex v = GiNaC::evalf(e.subs(at));
  if (!GiNaC::is_a<GiNaC::numeric>(v)) {
    throw ExpressionError(field + ": expression does not evaluate to a number: " +
                          GiNaC::ex_to<GiNaC::basic>(v).class_name());
  }
  const auto& n = GiNaC::ex_to<GiNaC::numeric>(v);
  if (!n.is_real()) throw ExpressionError(field + ": expression is not real");
  const double d = n.to_double();
  if (!std::isfinite(d)) throw ExpressionError(field + ": expression is not finite");
  return d;
}

bool is_identically_zero(const GiNaC::ex& e) { return GiNaC::normal(e).is_zero(); }

GiNaC::ex simplified_sqrt(const GiNaC::ex& e) {
  GiNaC::ex f = GiNaC::factor(GiNaC::normal(e));
  GiNaC::ex outside = 1, inside = 1;
  auto take = [&](const GiNaC::ex& factor) {
    if (GiNaC::is_a<GiNaC::power>(factor) && factor.op(1).info(GiNaC::info_flags::posint) &&
        factor.op(0).info(GiNaC::info_flags::positive)) {
      const auto n = GiNaC::ex_to<GiNaC::numeric>(factor.op(1));
      const GiNaC::numeric half = GiNaC::iquo(n, 2);
      outside *= GiNaC::pow(factor.op(0), half);
      inside *= GiNaC::pow(factor.op(0), n - 2 * half);
    } else {
      inside *= factor;
    }
  };
  if (GiNaC::is_a<GiNaC::mul>(f)) {
    for (std::size_t i = 0; i < f.nops(); ++i) take(f.op(i));
  } else {
    take(f);
  }
  return outside * GiNaC::sqrt(inside);
}

GiNaC::ex simplify(const GiNaC::ex& e) {
  const GiNaC::ex w = GiNaC::wild(0);
  const GiNaC::ex base = GiNaC::normal(GiNaC::expand(e));
  const std::array<GiNaC::ex, 3> candidates{
      base,
      GiNaC::normal(GiNaC::expand(base.subs(GiNaC::pow(GiNaC::sin(w), 2) == 1 - GiNaC::pow(GiNaC::cos(w), 2),
                                            GiNaC::subs_options::algebraic))),
      GiNaC::normal(GiNaC::expand(base.subs(GiNaC::pow(GiNaC::cos(w), 2) == 1 - GiNaC::pow(GiNaC::sin(w), 2),
                                            GiNaC::subs_options::algebraic)))};
  auto length = [](const GiNaC::ex& x) {
    std::ostringstream s;
    s << x;
    return s.str().size();
  };
  GiNaC::ex best = candidates[0];
  std::size_t best_length = length(best);
  for (std::size_t i = 1; i < candidates.size(); ++i) {
    const std::size_t l = length(candidates[i]);
    if (l < best_length) {
      best = candidates[i];
      best_length = l;
    }
  }
  // A factored numerator often reads better (m*d^2*(...)); keep it only if not longer.
  const GiNaC::ex factored = tidy(best);
  return length(factored) <= best_length ? factored : best;
}

GiNaC::ex tidy(const GiNaC::ex& e) {
  GiNaC::ex n = GiNaC::normal(e);
  GiNaC::ex nd = GiNaC::numer_denom(n);
  return GiNaC::factor(nd.op(0)) / GiNaC::factor(nd.op(1));
}

}  // namespace wobble::sym
