#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "symbolic/canonical_print.hpp"
#include "symbolic/principal_sym.hpp"

using namespace wobble::sym;
using Method = SymPrincipal::Method;

namespace {
GiNaC::matrix from_rows(const SymbolTable& t, const std::vector<std::vector<std::string>>& rows) {
  GiNaC::matrix m(3, 3);
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) m(i, j) = t.parse(rows[i][j], "m");
  }
  return m;
}

std::vector<double> sorted_values(const SymPrincipal& p, const GiNaC::lst& at) {
  std::vector<double> v;
  for (const auto& e : p.moments) v.push_back(evaluate(e, at, "moment"));
  std::sort(v.begin(), v.end());
  return v;
}
}  // namespace

TEST_CASE("closed-form routes: diagonal, block, factored, none") {
  SymbolTable t;
  t.declare("m", "m", SymbolSign::positive);
  t.declare("a", "a", SymbolSign::positive);
  const GiNaC::lst at = substitution(t, {{"m", 2.0}, {"a", 3.0}});
  const GiNaC::symbol lambda("lambda");

  const auto diag = principal_closed_form(
      from_rows(t, {{"m", "0", "0"}, {"0", "2*m", "0"}, {"0", "0", "a"}}), lambda);
  REQUIRE(diag.method == Method::diagonal);

  // Taylor 10.35: block in y-z, moments 5, 7, 10 m a^2.
  const auto block = principal_closed_form(
      from_rows(t, {{"10*m*a^2", "0", "0"}, {"0", "6*m*a^2", "m*a^2"}, {"0", "m*a^2", "6*m*a^2"}}),
      lambda);
  REQUIRE(block.method == Method::block);
  REQUIRE(sorted_values(block, at) == std::vector<double>{90.0, 126.0, 180.0});

  // All products nonzero: 3m 1 + m B with B's eigenvectors (1,1,0), (1,0,1) (eigenvalue 1) and
  // (1,-1,-1) (eigenvalue -2), so the moments are m, 4m, 4m: a repeated root, exact.
  const auto factored = principal_closed_form(
      from_rows(t, {{"3*m", "m", "m"}, {"m", "3*m", "-m"}, {"m", "-m", "3*m"}}), lambda);
  REQUIRE(factored.method == Method::factored);
  REQUIRE(sorted_values(factored, at) == std::vector<double>{2.0, 8.0, 8.0});
  // The repeated root has no single axis; the simple one does, and it is (1,-1,-1)/sqrt 3.
  std::size_t simple = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    if (evaluate(factored.moments[i], at, "m") == 2.0) simple = i;
  }
  const auto axis = principal_axis_closed_form(
      from_rows(t, {{"3*m", "m", "m"}, {"m", "3*m", "-m"}, {"m", "-m", "3*m"}}), factored, simple,
      at);
  REQUIRE(axis);
  const double x = evaluate((*axis)[0], at, "x"), y = evaluate((*axis)[1], at, "y");
  REQUIRE_THAT(std::abs(x), Catch::Matchers::WithinRel(1.0 / std::sqrt(3.0), 4e-16));
  REQUIRE_THAT(x, Catch::Matchers::WithinRel(-y, 4e-16));
  const std::size_t repeated = simple == 0 ? 1 : 0;
  REQUIRE_FALSE(principal_axis_closed_form(
      from_rows(t, {{"3*m", "m", "m"}, {"m", "3*m", "-m"}, {"m", "-m", "3*m"}}), factored, repeated,
      at));

  // An irreducible cubic in the parameters has no closed form here.
  const auto none = principal_closed_form(
      from_rows(t, {{"m", "a", "1"}, {"a", "2*m", "a"}, {"1", "a", "3"}}), lambda);
  REQUIRE(none.method == Method::numeric);
}

TEST_CASE("a moment whose root comes out whole is one fraction, as it is without pi") {
  // Taylor 10.35 with the mass at (a, 0, 0) moved to (a pi/3, 0, 0): the y-z block's mean is
  // m a^2 (pi^2 + 45)/9, its root m a^2. GiNaC adds 6 m a^2 - m a^2 by itself, not the form with
  // pi, which was printed "m a^2 (pi^2 + 45)/9 - m a^2".
  SymbolTable t;
  t.declare("m", "m", SymbolSign::positive);
  t.declare("a", "a", SymbolSign::positive);
  const std::string yy = "m*a^2*(pi^2 + 45)/9";
  const auto block = principal_closed_form(
      from_rows(t, {{"10*m*a^2", "0", "0"}, {"0", yy, "m*a^2"}, {"0", "m*a^2", yy}}),
      GiNaC::symbol("lambda"));
  REQUIRE(block.method == Method::block);
  CHECK(to_text(block.moments[1], t) == "m*a^2*(Pi^2 + 36)/9");
  CHECK(to_text(block.moments[2], t) == "m*a^2*(Pi^2 + 54)/9");
  // Where the root stays a root, the moments stay mean -+ root (the keys' forms).
  const auto rooted = principal_closed_form(
      from_rows(t, {{"10*m*a^2", "0", "0"}, {"0", "6*m*a^2", "m*a^2"}, {"0", "m*a^2", "m*a^2"}}),
      GiNaC::symbol("lambda"));
  REQUIRE(rooted.method == Method::block);
  CHECK(to_text(rooted.moments[1], t) == "7*m*a^2/2 - m*a^2*sqrt(29)/2");
}

TEST_CASE("a block's moment with a root stays a root over the block's one denominator") {
  // As the three-atom molecule's about its centre of mass: a mean and a root over one sum, 2 (M
  // + m). Two fractions were printed -(P/(2 (M + m)) + sqrt(Q)/(2 (M + m))), P negated.
  SymbolTable t;
  t.declare("M", "M", SymbolSign::positive);
  t.declare("m", "m", SymbolSign::positive);
  t.declare("a", "a", SymbolSign::positive);
  const auto block = principal_closed_form(from_rows(t, {{"m", "0", "0"},
                                                         {"0", "m*a^2/(M + m)", "m*a/(M + m)"},
                                                         {"0", "m*a/(M + m)", "3*m/(M + m)"}}),
                                           GiNaC::symbol("lambda"));
  REQUIRE(block.method == Method::block);
  // ((a^2 - 3)/2)^2 + a^2 = (a^4 - 2 a^2 + 9)/4, irreducible over the rationals: the moments
  // are m (a^2 + 3 -+ sqrt(a^4 - 2 a^2 + 9))/(2 (M + m)).
  CHECK(to_text(block.moments[1], t) == "(3*m + m*a^2 - m*sqrt(a^4 + 9 - 2*a^2))/(2*(M + m))");
  CHECK(to_text(block.moments[2], t) == "(3*m + m*a^2 + m*sqrt(a^4 + 9 - 2*a^2))/(2*(M + m))");
  const GiNaC::lst at = substitution(t, {{"M", 3.0}, {"m", 2.0}, {"a", 1.5}});
  const double root = std::sqrt(std::pow(1.5, 4) - 2 * 1.5 * 1.5 + 9);
  constexpr double kRoundings = 8 * std::numeric_limits<double>::epsilon();  // a few operations
  CHECK_THAT(evaluate(block.moments[1], at, "moment"),
             Catch::Matchers::WithinRel(2 * (1.5 * 1.5 + 3 - root) / 10, kRoundings));
  CHECK_THAT(evaluate(block.moments[2], at, "moment"),
             Catch::Matchers::WithinRel(2 * (1.5 * 1.5 + 3 + root) / 10, kRoundings));
}
