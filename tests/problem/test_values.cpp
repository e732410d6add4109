#include <catch2/catch.hpp>
#include <cmath>

#include "problem/values.hpp"

using namespace wobble;

namespace {
Parameter angle() {
  Parameter p;
  p.name = "alpha";
  p.unit = "rad";
  p.range = parse_interval("[0, pi/2)", "range");
  return p;
}
Parameter mass() {
  Parameter p;
  p.name = "m";
  p.unit = "kg";
  p.range = parse_interval("(0, inf)", "range");
  return p;
}
}  // namespace

TEST_CASE("values: numbers, constant expressions, degrees") {
  REQUIRE(parse_parameter_value(mass(), "2.5", "f") == 2.5);
  REQUIRE(parse_parameter_value(mass(), " 1e-3 ", "f") == 1e-3);
  // pi/6 is evaluated exactly and rounded once; M_PI / 6 rounds twice: within 1 ulp.
  REQUIRE_THAT(parse_parameter_value(angle(), "pi/6", "f"),
               Catch::Matchers::WithinULP(M_PI / 6, 1));
  REQUIRE_THAT(parse_parameter_value(angle(), "30deg", "f"),
               Catch::Matchers::WithinULP(M_PI / 6, 1));
  REQUIRE(parse_parameter_value(angle(), "0", "f") == 0.0);  // closed end
  // Degrees are converted exactly: 30deg is the correctly rounded pi/6, like "pi/6" itself.
  REQUIRE(parse_parameter_value(angle(), "30deg", "f") ==
          parse_parameter_value(angle(), "pi/6", "f"));
  REQUIRE(parse_parameter_value(angle(), "30 °", "f") ==
          parse_parameter_value(angle(), "pi/6", "f"));
  REQUIRE(parse_parameter_value(angle(), "45°", "f") ==
          parse_parameter_value(angle(), "pi/4", "f"));
}

TEST_CASE("values: each kind of bad value is named") {
  REQUIRE_THROWS_WITH(parse_parameter_value(mass(), "-1", "--set m"),
                      Catch::Contains("--set m") && Catch::Contains("outside its range (0, inf)"));
  REQUIRE_THROWS_WITH(parse_parameter_value(mass(), "0", "--set m"), Catch::Contains("outside"));
  REQUIRE_THROWS_WITH(parse_parameter_value(mass(), "nan", "--set m"), Catch::Contains("finite"));
  REQUIRE_THROWS_WITH(parse_parameter_value(mass(), "inf", "--set m"), Catch::Contains("finite"));
  REQUIRE_THROWS_WITH(parse_parameter_value(mass(), "1e999", "--set m"), Catch::Contains("finite"));
  REQUIRE_THROWS_WITH(parse_parameter_value(mass(), "two", "--set m"),
                      Catch::Contains("'two' is not a number"));
  REQUIRE_THROWS_WITH(parse_parameter_value(mass(), "3deg", "--set m"),
                      Catch::Contains("in degrees but m is in kg"));
  REQUIRE_THROWS_WITH(parse_parameter_value(angle(), "90deg", "--set alpha"),
                      Catch::Contains("outside its range [0, pi/2)"));
  REQUIRE_THROWS_WITH(parse_parameter_value(angle(), "", "--set alpha"),
                      Catch::Contains("not a number"));
}

TEST_CASE("intervals") {
  const Interval i = parse_interval("(0, pi]", "r");
  REQUIRE_FALSE(i.contains(0.0));
  REQUIRE(i.contains(M_PI));
  REQUIRE_FALSE(i.contains(4.0));
  REQUIRE_THROWS_WITH(
      parse_interval("0..1", "parameters[0].range"),
      Catch::Contains("parameters[0].range") && Catch::Contains("expected an interval"));
  REQUIRE_THROWS_WITH(parse_interval("(2, 1)", "r"), Catch::Contains("empty interval"));
}
