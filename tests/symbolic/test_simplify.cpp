// simplify(): its result depends only on the rational function, not on how it is written, so
// the sums it writes over one denominator before normal() come out as they would have.
#include <catch2/catch.hpp>

#include <random>

#include "symbolic/canonical_print.hpp"
#include "symbolic/inertia_sym.hpp"

using namespace wobble::sym;
using GiNaC::ex;

namespace {
const GiNaC::possymbol M("M"), m1("m1"), d1("d1");
const GiNaC::realsymbol alpha("alpha");

// A polynomial in masses, a length and cos, sin of an angle: seeded, small coefficients.
ex random_polynomial(std::mt19937& rng, int terms) {
  std::uniform_int_distribution<int> coefficient(-4, 4), exponent(0, 2);
  // Built here, not at namespace scope: GiNaC's functions are registered by its own static
  // initialisation, which need not have run before this file's.
  const GiNaC::lst atoms{M, m1, d1, GiNaC::cos(alpha), GiNaC::sin(alpha)};
  ex p = 0;
  for (int t = 0; t < terms; ++t) {
    ex term = coefficient(rng);
    for (const auto& atom : atoms) term *= GiNaC::pow(atom, exponent(rng));
    p += term;
  }
  return p;
}
}  // namespace

TEST_CASE("simplify gives one form for a rational function however it is written") {
  // As a tensor about the centre of mass writes it: P/D - Q/D, ((P/D - Q/D)/2)^2 + (R/D)^2,
  // against the same written as one fraction by hand, and through a different denominator.
  const SymbolTable table;
  std::mt19937 rng(20261125);
  int compared = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const ex P = random_polynomial(rng, 3), Q = random_polynomial(rng, 3),
             R = random_polynomial(rng, 2);
    const ex D = M + m1 + (trial % 2 == 0 ? ex(0) : ex(2) * d1);
    if (GiNaC::expand(P - Q).is_zero()) continue;
    ++compared;
    const ex A = P / D, B = Q / D, C = R / D;
    const std::vector<std::pair<ex, ex>> same{
        {A - B, (P - Q) / D},
        {(A + B) / 2, (P + Q) / (2 * D)},
        {A * B - C * C, (P * Q - R * R) / GiNaC::pow(D, 2)},
        {GiNaC::pow((A - B) / 2, 2) + C * C,
         GiNaC::expand(GiNaC::pow(P - Q, 2) + 4 * R * R) / (4 * GiNaC::pow(D, 2))},
        {A - B + 1 / M, (P * M - Q * M + D) / (D * M)},  // two denominators
    };
    for (const auto& [written, by_hand] : same) {
      INFO("written " << written << "\nby hand " << by_hand);
      REQUIRE(to_text(simplify(written), table) == to_text(simplify(by_hand), table));
    }
  }
  REQUIRE(compared > 30);
}

TEST_CASE("simplify reduces by sin^2 + cos^2 = 1 wherever sin or cos occurs, in either direction") {
  // Expressions without sin or cos skip the reductions (they would change nothing); these have
  // them, nested in sums, powers and denominators, and must still be reduced.
  const SymbolTable table;
  const ex s = GiNaC::sin(alpha), c = GiNaC::cos(alpha);
  const auto text = [&](const ex& e) { return to_text(simplify(e), table); };
  REQUIRE(text(M * GiNaC::pow(s, 2) + M * GiNaC::pow(c, 2)) == "M");
  REQUIRE(text(M * GiNaC::pow(c, 2) - M) == "-M*sin(alpha)^2");
  REQUIRE(text(m1 - m1 * GiNaC::pow(s, 2)) == "m1*cos(alpha)^2");
  REQUIRE(text((GiNaC::pow(s, 2) + GiNaC::pow(c, 2)) / (M + m1 * GiNaC::pow(c, 4))) ==
          text(1 / (M + m1 * GiNaC::pow(c, 4))));
  // Of the two reductions the one with fewer minus signs, then the shorter, whichever is typed.
  REQUIRE(text(2 - GiNaC::pow(s, 2)) == "cos(alpha)^2 + 1");
  REQUIRE(text(1 + GiNaC::pow(c, 2)) == "cos(alpha)^2 + 1");
  REQUIRE(text(4 - 3 * GiNaC::pow(c, 2)) == "3*sin(alpha)^2 + 1");
  // Factored where that is shorter, with functions as without (symbols stand in for them while
  // factoring): the same polynomial gives the same form whether sin and cos were in it or not,
  // and a moment about the centre of mass is m1 d1^2 sin^2 (M + m1)/.., not two terms.
  REQUIRE(text(GiNaC::pow(M * GiNaC::pow(s, 2) + M * GiNaC::pow(c, 2) - m1, 2)) == "(M - m1)^2");
  REQUIRE(text(GiNaC::pow(M - m1, 2)) == "(M - m1)^2");
  REQUIRE(text((M * m1 * GiNaC::pow(d1 * s, 2) + m1 * m1 * GiNaC::pow(d1 * s, 2)) / (M + 2 * m1)) ==
          "d1^2*m1*sin(alpha)^2*(M + m1)/(2*m1 + M)");
  // What comes out of each sum is its content, a number times a monomial, from the numerator
  // and the denominator alike; a fraction with pi among its coefficients is factored whole.
  REQUIRE(text((6 * M * s + 4 * m1 * s) / (M * M + M * m1)) ==
          "2*sin(alpha)*(2*m1 + 3*M)/(M*(M + m1))");
  REQUIRE(text(GiNaC::Pi * M * m1 * s + GiNaC::Pi * m1 * m1 * s) == "m1*Pi*sin(alpha)*(M + m1)");
  // A factor of the denominator that the reduction brings out in the numerator cancels: GiNaC's
  // gcd took M sin^2 + M cos^2 + m1 for prime to M + m1.
  REQUIRE(text(d1 * s * (M * GiNaC::pow(s, 2) + M * GiNaC::pow(c, 2) + m1) * (M + 2 * m1) /
               GiNaC::pow(M + m1, 2)) == "d1*sin(alpha)*(2*m1 + M)/(M + m1)");
  // Without sin or cos: one fraction, cancelled, and factored where that is shorter.
  REQUIRE(text((GiNaC::pow(M, 2) - GiNaC::pow(m1, 2)) / (M + m1)) == "M - m1");
  REQUIRE(text(GiNaC::atan(M) * GiNaC::atan(M) / M) == "atan(M)^2/M");
}

