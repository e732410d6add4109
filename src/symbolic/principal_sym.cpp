#include "symbolic/principal_sym.hpp"

#include <array>
#include <cmath>

#include "symbolic/expression.hpp"
#include "symbolic/factored.hpp"

namespace wobble::sym {

namespace {
using GiNaC::ex;

// Index pairs of the products of inertia that are not identically zero.
std::vector<std::pair<int, int>> nonzero_products(const GiNaC::matrix& I) {
  std::vector<std::pair<int, int>> out;
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = i + 1; j < 3; ++j) {
      if (!is_identically_zero(I(i, j))) out.emplace_back(static_cast<int>(i), static_cast<int>(j));
    }
  }
  return out;
}

// True if e has a power with an exponent that is not an integer (a root) anywhere.
bool has_root(const ex& e) {
  if (GiNaC::is_a<GiNaC::power>(e) && !e.op(1).info(GiNaC::info_flags::integer)) return true;
  for (std::size_t i = 0; i < e.nops(); ++i) {
    if (has_root(e.op(i))) return true;
  }
  return false;
}

// mean - offset and mean + offset, where offset is a root's term: each one fraction where the
// root came out whole (a square, as the y-z block's with I_yy = I_zz: m a^2 (pi^2 + 36)/9, not
// m a^2 (pi^2 + 45)/9 - m a^2, which GiNaC combines by itself only where the mean is a number
// times the same monomial).
std::array<ex, 2> mean_minus_plus(const ex& mean, const ex& offset) {
  if (has_root(offset)) return {mean - offset, mean + offset};
  return {simplify(mean - offset), simplify(mean + offset)};
}

// The block's moments mean -+ root; where the root stays a root, over their one denominator,
// (P -+ sqrt(Q))/(2 D), as books write them: the sum of two fractions with a common denominator
// printed -(P'/(2 D) + sqrt(Q)/(2 D)) where the mean's numerator came negated (the three-atom
// molecule's moments about its centre).
std::array<ex, 2> block_moments(const ex& mean, const ex& root) {
  if (!has_root(root)) return mean_minus_plus(mean, root);
  const ex nd_mean = GiNaC::numer_denom(mean), nd_root = GiNaC::numer_denom(root);
  const ex d = GiNaC::expand(nd_mean.op(1)), d_root = GiNaC::expand(nd_root.op(1));
  // numer_denom() gives each denominator up to a sign, as GiNaC's term order fell in this run.
  ex over_d = nd_root.op(0);  // the root's numerator over the mean's denominator d
  if (d_root.is_equal(-d)) {
    over_d = -over_d;
  } else if (!d_root.is_equal(d)) {
    return {mean - root, mean + root};
  }
  return {GiNaC::expand(nd_mean.op(0) - over_d) / d, GiNaC::expand(nd_mean.op(0) + over_d) / d};
}

// Roots of the factored polynomial in lambda, if every factor has degree <= 2.
std::optional<std::vector<ex>> roots_of(const ex& factored, const GiNaC::symbol& lambda) {
  std::vector<ex> roots;
  auto solve_factor = [&](const ex& f, int multiplicity) {
    const int degree = f.degree(lambda);
    if (degree == 0) return true;
    if (degree > 2) return false;
    std::vector<ex> r;
    if (degree == 1) {
      r.push_back(simplify(-f.coeff(lambda, 0) / f.coeff(lambda, 1)));
    } else {
      const ex a = f.coeff(lambda, 2), b = f.coeff(lambda, 1), c = f.coeff(lambda, 0);
      const ex root = simplified_sqrt(simplify(b * b - 4 * a * c));
      const auto [minus, plus] = mean_minus_plus(simplify(-b / (2 * a)), root / (2 * a));
      r.push_back(minus);
      r.push_back(plus);
    }
    for (int k = 0; k < multiplicity; ++k) roots.insert(roots.end(), r.begin(), r.end());
    return true;
  };
  auto solve_power_or_factor = [&](const ex& f) {
    if (GiNaC::is_a<GiNaC::power>(f) && f.op(1).info(GiNaC::info_flags::posint)) {
      return solve_factor(f.op(0), GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int());
    }
    return solve_factor(f, 1);
  };
  if (GiNaC::is_a<GiNaC::mul>(factored)) {
    for (std::size_t i = 0; i < factored.nops(); ++i) {
      if (!solve_power_or_factor(factored.op(i))) return std::nullopt;
    }
  } else if (!solve_power_or_factor(factored)) {
    return std::nullopt;
  }
  if (roots.size() != 3) return std::nullopt;
  return roots;
}

SymVec3 unit(int k) {
  SymVec3 v{0, 0, 0};
  v[static_cast<std::size_t>(k)] = 1;
  return v;
}

SymVec3 cross(const SymVec3& a, const SymVec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
}  // namespace

namespace {
void count_nodes(const ex& e, int& n) {
  if (++n > kMaxClosedFormNodes) return;
  for (std::size_t i = 0; i < e.nops() && n <= kMaxClosedFormNodes; ++i) count_nodes(e.op(i), n);
}
}  // namespace

int tensor_nodes(const GiNaC::matrix& I) {
  int n = 0;
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = i; j < 3; ++j) count_nodes(I(i, j), n);
  }
  return std::min(n, kMaxClosedFormNodes + 1);
}

