#include "symbolic/factored.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "symbolic/memo.hpp"

namespace wobble::sym {

namespace {
using GiNaC::ex;

// Two sets of values for the symbols held fixed in an image: distinct primes, so that no
// coincidence of small values (a - b = 0, a = 1) makes an image degenerate.
constexpr std::array<std::array<int, 12>, 2> kValues{{
    {3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41},
    {43, 47, 53, 59, 61, 67, 71, 73, 79, 83, 89, 97},
}};

// Held as ex: a copy as GiNaC::symbol would slice a possymbol or realsymbol into a symbol of
// another class, which no longer matches it in degree(), coeff() or subs().
using Symbols = std::vector<ex>;

Symbols symbols_of(const ex& p) {
  Symbols out;
  for (auto it = p.preorder_begin(); it != p.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::symbol>(*it) &&
        std::none_of(out.begin(), out.end(), [&](const ex& o) { return o.is_equal(*it); })) {
      out.push_back(*it);
    }
  }
  // By name, so that the symbols take the same values in every run (GiNaC's own order follows
  // hash values that change from run to run).
  const auto name = [](const ex& s) { return GiNaC::ex_to<GiNaC::symbol>(s).get_name(); };
  std::sort(out.begin(), out.end(), [&](const ex& a, const ex& b) {
    return name(a) < name(b) || (name(a) == name(b) && a.compare(b) < 0);
  });
  return out;
}

// q with every symbol but `keep` given the value of set `set`.
ex image(const ex& q, const Symbols& symbols, const ex& keep, std::size_t set) {
  GiNaC::exmap values;
  for (std::size_t i = 0; i < symbols.size(); ++i) {
    if (!symbols[i].is_equal(keep)) values[symbols[i]] = kValues[set][i];
  }
  return GiNaC::expand(q.subs(values));
}

bool is_monomial(const ex& c) {  // c expanded (a coefficient of an expanded polynomial)
  return !GiNaC::is_a<GiNaC::add>(c);
}

// gcd(a, b) shown to be a number: in each symbol y of a, the images of a and b (all else fixed)
// have a constant gcd, and a's image keeps its degree in y (so a common factor involving y,
// whose leading coefficient divides a's, would keep a degree >= 1 in both images).
bool coprime(const ex& a, const ex& b, const Symbols& symbols) {
  for (const auto& y : symbols) {
    const int d = a.degree(y);
    if (d == 0) continue;
    bool shown = false;
    for (std::size_t set = 0; set < kValues.size() && !shown; ++set) {
      const ex a_y = image(a, symbols, y, set), b_y = image(b, symbols, y, set);
      shown = a_y.degree(y) == d && GiNaC::gcd(a_y, b_y).degree(y) == 0;
    }
    if (!shown) return false;
  }
  return true;
}

// The gcd of p's coefficients in x shown to be a number (p has no symbol as a factor).
bool primitive_in(const ex& p, const ex& x, const Symbols& symbols) {
  std::vector<ex> coefficients;
  for (int k = 0; k <= p.degree(x); ++k) {
    const ex c = p.coeff(x, k);
    if (c.is_zero()) continue;
    // A number, or a monomial, none of whose symbols divides p: the gcd divides it, so is a
    // product of its symbols, and each of those divides p.
    if (is_monomial(c)) return true;
    coefficients.push_back(c);
  }
  // Any two coprime coefficients will do, the smallest first: two may share a factor the
  // others lack (14 (b^2 + c^2) and 14 b^2 c^2 (b^2 + c^2) beside 14 b^4 + 37 b^2 c^2 + 14 c^4).
  const auto terms = [](const ex& c) { return GiNaC::is_a<GiNaC::add>(c) ? c.nops() : 1; };
  std::sort(coefficients.begin(), coefficients.end(),
            [&](const ex& a, const ex& b) { return terms(a) < terms(b); });
  for (std::size_t i = 0; i < coefficients.size(); ++i) {
    for (std::size_t j = i + 1; j < coefficients.size(); ++j) {
      if (coprime(coefficients[i], coefficients[j], symbols)) return true;
    }
  }
  return false;
}

// An expanded polynomial with rational coefficients in symbols, of two or more terms.
bool is_polynomial_sum(const ex& p) {
  return GiNaC::is_a<GiNaC::add>(p) && p.info(GiNaC::info_flags::rational_polynomial) &&
         p.is_equal(GiNaC::expand(p));
}

// A univariate polynomial over Q irreducible (GiNaC moves a numeric content into the sum).
bool irreducible_univariate(const ex& q) {
  return GiNaC::is_a<GiNaC::add>(GiNaC::factor(q));
}
}  // namespace

