#include "core/elliptic.hpp"

#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <cmath>

namespace wobble {

namespace {
// Boost.Math promotes double to long double by default, several times slower for no accuracy
// wobble can print; the Carlson integrals are accurate to a few eps in double.
using Fast = boost::math::policies::policy<boost::math::policies::promote_double<false>>;
}  // namespace

SnCnDn jacobi_sncndn(double u, double kc2) {
  if (kc2 == 0.0) {
    const double sech = 1.0 / std::cosh(u);
    return {std::tanh(u), sech, sech};
  }
  // Bulirsch's algorithm (Numer. Math. 7, 1965), as in Numerical Recipes' sncndn.
  constexpr double kTol = 1e-8;  // sqrt(eps): the AGM converges quadratically past it
  double em[16], en[16];
  double a = 1.0, c = 1.0, emc = kc2, dn = 1.0;
  int l = 0;
  for (int i = 0; i < 16; ++i) {
    l = i;
    em[i] = a;
    emc = std::sqrt(emc);
    en[i] = emc;
    c = 0.5 * (a + emc);
    if (std::abs(a - emc) <= kTol * a) break;
    emc *= a;
    a = c;
  }
  const double v = u * c;
  double sn = std::sin(v), cn = std::cos(v);
  if (sn != 0.0) {
    a = cn / sn;
    c *= a;
    for (int ii = l; ii >= 0; --ii) {
      const double b = em[ii];
      a *= c;
      c *= dn;
      dn = (en[ii] + a) / (b + a);
      a = c / b;
    }
    a = 1.0 / std::sqrt(c * c + 1.0);
    sn = sn >= 0.0 ? a : -a;
    cn = c * sn;
  }
  return {sn, cn, dn};
}

double complete_K(double kc2) {
  return boost::math::ellint_rf(0.0, kc2, 1.0, Fast());
}

double incomplete_F(double s, double c, double kc2) {
  const double c2 = c * c;
  return s * boost::math::ellint_rf(c2, c2 + kc2 * s * s, 1.0, Fast());
}

double third_kind_excess(double s, double c, double kc2, double n) {
  return third_kind_excess(s, c, kc2, n, 1.0 - n);
}

double third_kind_excess(double s, double c, double kc2, double n, double one_minus_n) {
  if (s == 0.0) return 0.0;
  const double c2 = c * c, s2 = s * s;
  // 1 - n sin^2: for n > 0 as (1 - n) + n cos^2, which keeps its digits where n sin^2 is near 1;
  // for n <= 0 as it is, a sum of terms >= 0 (the other form would cancel for large -n).
  const double p = n > 0.0 ? one_minus_n + n * c2 : 1.0 - n * s2;
  return s * s2 * boost::math::ellint_rj(c2, c2 + kc2 * s2, 1.0, p, Fast()) / 3.0;
}

double complete_third_kind_excess(double kc2, double n) {
  return boost::math::ellint_rj(0.0, kc2, 1.0, 1.0 - n, Fast()) / 3.0;
}

ReducedArgument reduce_by_half_period(double u, double K, double kc2) {
  ReducedArgument a;
  a.r = u;
  if (std::isfinite(K)) {
    a.j = std::nearbyint(u / (2.0 * K));
    a.r = u - 2.0 * K * a.j;
    // The quotient's rounding can leave r just past +-K: step it back (see the overload below).
    if (a.r > K) {
      a.r -= 2.0 * K;
      a.j += 1.0;
    } else if (a.r < -K) {
      a.r += 2.0 * K;
      a.j -= 1.0;
    }
  }
  a.of_r = jacobi_sncndn(a.r, kc2);
  return a;
}

ReducedArgument reduce_by_half_period(const DoubleDouble& u, const DoubleDouble& K, double kc2) {
  ReducedArgument a;
  const DoubleDouble two_K(2.0 * K.hi, 2.0 * K.lo);
  a.j = std::nearbyint(u.hi / two_K.hi);
  // j 2K exactly to double-double: j is an integer below 2^53, so j * 2K.hi by two_prod.
  DoubleDouble r = u - (two_prod(a.j, two_K.hi) + DoubleDouble(a.j * two_K.lo));
  // j is the rounded quotient of the high parts, off by up to an ulp of u / 2K: r can land past
  // +-K by that much times 2K (6e-10 after a million half periods). The integrals of r
  // (Pi(n; am r), the heavy top's arctangent) read past K as mirrored back inside: the free
  // body's attitude was 1e7 eps off at such a time, a million periods on. Step r back into
  // [-K, K].
  if ((r - K).hi > 0.0) {
    r = r - two_K;
    a.j += 1.0;
  } else if ((r + K).hi < 0.0) {
    r = r + two_K;
    a.j -= 1.0;
  }
  a.r = r.value();
  // Near +-K, r = +-(K - s): r in double is off by up to eps K / 2, and cn(r), about k' s, by
  // that much, a relative error eps K / s, where the integrals of r take 1 - n sn^2 with n
  // near 1 (a top passing 2.4e-6 rad from upright: 1 - n+ = 1e-12, and psi, with the
  // momentum, was off by 3e5 eps there). cn from s, formed in double-double: k' sd(s) keeps
  // its relative digits. sn and dn are flat at K, r's rounding moves them by next to nothing,
  // and from s (cd(s) = cn(s) / dn(s), two numbers near sech s for k near 1) sn was 2 eps off.
  a.of_r = jacobi_sncndn(a.r, kc2);
  if (std::abs(a.r) > 0.5 * K.hi) {
    const SnCnDn of_s = jacobi_sncndn((r.hi < 0.0 ? K + r : K - r).value(), kc2);
    a.of_r.cn = std::sqrt(kc2) * of_s.sn / of_s.dn;
  }
  return a;
}

DoubleDouble complete_K_dd(const DoubleDouble& kc2) {
  DoubleDouble a(1.0), b = sqrt(kc2);
  // Quadratic convergence: from b = 1e-8 (k'^2 = 1e-16) about 10 steps reach 2^-104; the
  // bound only guards against a loop that would not end.
  constexpr int kMaxSteps = 64;
  for (int i = 0; i < kMaxSteps && std::abs((a - b).hi) > 0x1p-104 * a.hi; ++i) {
    const DoubleDouble mean = DoubleDouble(0.5) * (a + b);
    b = sqrt(a * b);
    a = mean;
  }
  return dd_pi() / (DoubleDouble(2.0) * a);
}

DoubleDouble complete_third_kind_excess_dd(const DoubleDouble& kc2,
                                           const DoubleDouble& one_minus_n) {
  // cel(kc, p, a, b) = int_0^(pi/2) (a cos^2 + b sin^2) / ((cos^2 + p sin^2)
  // sqrt(cos^2 + kc^2 sin^2)) dphi; with p = 1 - n, a = 0, b = 1 it is (Pi(n) - K) / n.
  using DD = DoubleDouble;
  DD p = one_minus_n, qc = sqrt(kc2), a(0.0), b(1.0), e = qc, em(1.0);
  p = sqrt(p);
  b = b / p;
  // Each step squares the relative gap |g - qc| / g; once below 2^-53 the next would be
  // below 2^-106: the sum is complete. The bound guards against a loop that would not end.
  constexpr int kMaxSteps = 64;
  for (int i = 0; i < kMaxSteps; ++i) {
    const DD f = a;
    a = a + b / p;
    DD g = e / p;
    b = b + f * g;
    b = b + b;
    p = g + p;
    g = em;
    em = em + qc;
    if (std::abs((g - qc).hi) <= 0x1p-53 * g.hi) break;
    qc = sqrt(e);
    qc = qc + qc;
    e = qc * em;
  }
  return DD(0.5) * dd_pi() * (b + a * em) / (em * (em + p));
}

NegativeThirdKind negative_third_kind(const DoubleDouble& n, const DoubleDouble& one_minus_n,
                                      const DoubleDouble& k2, const DoubleDouble& kc2) {
  using DD = DoubleDouble;
  const DD minus_n = -n, k2_minus_n = k2 + minus_n;  // sums of positive terms
  NegativeThirdKind t;
  t.N = k2_minus_n / one_minus_n;
  t.one_minus_N = kc2 / one_minus_n;
  const DD A = minus_n * kc2 / (one_minus_n * k2_minus_n), B = k2 / k2_minus_n;
  t.linear = A + B;
  t.excess_coef = A * t.N;
  t.atan_coef = sqrt(minus_n / (one_minus_n * k2_minus_n));
  t.atan_p = sqrt(minus_n * t.N).value();
  return t;
}

double negative_third_kind_atan(double atan_p, const SnCnDn& of_r) {
  const double cn_over_dn = of_r.dn > 0.0 ? std::abs(of_r.cn) / of_r.dn : 1.0;
  return std::atan(atan_p * of_r.sn * cn_over_dn);
}

double third_kind_excess(const ReducedArgument& a, double kc2, double n, double complete) {
  return 2.0 * a.j * complete + third_kind_excess(a.of_r.sn, a.of_r.cn, kc2, n);
}

}  // namespace wobble
