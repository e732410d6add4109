// A number glued to pi or a function's name gets its '*'; names, exponents and symbols do not.
#include <catch2/catch.hpp>
#include <string>
#include <utility>
#include <vector>

#include "symbolic/glued_numbers.hpp"

using wobble::sym::numbers_times_constants;

TEST_CASE("numbers glued to pi or a function are products; names and exponents stay") {
  for (const auto& [typed, read] : std::vector<std::pair<std::string, std::string>>{
           {"2pi/3", "2*pi/3"},
           {"0.25Pi", "0.25*Pi"},
           {"3sin^2(a)", "3*sin^2(a)"},
           {"2sqrt(3) + 4exp(1)", "2*sqrt(3) + 4*exp(1)"},
           {".5arctan(x)", ".5*arctan(x)"},
           {"(1/3)pi", "(1/3)*pi"},
           {"(a + b)sin(x)", "(a + b)*sin(x)"},
           // No change: the digits end a name; an exponent; a symbol (its reader decides);
           // a name that only starts like pi.
           {"theta0pi", "theta0pi"},
           {"1e-3", "1e-3"},
           {"2E+5", "2E+5"},
           {"2exp(1)", "2*exp(1)"},
           {"2m", "2m"},
           {"2pix", "2pix"},
           {"psidot0 sin(a)", "psidot0 sin(a)"}}) {
    INFO(typed);
    REQUIRE(numbers_times_constants(typed) == read);
  }
}