bool shown_irreducible(const ex& p) {
  if (!is_polynomial_sum(p)) return false;
  const Symbols symbols = symbols_of(p);
  if (symbols.empty() || symbols.size() > kValues[0].size()) return false;
  for (const auto& v : symbols) {
    if (p.ldegree(v) > 0) return false;  // v divides p: p = v q, q not constant
  }
  for (const auto& x : symbols) {
    const int d = p.degree(x);
    if (d == 0 || !primitive_in(p, x, symbols)) continue;
    if (d == 1) return true;
    for (std::size_t set = 0; set < kValues.size(); ++set) {
      const ex p_x = image(p, symbols, x, set);
      if (p_x.degree(x) == d && irreducible_univariate(p_x)) return true;
    }
  }
  return false;
}

std::pair<ex, ex> split_content(const ex& p) {
  const Symbols symbols = symbols_of(p);
  GiNaC::exmap ones;
  ex monomial = 1;
  for (const auto& v : symbols) {
    ones[v] = 1;
    monomial *= GiNaC::pow(v, p.ldegree(v));
  }
  bool all_negative = true;
  for (std::size_t i = 0; i < p.nops() && all_negative; ++i) {
    all_negative = GiNaC::ex_to<GiNaC::numeric>(p.op(i).subs(ones)).is_negative();
  }
  const ex content = (all_negative ? -1 : 1) * p.integer_content() * monomial;
  return {content, GiNaC::expand(p / content)};
}

namespace {
// Calls yield(base, exponent) for each explicit factor of e (a power's base and exponent, any
// other operand to the power 1, a product's number included), as GiNaC's factor() walks it.
template <typename Yield>
void for_each_factor(const ex& e, Yield yield) {
  const auto one = [&](const ex& f) {
    if (GiNaC::is_a<GiNaC::power>(f)) {
      yield(f.op(0), f.op(1));
    } else {
      yield(f, ex(1));
    }
  };
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    for (const auto& f : e) one(f);
  } else {
    one(e);
  }
}

// Two sums among `sums` (each expanded) equal or opposite: the same irreducible factor.
bool shares_a_sum(const std::vector<ex>& sums) {
  for (std::size_t i = 0; i < sums.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (sums[i].nops() == sums[j].nops() &&
          ((sums[i] - sums[j]).is_zero() || (sums[i] + sums[j]).is_zero())) {
        return true;
      }
    }
  }
  return false;
}

// GiNaC::factor(p) with each factor expanded: factor() may give a factor partly collected as
// its run-dependent term order falls (7 a^2 (36 + c^2) - 252 a^2 - 7 a^2 c^2 + .., or
// 3 M + m (pi + 3)); expanded, a factor has one form, which the canonical printer prints alike
// in every run.
ex factor_expanded(const ex& p) {
  ex factors = 1;
  for_each_factor(GiNaC::factor(p), [&](const ex& base, const ex& exponent) {
    factors *= GiNaC::pow(GiNaC::expand(base), exponent);
  });
  return factors;
}

// factors^exponent as a product where that is true: (a b)^e = a^e b^e for a > 0 (a positive
// number or symbol, pi, a sum of such), but not for two factors of unknown sign. factor()
// distributes a root over every factor it finds, sqrt(-c^2 X) -> I c sqrt(X), which is the
// negative of sqrt(-c^2 X) = c sqrt(-X) where X < 0. An integer power distributes always.
ex power_of_factors(const ex& factors, const ex& exponent) {
  if (exponent.info(GiNaC::info_flags::integer)) return GiNaC::pow(factors, exponent);
  ex out = 1, unknown_sign = 1;
  for_each_factor(factors, [&](const ex& factor, const ex& power) {
    if (factor.info(GiNaC::info_flags::positive)) {
      out *= GiNaC::pow(factor, power * exponent);
    } else {
      unknown_sign *= GiNaC::pow(factor, power);
    }
  });
  return out * GiNaC::pow(unknown_sign, exponent);
}

// GiNaC::factor(p) for p no polynomial over Q: each constant (pi) stands as a positive symbol,
// each root of an expression (a non-integer power) as a symbol for its base factored and taken
// out as above.
// factor() alone takes pi for a coefficient, and its gcd throws ("arguments must be polynomials
// over the rationals") on pi a + pi b, which a rate in rpm (pi/30 rad/s) brings into a key; and
// it distributes a root over the factors of its base.
ex factor_keeping_roots(const ex& p) {
  struct StandIns : GiNaC::map_function {
    std::map<ex, ex, GiNaC::ex_is_less> stand_in;
    GiNaC::exmap back;
    ex operator()(const ex& e) override {
      const bool constant = GiNaC::is_a<GiNaC::constant>(e);
      // A root of a number (sqrt(2)) is a number to factor(), as before: standing in for it
      // would add a symbol to factor in (40 masses at sqrt(k) coordinates: minutes).
      const bool root = GiNaC::is_a<GiNaC::power>(e) && !e.op(1).info(GiNaC::info_flags::integer) &&
                        !GiNaC::is_a<GiNaC::numeric>(e.op(0));
      if (!constant && !root) return e.map(*this);
      if (const auto it = stand_in.find(e); it != stand_in.end()) return it->second;
      const ex symbol = constant ? ex(GiNaC::possymbol("constant")) : ex(GiNaC::symbol("root"));
      stand_in.emplace(e, symbol);
      back[symbol] = constant ? e : power_of_factors(factored(e.op(0)), e.op(1));
      return symbol;
    }
  } stand_ins;
  const ex polynomial = stand_ins(p);  // fills stand_ins.back (empty: p has none to stand in)
  return factor_expanded(polynomial).subs(stand_ins.back);
}

