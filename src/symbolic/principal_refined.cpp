#include "symbolic/principal_refined.hpp"

#include <algorithm>
#include <stdexcept>

#include "symbolic/expression.hpp"

namespace wobble::sym {

namespace {
using GiNaC::numeric;

constexpr long kDigits = 60;
constexpr int kMaxSweeps = 60;  // cyclic Jacobi converges quadratically: ~6 sweeps for 60 digits
}  // namespace

RefinedPrincipal refined_principal(const GiNaC::matrix& I, const GiNaC::lst& at) {
  const DigitsGuard guard(kDigits);
  std::array<std::array<numeric, 3>, 3> a, v;
  numeric norm2 = 0;
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) {
      const GiNaC::ex e = GiNaC::evalf(I(i, j).subs(at));
      if (!GiNaC::is_a<numeric>(e) || !GiNaC::ex_to<numeric>(e).is_real()) {
        throw std::invalid_argument("refined_principal: tensor entry is not a real number");
      }
      a[i][j] = GiNaC::ex_to<numeric>(e);
      v[i][j] = i == j ? 1 : 0;
      norm2 += a[i][j] * a[i][j];
    }
  }
  // Off-diagonal mass below 10^-(2 kDigits) of the whole: diagonal to the working precision.
  const numeric negligible = norm2 * numeric(10).power(numeric(-2 * kDigits));
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    numeric off = 0;
    for (unsigned p = 0; p < 3; ++p)
      for (unsigned q = p + 1; q < 3; ++q) off += a[p][q] * a[p][q];
    if (off <= negligible) break;
    for (unsigned p = 0; p < 3; ++p) {
      for (unsigned q = p + 1; q < 3; ++q) {
        if (a[p][q].is_zero()) continue;
        // The rotation in the p-q plane that zeroes a[p][q] (Golub and Van Loan, 8.5.2).
        const numeric theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const numeric t = (theta.is_negative() ? numeric(-1) : numeric(1)) /
                          (GiNaC::abs(theta) + GiNaC::sqrt(theta * theta + 1));
        const numeric c = 1 / GiNaC::sqrt(t * t + 1), s = t * c;
        for (unsigned k = 0; k < 3; ++k) {  // A <- A J (columns p, q)
          const numeric akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (unsigned k = 0; k < 3; ++k) {  // A <- J^T A (rows p, q)
          const numeric apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (unsigned k = 0; k < 3; ++k) {  // V <- V J
          const numeric vkp = v[k][p], vkq = v[k][q];
          v[k][p] = c * vkp - s * vkq;
          v[k][q] = s * vkp + c * vkq;
        }
      }
    }
  }
  std::array<unsigned, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](unsigned x, unsigned y) { return a[x][x] < a[y][y]; });
  RefinedPrincipal out;
  for (unsigned c = 0; c < 3; ++c) {
    const unsigned k = order[c];
    out.moments[c] = a[k][k].to_double();
    for (unsigned r = 0; r < 3; ++r) out.axes(r, c) = v[r][k].to_double();
  }
  return out;
}

}  // namespace wobble::sym
