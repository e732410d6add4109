// The terminal's notation both ways: what to_unicode prints, to_ascii reads back as the same
// text, so that a printed form pasted into `check` is what was printed.
#include <catch2/catch.hpp>
#include <string>
#include <utility>
#include <vector>

#include "symbolic/unicode_notation.hpp"

using wobble::sym::to_ascii;
using wobble::sym::to_unicode;

TEST_CASE("to_unicode prints powers as superscripts, a negative whole one too, and reads back") {
  for (const auto& [ginac, printed] :
       std::vector<std::pair<std::string, std::string>>{{"m*R^2/4", "m·R²/4"},
                                                        {"150 s^(-1)", "150 s⁻¹"},
                                                        {"kg*m^2*s^(-12)", "kg·m²·s⁻¹²"},
                                                        // A unit as the SI's powers write it.
                                                        {"kg m^2 s^-1", "kg m² s⁻¹"},
                                                        // Not a whole power: left as it is.
                                                        {"x^(-a)", "x^(-a)"},
                                                        {"x^(-1/2)", "x^(-1/2)"}}) {
    INFO(ginac);
    REQUIRE(to_unicode(ginac) == printed);
  }
  REQUIRE(to_ascii("150 s⁻¹") == "150 s^(-1)");
  REQUIRE(to_ascii(to_unicode("kg m^2 s^-1")) == "kg m^2 s^(-1)");
  REQUIRE(to_ascii(to_unicode("kg*m^2*s^(-12)")) == "kg*m^2*s^(-12)");
}

TEST_CASE("a root's operand is a bracket, a number, a name or another root's operand") {
  for (const auto& [typed, read] : std::vector<std::pair<std::string, std::string>>{
           {"√2", "sqrt(2)"},
           {"√(m R)", "sqrt(m R)"},
           {"2√3/2", "2sqrt(3)/2"},
           {"√√2", "sqrt(sqrt(2))"},
           {"√√(a+b)/4", "sqrt(sqrt(a+b))/4"},
           {"√(√(a))·√√√x", "sqrt(sqrt(a))*sqrt(sqrt(sqrt(x)))"},
           // Closes owed to roots of roots come after their own bracket's, nested too.
           {"√√(√√(a)+1)", "sqrt(sqrt(sqrt(sqrt(a))+1))"},
           // Nothing to take the root of: an empty call, for the guard to refuse.
           {"√", "sqrt()"},
           {"√√", "sqrt(sqrt())"}}) {
    INFO(typed);
    REQUIRE(to_ascii(typed) == read);
  }
  // Thousands of roots of roots read without a deep recursion.
  constexpr int kRoots = 20000;
  std::string many, read;
  for (int k = 0; k < kRoots; ++k) {
    many += "√";
    read += "sqrt(";
  }
  REQUIRE(to_ascii(many + "2") == read + "2" + std::string(kRoots, ')'));
}