// factor() factors each explicit factor of a product on its own and multiplies the results;
// here each goes through factored() instead, so that a sum shown irreducible is not factored
// from scratch (6 ms for one product in the tennis racket's key). factor() writes one
// irreducible factor the same way wherever it finds it, so that (q^2 sqrt(q) -> q^(5/2)) its
// powers merge; factored() returns a sum shown irreducible as given, which may be -q or q
// expanded elsewhere. A product where that could matter (one sum in two places) goes to factor().
ex factored_product(const ex& p) {
  ex result = 1;
  std::vector<ex> sums;
  for_each_factor(p, [&](const ex& base, const ex& exponent) {
    const ex factors = factored(base);
    for_each_factor(factors, [&](const ex& factor, const ex&) {
      if (GiNaC::is_a<GiNaC::add>(factor)) sums.push_back(GiNaC::expand(factor));
    });
    result *= power_of_factors(factors, exponent);
  });
  return shares_a_sum(sums) ? factor_keeping_roots(p) : result;
}

// The square root of a term c x^2k y^2l ... (c > 0 a rational square): sqrt(c) x^k y^l ...
std::optional<ex> monomial_root(const ex& term) {
  ex root = 1;
  bool ok = true;
  for_each_factor(term, [&](const ex& base, const ex& exponent) {
    if (GiNaC::is_a<GiNaC::numeric>(base) && exponent.is_equal(1)) {
      const ex r = GiNaC::sqrt(base);  // exact where base is a rational square
      ok = ok && GiNaC::ex_to<GiNaC::numeric>(base).is_positive() &&
           GiNaC::is_a<GiNaC::numeric>(r) && GiNaC::ex_to<GiNaC::numeric>(r).is_rational();
      if (ok) root *= r;
    } else if (GiNaC::is_a<GiNaC::symbol>(base) && exponent.info(GiNaC::info_flags::even) &&
               exponent.info(GiNaC::info_flags::positive)) {
      root *= GiNaC::pow(base, exponent / 2);
    } else {
      ok = false;
    }
  });
  return ok ? std::optional<ex>(root) : std::nullopt;
}

// q = u^2 - v^2 (u, v monomials): the difference of two squares, u - v and u + v. With the
// content out, u and v share no symbol, so the two are coprime and factor() would find the
// same factors (up to sign), slowly: a^2 - b^2 took 0.25 ms, b^4 - a^2 c^2 1 ms.
std::optional<std::pair<ex, ex>> difference_of_squares(const ex& q) {
  if (!GiNaC::is_a<GiNaC::add>(q) || q.nops() != 2) return std::nullopt;
  for (std::size_t i = 0; i < 2; ++i) {
    const auto u = monomial_root(q.op(i)), v = monomial_root(-q.op(1 - i));
    if (u && v) return std::make_pair(*u, *v);
  }
  return std::nullopt;
}

ex factored_once(const ex& p) {
  if (GiNaC::is_a<GiNaC::mul>(p) || GiNaC::is_a<GiNaC::power>(p)) return factored_product(p);
  if (!is_polynomial_sum(p)) return factor_keeping_roots(p);
  const auto [content, q] = split_content(p);
  // First, as it is cheap and never applies to an irreducible q (u and v are not both numbers).
  if (const auto uv = difference_of_squares(q)) {
    return content * factored(uv->first - uv->second) * factored(uv->first + uv->second);
  }
  // content * q is what factor() gives when q is irreducible (for content 1, p itself).
  return shown_irreducible(q) ? content * q : factor_expanded(p);
}
}  // namespace

ex factored(const ex& p) {
  // The same polynomial is factored again and again: 9 ms of a keys check.
  thread_local Memo<ex> known;
  return known.get(p, [&] { return factored_once(p); });
}

std::pair<ex, ex> sums_divided_out(const ex& numerator, const ex& denominator) {
  ex left = numerator, below = 1;
  for_each_factor(factored(denominator), [&](const ex& base, const ex& exponent) {
    int times = GiNaC::ex_to<GiNaC::numeric>(exponent).to_int();  // a polynomial's: 1, 2, ..
    ex quotient;
    while (times > 0 && GiNaC::is_a<GiNaC::add>(base) && GiNaC::divide(left, base, quotient)) {
      left = quotient;
      --times;
    }
    below *= GiNaC::pow(base, times);
  });
  return {GiNaC::expand(left), below};
}

}  // namespace wobble::sym
