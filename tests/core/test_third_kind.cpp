// The elliptic integral of the third kind for n < -1 by A&S 17.7.15 (core/elliptic.hpp,
// negative_third_kind), against Boost.Math's ellint_3 at 50 digits.
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "core/double_double.hpp"
#include "core/elliptic.hpp"
#include "double_double_error.hpp"

using namespace wobble;
using mp = wobble::testing::mp50;
using wobble::testing::error_in_u;

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();

// The moduli (k'^2 down to near the separatrix) and characteristics (n- of tops that swing
// nearer and nearer to hanging down) the grid runs over.
constexpr double kKc2s[] = {0.9, 0.5, 1e-4, 1e-12};
constexpr double kNs[] = {-1.5, -40.0, -1e4, -1e8};

mp pi_50(double kc2, double n, const mp& phi) {
  return boost::math::ellint_3(sqrt(1 - mp(kc2)), mp(n), phi);
}

NegativeThirdKind form_of(double n, double kc2) {
  // 1 - n and k^2 = 1 - k'^2 are exact in double-double: the caller's complements, exactly.
  return negative_third_kind(DoubleDouble(n), DoubleDouble(1.0) - DoubleDouble(n),
                             DoubleDouble(1.0) - DoubleDouble(kc2), DoubleDouble(kc2));
}
}  // namespace

TEST_CASE("Pi(n; phi) for n < -1 by A&S 17.7.15 within 8 eps of 50 digits, where F + n G is not") {
  double worst_untransformed = 0.0;
  for (const double kc2 : kKc2s) {
    for (const double n : kNs) {
      const NegativeThirdKind form = form_of(n, kc2);
      for (const double phi : {0.3, 1.0, 1.5, 1.5707, -1.2}) {
        const double sn = std::sin(phi), cn = std::cos(phi);
        const SnCnDn of_r{sn, cn, std::sqrt(cn * cn + kc2 * sn * sn)};
        const double F = incomplete_F(sn, cn, kc2);
        const double got = form.linear.value() * F +
                           form.excess_coef.value() * third_kind_excess(sn, cn, kc2, form.N.value(),
                                                                        form.one_minus_N.value()) +
                           form.atan_coef.value() * negative_third_kind_atan(form.atan_p, of_r);
        // phi rounded to double is the angle both sides take.
        const mp want = pi_50(kc2, n, mp(phi));
        const auto error_in_eps = [&](double x) {
          return static_cast<double>(abs(mp(x) - want) / abs(want)) / kEps;
        };
        const double error = error_in_eps(got);
        INFO("k'^2 = " << kc2 << ", n = " << n << ", phi = " << phi << ": " << error << " eps");
        // The three terms have Pi's sign (A, B, C, N > 0; F, G_N and the arctangent odd in phi),
        // so none cancels: each within a few eps of itself (Carlson's R_F and R_J about 2 eps,
        // the coefficients' rounding to double 1, the products and sums 1 each) is within as
        // many of Pi. 8 eps.
        CHECK(error <= 8.0);
        const double untransformed =
            F + n * third_kind_excess(sn, cn, kc2, n, static_cast<double>(1 - mp(n)));
        worst_untransformed = std::max(worst_untransformed, error_in_eps(untransformed));
      }
    }
  }
  // The grid reaches the cancellation the transformation avoids: Pi = F + n G with n G's rounding
  // eps K against Pi ~ pi / (2 sqrt(-n)) is some 1e4 eps at n = -1e8.
  INFO("F + n G: " << worst_untransformed << " eps at worst");
  REQUIRE(worst_untransformed > 100 * 8.0);
}

TEST_CASE("the complete Pi(n) for n < -1 by A&S 17.7.15 in double-double against 50 digits") {
  // At phi = pi/2 the arctangent is 0: Pi(n) = linear K + excess_coef (Pi(N) - K) / N, the sum a
  // heavy top's minus term grows by every half period.
  for (const double kc2 : kKc2s) {
    for (const double n : kNs) {
      const NegativeThirdKind form = form_of(n, kc2);
      const DoubleDouble got =
          form.linear * complete_K_dd(DoubleDouble(kc2)) +
          form.excess_coef * complete_third_kind_excess_dd(DoubleDouble(kc2), form.one_minus_N);
      const mp want = pi_50(kc2, n, boost::math::constants::half_pi<mp>());
      const double error_u = error_in_u(got, want);
      INFO("k'^2 = " << kc2 << ", n = " << n << ": " << error_u << " u (2^-104)");
      // K and the excess within 64 u each (test_double_double.cpp); both terms positive, so the
      // sum is within the larger; the coefficients' few products and quotients 4 u each: 80 u.
      CHECK(error_u <= 80.0);
    }
  }
}

TEST_CASE("the transformed arctangent takes r rounded past K as reflected there") {
  // At r = K + a rounding, cn = -1e-17: G_N (of cn^2) takes that as r = K - the rounding, and
  // the arctangent must as well; its sign flipped would break Pi by C p 2e-17 / dn.
  const double p = 3.0, kc2 = 1e-4, sn = 1.0, dn = std::sqrt(kc2);
  for (const double cn : {1e-17, 1e-9, 0.25}) {
    INFO("cn = " << cn);
    const double before = negative_third_kind_atan(p, SnCnDn{sn, cn, dn});
    REQUIRE(before > 0.0);
    REQUIRE(negative_third_kind_atan(p, SnCnDn{sn, -cn, dn}) == before);
  }
}