TEST_CASE("normalized() simplifies every entry, a mirrored one once, an unmirrored one itself") {
  // A symmetric tensor's lower entry is taken from the upper; a matrix whose lower entry differs
  // from the upper (or is not square) has each entry simplified on its own.
  const SymbolTable table;
  const ex D = M + m1;
  const ex upper = M * d1 / D - m1 * d1 / D, other = (M - m1) / D;
  GiNaC::matrix m(3, 3);
  m(0, 1) = m(1, 0) = upper;
  m(0, 2) = other;
  m(2, 0) = other * d1;
  m(1, 1) = GiNaC::pow(GiNaC::sin(alpha), 2) + GiNaC::pow(GiNaC::cos(alpha), 2);
  const GiNaC::matrix out = normalized(m);
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) {
      INFO(i << ", " << j);
      REQUIRE(to_text(out(i, j), table) == to_text(simplify(m(i, j)), table));
    }
  }
  REQUIRE(to_text(out(1, 0), table) == "d1*(M - m1)/(M + m1)");
  REQUIRE(to_text(out(2, 0), table) == "d1*(M - m1)/(M + m1)");
  REQUIRE(to_text(out(0, 2), table) == "(M - m1)/(M + m1)");
  REQUIRE(to_text(out(1, 1), table) == "1");
  GiNaC::matrix wide(2, 3);
  wide(1, 0) = upper;
  wide(0, 1) = other;
  const GiNaC::matrix wide_out = normalized(wide);
  REQUIRE(to_text(wide_out(1, 0), table) == "d1*(M - m1)/(M + m1)");
  REQUIRE(to_text(wide_out(0, 1), table) == "(M - m1)/(M + m1)");
}

TEST_CASE(
    "simplified_sqrt takes out square numbers, a sum's integer content, a positive denominator's "
    "square") {
  const SymbolTable table;
  const GiNaC::realsymbol x("x"), y("y");
  // GiNaC distributes 16 over the sum, where factor() cannot find it again as a factor.
  const ex content = simplified_sqrt(GiNaC::expand(16 * (x * x + y * y)));
  CHECK(to_text(content, table) == "4*sqrt(x^2 + y^2)");
  // (4 d1^2 + M^2)^4 expanded below a sum of either sign, as the heavy top's nutation limit has
  // it: the positive sum's square comes out, the numerator stays under the root.
  const ex d = 4 * d1 * d1 + M * M;
  const ex over_d4 = simplified_sqrt((x - y) / GiNaC::expand(GiNaC::pow(d, 4)));
  CHECK(to_text(over_d4, table) == to_text(GiNaC::sqrt(x - y) / GiNaC::pow(d, 2), table));
  // A negative content: its sign stays under the root with the sum (imaginary where it is).
  const ex negative = simplified_sqrt(GiNaC::expand(-8 * (x * x + 1)));
  CHECK(to_text(negative, table) ==
        to_text(2 * GiNaC::sqrt(ex(2)) * GiNaC::sqrt(-x * x - 1), table));
  // GiNaC evaluates the root of a perfect square only: a number's square factors come out.
  CHECK(to_text(simplified_sqrt(ex(23328) * x * x), table) == "108*sqrt(2)*sqrt(x^2)");
  CHECK(to_text(simplified_sqrt(ex(8) / 75), table) == to_text(2 * GiNaC::sqrt(ex(6)) / 15, table));
  // Each is the root it was given, at points of both signs (to 20 digits' rounding).
  const std::vector<std::pair<ex, ex>> cases{{content, GiNaC::expand(16 * (x * x + y * y))},
                                             {over_d4, (x - y) / GiNaC::expand(GiNaC::pow(d, 4))},
                                             {negative, GiNaC::expand(-8 * (x * x + 1))}};
  constexpr double kTwentyDigits = 1e-15;
  for (const auto& [root, radicand] : cases) {
    for (const int xv : {-3, 2}) {
      const GiNaC::exmap at{{x, xv}, {y, -5}, {d1, 2}, {M, 3}};
      const ex want = GiNaC::sqrt(radicand.subs(at)).evalf();
      const double off =
          GiNaC::ex_to<GiNaC::numeric>(GiNaC::abs(root.subs(at).evalf() - want) / GiNaC::abs(want))
              .to_double();
      CHECK(off < kTwentyDigits);
    }
  }
}
