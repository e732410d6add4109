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
Parameter pure() {
  Parameter p;
  p.name = "k";
  p.range = parse_interval("(0, 1)", "range");
  return p;
}
Parameter with_unit(const std::string& unit) {
  Parameter p;
  p.name = "x";
  p.unit = unit;
  p.range = parse_interval("(-inf, inf)", "range");
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

TEST_CASE("values with a unit are converted exactly, rounded once") {
  // 5 cm is 5/100 m exactly, then rounded: the double nearest 0.05, as "0.05" itself.
  REQUIRE(parse_parameter_value(with_unit("m"), "5 cm", "f") == 0.05);
  REQUIRE(parse_parameter_value(with_unit("m"), "5cm", "f") == 0.05);
  REQUIRE(parse_parameter_value(with_unit("m"), "0.05 m", "f") == 0.05);
  REQUIRE(parse_parameter_value(with_unit("m"), "5 [cm]", "f") == 0.05);  // as a table heads it
  REQUIRE(parse_parameter_value(mass(), "500 g", "f") == 0.5);
  REQUIRE(parse_parameter_value(mass(), "0.5kg", "f") == 0.5);
  REQUIRE(parse_parameter_value(mass(), "5e2 g", "f") == 0.5);
  REQUIRE(parse_parameter_value(with_unit("kg m^2"), "2 kg m²", "f") == 2.0);
  REQUIRE(parse_parameter_value(with_unit("kg m^2"), "2e4 g cm^2", "f") == 2e-3);
  REQUIRE(parse_parameter_value(with_unit("m/s^2"), "9.81 m/s²", "f") == 9.81);
  REQUIRE(parse_parameter_value(with_unit("N m"), "0.05 N m", "f") == 0.05);
  // Rates: rad/s is 1/s; rpm and Hz count turns, 2 pi rad each, one rounding.
  REQUIRE(parse_parameter_value(with_unit("rad/s"), "150 rad/s", "f") == 150.0);
  REQUIRE(parse_parameter_value(with_unit("rad/s"), "150 1/s", "f") == 150.0);
  REQUIRE(parse_parameter_value(with_unit("rad/s"), "150 s⁻¹", "f") == 150.0);
  REQUIRE(parse_parameter_value(with_unit("rad/s"), "60 rpm", "f") ==
          parse_parameter_value(with_unit("rad/s"), "2*pi", "f"));
  REQUIRE(parse_parameter_value(with_unit("rad/s"), "1 Hz", "f") ==
          parse_parameter_value(with_unit("rad/s"), "2*pi", "f"));
  // The terminal's Unicode, as a key prints it.
  REQUIRE(parse_parameter_value(angle(), "π/6", "f") ==
          parse_parameter_value(angle(), "pi/6", "f"));
  REQUIRE(parse_parameter_value(angle(), "π/6 rad", "f") ==
          parse_parameter_value(angle(), "pi/6", "f"));
  // Both sides of a key's "30° = 0.5235987756 rad": the exact first is taken.
  REQUIRE(parse_parameter_value(angle(), "30° = 0.5235987756 rad", "f") ==
          parse_parameter_value(angle(), "pi/6", "f"));
  // A number glued to pi is a product, as typed and as calculators write it.
  for (const std::string& glued :
       {std::string("2π/12"), std::string("2pi/12"), std::string("(1/3)π/2")}) {
    INFO(glued);
    REQUIRE(parse_parameter_value(angle(), glued, "f") ==
            parse_parameter_value(angle(), "pi/6", "f"));
  }
  // Degrees, minutes and seconds of arc, as an angle is measured: exactly the degrees they sum
  // to (30°15′ is 121π/720, which the exact route recognises; 30.25 deg reads the same).
  for (const std::string& arc : {std::string("30°15′"), std::string("30° 15′ 0″"),
                                 std::string("30 deg 15 arcmin"), std::string("30°15′ = 30.25°")}) {
    INFO(arc);
    REQUIRE(parse_parameter_value(angle(), arc, "f") ==
            parse_parameter_value(angle(), "30.25 deg", "f"));
  }
  REQUIRE(parse_parameter_value(angle(), "30°16′", "f") >
          parse_parameter_value(angle(), "30.25 deg", "f"));
  // Minutes or seconds that run over 59 are a slip: 30°75′ might be 30°57′ or 31°15′.
  for (const std::string& over :
       {std::string("30°75′"), std::string("30°60′"), std::string("30°15′60″"),
        std::string("30 deg 15 arcmin 99 arcsec")}) {
    INFO(over);
    REQUIRE_THROWS_WITH(parse_parameter_value(angle(), over, "--set f"),
                        Catch::Contains("--set f") && Catch::Contains("carry the"));
  }
  REQUIRE(parse_parameter_value(angle(), "30°59′59.9″", "f") <
          parse_parameter_value(angle(), "31 deg", "f"));
  // A length or a time in parts, as people tell them: their sum, converted exactly.
  REQUIRE(parse_parameter_value(with_unit("m"), "1 m 20 cm", "f") ==
          parse_parameter_value(with_unit("m"), "120 cm", "f"));
  REQUIRE_THROWS_AS(parse_parameter_value(with_unit("m"), "20 cm 1 m", "f"), InputError);
  // A constant expression is not cut into a unit: the "i" of pi, the "e" of an exponent.
  REQUIRE(parse_parameter_value(with_unit("m"), "2*pi", "f") == 2 * M_PI);  // doubling is exact
  REQUIRE(parse_parameter_value(with_unit("m"), "1e-3", "f") == 1e-3);
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
  // A second decimal point is a typo, not a digit to drop: 0.2.5 is not 0.25.
  REQUIRE_THROWS_WITH(parse_parameter_value(mass(), "0.2.5", "--set m"),
                      Catch::Contains("'0.2.5' is not a number"));
  REQUIRE_THROWS_WITH(parse_parameter_value(mass(), "3deg", "--set m"),
                      Catch::Contains("'3deg' is in deg (an angle), but m is in kg (mass)"));
  REQUIRE_THROWS_WITH(parse_parameter_value(mass(), "3 m", "--set m"),
                      Catch::Contains("'3 m' is in m (length), but m is in kg (mass)"));
  REQUIRE_THROWS_WITH(parse_parameter_value(mass(), "3 parsecs", "--set m"),
                      Catch::Contains("--set m") && Catch::Contains("unknown unit 'parsecs'"));
  REQUIRE_THROWS_WITH(parse_parameter_value(pure(), "3 deg", "--set k"),
                      Catch::Contains("'3 deg' is in deg (an angle), but k is a pure number"));
  REQUIRE_THROWS_WITH(parse_parameter_value(angle(), "30° = 0.6 rad", "--set alpha"),
                      Catch::Contains("the two sides of '30° = 0.6 rad' differ"));
  REQUIRE_THROWS_WITH(parse_parameter_value(angle(), "30° = 0.5235987756 rad = 1", "--set alpha"),
                      Catch::Contains("more than two sides"));
  REQUIRE_THROWS_WITH(parse_parameter_value(mass(), "2 kg m", "--set m"),
                      Catch::Contains("mass × length"));
  REQUIRE_THROWS_WITH(parse_parameter_value(angle(), "90deg", "--set alpha"),
                      Catch::Contains("outside its range [0, pi/2)"));
  REQUIRE_THROWS_WITH(parse_parameter_value(angle(), "", "--set alpha"),
                      Catch::Contains("not a number"));
  // A unit inside arithmetic, as in a file: the value so written where the unit multiplies all.
  REQUIRE_THROWS_WITH(parse_parameter_value(angle(), "30deg + 14.5deg", "--set alpha"),
                      Catch::Equals("--set alpha: cannot read \"30deg + 14.5deg\": 'deg' is a unit "
                                    "inside the expression; a unit goes once, after the whole "
                                    "value: \"(30 + 14.5) deg\""));
  REQUIRE_THAT(parse_parameter_value(angle(), "(30 + 14.5) deg", "--set alpha"),
               Catch::Matchers::WithinULP(44.5 * M_PI / 180, 1));
  REQUIRE_THROWS_WITH(parse_parameter_value(mass(), "2 kg + 300 g", "--set m"),
                      Catch::Contains("'2 kg + 300 g' is not a number"));
}

TEST_CASE("a percentage is the fraction it says") {
  using Catch::Matchers::WithinULP;
  REQUIRE(percent_as_fraction("5%"));
  CHECK_THAT(*percent_as_fraction("5%"), WithinULP(0.05, 1));
  CHECK_THAT(*percent_as_fraction(" 0.5 % "), WithinULP(0.005, 1));
  for (const std::string not_one : {"5", "%", "5%%", "abc%", "", "5 %x"}) {
    INFO(not_one);
    CHECK_FALSE(percent_as_fraction(not_one));
  }
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
