// The exact number a parameter's double stands for: r * pi for the double nearest r * pi
// (denominator up to 720), the shortest decimal otherwise.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "symbolic/expression.hpp"

using wobble::sym::exact_value;

namespace {
// The double nearest num/den * pi, as a parameter "104.5deg" or "pi/6" arrives.
double times_pi(long num, long den) {
  return static_cast<double>(static_cast<long double>(num) / den * std::numbers::pi_v<long double>);
}

bool is_pi_times(const GiNaC::ex& e, long num, long den) {
  return e.is_equal(GiNaC::numeric(num, den) * GiNaC::Pi);
}
}  // namespace

TEST_CASE("a double nearest a rational multiple of pi is that multiple") {
  // Degrees, half and quarter degrees, negative angles, and large multiples (up to where the
  // double's own rounding, 1.1e-16 of it, nears the slack of 1e-12 per unit of denominator).
  const std::vector<std::pair<long, long>> multiples{
      {1, 1}, {1, 6},   {209, 360}, {-1, 2},  {-179, 180},   {1, 720},
      {3, 4}, {7, 720}, {360, 1},   {5000, 1}, {-99999, 720}, {719, 720}};
  for (const auto& [num, den] : multiples) {
    const double d = times_pi(num, den);
    INFO(num << "/" << den << " pi = " << d << " -> " << exact_value(d));
    REQUIRE(is_pi_times(exact_value(d), num, den));
  }
}

TEST_CASE("any other double is its shortest decimal") {
  // Beside a multiple by far more than rounding, a numerator past 1e6, a denominator past 720
  // (1/721 pi), and plain decimals.
  const double near_pi = std::numbers::pi + 1e-9;
  const double large = times_pi(1000003, 1);
  const double fine = times_pi(1, 721);
  for (const double d : {near_pi, large, fine, 0.1, -2.5, 1e300}) {
    const GiNaC::ex e = exact_value(d);
    INFO(d << " -> " << e);
    REQUIRE(GiNaC::is_a<GiNaC::numeric>(e));
    REQUIRE(GiNaC::ex_to<GiNaC::numeric>(e).is_rational());
    REQUIRE(GiNaC::ex_to<GiNaC::numeric>(e).to_double() == d);
  }
  REQUIRE(exact_value(0.1).is_equal(GiNaC::numeric(1, 10)));
}