SymPrincipal principal_closed_form(const GiNaC::matrix& I, const GiNaC::symbol& lambda) {
  SymPrincipal out;
  out.tensor_nodes = tensor_nodes(I);
  if (out.tensor_nodes > kMaxClosedFormNodes) {
    out.too_large = true;
    return out;
  }
  GiNaC::matrix shifted(3, 3);
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) shifted(i, j) = (i == j ? ex(lambda) : ex(0)) - I(i, j);
  }
  const auto products = nonzero_products(I);
  // The characteristic polynomial in the form its structure gives (a product of diagonal
  // factors, or a linear factor times the block's quadratic); expanded and factored otherwise.
  if (products.empty()) {
    out.characteristic = (lambda - I(0, 0)) * (lambda - I(1, 1)) * (lambda - I(2, 2));
  } else if (products.size() == 1) {
    const auto p = static_cast<unsigned>(products[0].first),
               q = static_cast<unsigned>(products[0].second);
    const unsigned k = 3 - p - q;
    const ex quadratic = GiNaC::pow(lambda, 2) - simplify(I(p, p) + I(q, q)) * lambda +
                         simplify(I(p, p) * I(q, q) - I(p, q) * I(p, q));
    // Keep the quadratic's linear factors where it splits over the rationals (four-masses).
    const ex split = factored(GiNaC::expand(quadratic));
    const bool splits = GiNaC::is_a<GiNaC::mul>(split) || GiNaC::is_a<GiNaC::power>(split);
    out.characteristic = (lambda - I(k, k)) * (splits ? split : quadratic);
  } else {
    const ex poly = GiNaC::expand(shifted.determinant());
    out.characteristic = factored(poly);
    if (!GiNaC::is_a<GiNaC::mul>(out.characteristic) &&
        !GiNaC::is_a<GiNaC::power>(out.characteristic)) {
      // No factors: write it as a polynomial in lambda with simplified coefficients.
      ex collected = 0;
      for (int k = poly.ldegree(lambda); k <= poly.degree(lambda); ++k) {
        collected += simplify(poly.coeff(lambda, k)) * GiNaC::pow(lambda, k);
      }
      out.characteristic = collected;
    }
  }

  if (products.empty()) {
    out.method = SymPrincipal::Method::diagonal;
    for (unsigned i = 0; i < 3; ++i) out.moments.push_back(I(i, i));
    return out;
  }
  if (products.size() == 1) {
    out.method = SymPrincipal::Method::block;
    out.block_p = products[0].first;
    out.block_q = products[0].second;
    out.block_k = 3 - out.block_p - out.block_q;
    const auto p = static_cast<unsigned>(out.block_p), q = static_cast<unsigned>(out.block_q);
    const ex A = I(p, p), B = I(q, q), C = I(p, q);
    const ex mean = simplify((A + B) / 2);
    const ex root = simplified_sqrt(simplify(GiNaC::pow((A - B) / 2, 2) + C * C));
    const auto [minus, plus] = block_moments(mean, root);
    out.moments = {I(static_cast<unsigned>(out.block_k), static_cast<unsigned>(out.block_k)), minus,
                   plus};
    out.block_angle = GiNaC::atan2(simplify(2 * C), simplify(A - B)) / 2;
    return out;
  }
  if (auto roots = roots_of(out.characteristic, lambda)) {
    out.method = SymPrincipal::Method::factored;
    out.moments = *roots;
  }
  return out;
}

std::optional<SymVec3> principal_axis_closed_form(const GiNaC::matrix& I, const SymPrincipal& p,
                                                  std::size_t index, const GiNaC::lst& at) {
  using M = SymPrincipal::Method;
  if (p.method == M::numeric || index >= p.moments.size()) return std::nullopt;
  const ex& value = p.moments[index];
  for (std::size_t j = 0; j < p.moments.size(); ++j) {
    if (j != index && is_identically_zero(p.moments[j] - value)) return std::nullopt;
  }
  if (p.method == M::diagonal) return unit(static_cast<int>(index));
  if (p.method == M::block) {
    if (index == 0) return unit(p.block_k);
    SymVec3 v{0, 0, 0};
    const ex c = GiNaC::cos(p.block_angle), s = GiNaC::sin(p.block_angle);
    const auto bp = static_cast<std::size_t>(p.block_p), bq = static_cast<std::size_t>(p.block_q);
    if (index == 2) {  // the larger root: (cos theta, sin theta) in the p-q plane
      v[bp] = c;
      v[bq] = s;
    } else {
      v[bp] = -s;
      v[bq] = c;
    }
    return v;
  }
  // Factored: cross product of the two rows of I - lambda 1 that are most independent at `at`.
  std::array<SymVec3, 3> rows;
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) rows[i][j] = I(i, j) - (i == j ? value : ex(0));
  }
  SymVec3 best{0, 0, 0};
  double best_norm = -1.0;
  for (std::size_t a = 0; a < 3; ++a) {
    for (std::size_t b = a + 1; b < 3; ++b) {
      SymVec3 c = cross(rows[a], rows[b]);
      for (auto& e : c) e = simplify(e);
      double norm = 0.0;
      for (const auto& e : c) {
        const double x = evaluate(e, at, "principal axis");
        norm += x * x;
      }
      if (norm > best_norm) {
        best_norm = norm;
        best = c;
      }
    }
  }
  const ex length =
      simplified_sqrt(simplify(best[0] * best[0] + best[1] * best[1] + best[2] * best[2]));
  for (auto& e : best) e = simplify(e / length);
  return best;
}

}  // namespace wobble::sym
