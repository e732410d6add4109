// Double-double arithmetic (core/double_double.hpp) and the complete integral K to
// double-double (core/elliptic.hpp), against Boost.Multiprecision at 50 digits.
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "core/double_double.hpp"
#include "core/elliptic.hpp"
#include "double_double_error.hpp"

using namespace wobble;
using Catch::Matchers::WithinAbs;
using mp = wobble::testing::mp50;
using wobble::testing::error_in_u;
using wobble::testing::exact;

TEST_CASE("two_sum and two_prod are exact") {
  for (const auto& [a, b] : {std::pair{0.1, 0.7}, std::pair{1e16, 1.0 + 0x1p-52},
                             std::pair{-3.0, 1.0 / 3.0}, std::pair{M_PI, M_E * 1e-20}}) {
    REQUIRE(exact(two_sum(a, b)) == mp(a) + mp(b));
    REQUIRE(exact(two_prod(a, b)) == mp(a) * mp(b));
  }
}

TEST_CASE("double-double +, *, / and sqrt within a few 2^-104 of 50 digits") {
  const DoubleDouble x = two_prod(M_PI, 1.0 / 3.0), y = two_sum(M_E, 1e-17), z = two_prod(7.0, 0.1);
  const mp X = exact(x), Y = exact(y), Z = exact(z);
  // Bounds: the QD library's, 2 u for + and *, 4 u for / and sqrt (u = 2^-104), doubled.
  CHECK(error_in_u(x + y, X + Y) <= 4.0);
  CHECK(error_in_u(x - z, X - Z) <= 4.0);
  CHECK(error_in_u(x * y, X * Y) <= 4.0);
  CHECK(error_in_u(x / y, X / Y) <= 8.0);
  CHECK(error_in_u(sqrt(y), sqrt(Y)) <= 8.0);
  CHECK(error_in_u(dd_pi(), boost::math::constants::pi<mp>()) <= 1.0);
  // Not merely double: the low word carries digits a double would have lost.
  REQUIRE(std::abs(static_cast<double>((exact(x * y) - X * Y) / (X * Y))) <
          std::numeric_limits<double>::epsilon() / 1e6);
}

TEST_CASE("K by the AGM in double-double, from k'^2 = 1 to 1e-16, against 50 digits") {
  for (const double kc2 : {1.0, 0.5, 0.1, 1e-4, 1e-8, 1e-12, 1e-16}) {
    const mp k = sqrt(1 - mp(kc2));
    const mp want = boost::math::ellint_1(k);
    const double e = error_in_u(complete_K_dd(DoubleDouble(kc2)), want);
    INFO("k'^2 = " << kc2 << ": " << e << " u");
    // Some ten AGM steps, each a few u, and the final division: 64 u, far below a double's
    // 2^52 u.
    REQUIRE(e <= 64.0);
    // The double K agrees with it to a double's rounding.
    REQUIRE_THAT(complete_K(kc2),
                 WithinAbs(static_cast<double>(want),
                           8 * std::numeric_limits<double>::epsilon() * static_cast<double>(want)));
  }
}

TEST_CASE("reduction by 2K keeps r in [-K, K] at the end of a half period, a million periods on") {
  // u = (2j + 1) K + delta: the quotient of the high parts, u / 2K, rounds to j + 1/2 exactly
  // for |delta| below 2K ulp(j) / 2 (2e-10 at j = 1e6), and the nearest integer, ties to even,
  // picked j whichever side delta was on: r = K + delta, past K. The integrals of r read it
  // mirrored back inside, a jump of 2 delta G'(K) in a precession angle.
  const double kc2 = 0.5;
  const DoubleDouble K = complete_K_dd(DoubleDouble(kc2));
  for (const double j : {0.0, 1e6, 1e6 + 1, -1e6 - 1}) {
    for (const double delta : {1e-12, -1e-12, 1e-15, -1e-15}) {
      INFO("j = " << j << ", delta = " << delta);
      const DoubleDouble u = DoubleDouble(2.0 * j + 1.0) * K + DoubleDouble(delta);
      const ReducedArgument a = reduce_by_half_period(u, K, kc2);
      // r within [-K, K] up to its own rounding to double, u = r + 2 K j.
      REQUIRE(std::abs(a.r) <= K.hi * (1 + std::numeric_limits<double>::epsilon()));
      const mp rest = exact(u) - 2 * mp(a.j) * exact(K);
      REQUIRE_THAT(
          a.r, WithinAbs(static_cast<double>(rest), std::numeric_limits<double>::epsilon() * K.hi));
      // The side delta puts u on: past the end (delta > 0) is the next half period's start.
      REQUIRE(a.j == (delta > 0 ? j + 1 : j));
      // cn(r) = k' sd(K - |r|) = k' (K - |r|) (1 + O(delta^2)), to its relative digits but for
      // the double-double rounding of r itself, a few 2^-104 |u| (K - |r| from u as stored, whose
      // low word rounds delta): from r in double, off by up to eps K / 2, cn had been 1e-4 off at
      // delta = 1e-12 and 0.4 at 1e-15.
      const mp s = exact(K) - abs(rest);
      const double cn = static_cast<double>(sqrt(mp(kc2)) * s);
      const double bound = 4 * std::numeric_limits<double>::epsilon() * cn +
                           std::sqrt(kc2) * 8 * 0x1p-104 * std::abs(u.hi);
      REQUIRE_THAT(a.of_r.cn, WithinAbs(cn, bound));
    }
  }
}

TEST_CASE("the complete third-kind excess in double-double (Bulirsch's cel) against 50 digits") {
  for (const double kc2 : {0.9, 0.5, 1e-4, 1e-10, 1e-16}) {
    for (const double n : {-0.5, -3.0, -40.0, 0.3}) {
      // (Pi(n | k) - K(k)) / n = R_J(0, k'^2, 1, 1 - n) / 3 (Carlson), Boost.Math at 50 digits.
      const mp want = boost::math::ellint_rj(mp(0), mp(kc2), mp(1), 1 - mp(n)) / 3;
      const double e = error_in_u(
          complete_third_kind_excess_dd(DoubleDouble(kc2), DoubleDouble(1.0) - DoubleDouble(n)),
          want);
      INFO("k'^2 = " << kc2 << ", n = " << n << ": " << e << " u");
      REQUIRE(e <= 64.0);  // as K's: a dozen steps of a few u each
      // And the double routine agrees to a double's rounding.
      REQUIRE_THAT(complete_third_kind_excess(kc2, n),
                   WithinAbs(static_cast<double>(want), 8 * std::numeric_limits<double>::epsilon() *
                                                            static_cast<double>(want)));
    }
  }
}

TEST_CASE("the complete third-kind excess in double-double with n within 1e-16 to 1e-32 of 1") {
  // A top released near upright has n+ and k^2 both within ~theta0^2 of 1: 1 - n then comes
  // from its caller, as a quotient of distances to the pole, since formed from n it would keep
  // no digit (the double-double n's own rounding is 1e-32). Given 1 - n exactly, the excess
  // (~1 / (1 - n) there) keeps double-double's accuracy.
  for (const double kc2 : {1e-16, 1e-24, 1e-32}) {
    for (const double one_minus_n : {1e-16, 3e-25, 1e-32}) {
      const mp want = boost::math::ellint_rj(mp(0), mp(kc2), mp(1), mp(one_minus_n)) / 3;
      const double e = error_in_u(
          complete_third_kind_excess_dd(DoubleDouble(kc2), DoubleDouble(one_minus_n)), want);
      INFO("k'^2 = " << kc2 << ", 1 - n = " << one_minus_n << ": " << e << " u");
      REQUIRE(e <= 64.0);  // as above
    }
  }
}
