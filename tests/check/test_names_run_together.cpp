// Symbols' names run together, as a product is written by hand ("mR²/4"): read as the product
// where the names split one way, and never where the letters are a unit's or a function's.
#include <catch2/catch.hpp>
#include <cctype>
#include <string>

#include "check/check_fixture.hpp"
#include "check/judge.hpp"
#include "check/names_run_together.hpp"
#include "solvers/catalog.hpp"
#include "symbolic/unicode_notation.hpp"

using namespace wobble;
using Fixture = wobble::test::CheckFixture;

namespace {
bool word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

// `text` with each '*' between two of the table's symbols dropped, as a hand writes "m R":
// "m*R^2*omega*sin(alpha)/4" -> "mR^2*omega*sin(alpha)/4". Not after an exponent ("R^2*omega"
// would run 2 into omega), nor before a call.
std::string run_together(const std::string& text, const sym::SymbolTable& table) {
  std::string out;
  for (std::size_t k = 0; k < text.size(); ++k) {
    if (text[k] != '*') {
      out += text[k];
      continue;
    }
    std::size_t left = k;
    while (left > 0 && word_char(text[left - 1])) --left;
    std::size_t right = k + 1;
    while (right < text.size() && word_char(text[right])) ++right;
    const bool symbols = left < k && right > k + 1 && (left == 0 || text[left - 1] != '^') &&
                         table.contains(text.substr(left, k - left)) &&
                         table.contains(text.substr(k + 1, right - k - 1)) &&
                         (right == text.size() || text[right] != '(');
    if (!symbols) out += '*';
  }
  return out;
}
}  // namespace

TEST_CASE("names run together are split where they split one way into the problem's symbols") {
  sym::SymbolTable t;
  for (const char* name : {"m", "R", "a", "b", "ab", "c", "theta0"})
    t.declare(name, name, sym::SymbolSign::positive);
  using check::names_apart;
  CHECK(names_apart("mR^2/4", t) == "m*R^2/4");
  CHECK(names_apart("2mR^2", t) == "2m*R^2");
  CHECK(names_apart("bc + Rtheta0", t) == "b*c + R*theta0");
  // A function's name may end the run before its call or argument, or stand before one name,
  // its argument: "φ̇cosθ" reads so in ASCII.
  CHECK(names_apart("Rcos(theta0)", t) == "R cos(theta0)");
  CHECK(names_apart("mRsin theta0", t) == "m*R sin theta0");
  CHECK(names_apart("Rcostheta0", t) == "R cos theta0");
  CHECK(names_apart("Rcos + 1", t) == "Rcos + 1");
  // Two ways (a*b*c and ab*c), or none: left for the reader to refuse.
  CHECK(names_apart("abc", t) == "abc");
  CHECK(names_apart("mq", t) == "mq");
  // A symbol, a unit's letters, a function, a Greek letter's name, a number's exponent, a name
  // with an underscore: each means itself.
  for (const char* whole : {"ab", "120 mm", "0.5 kg", "sin(a)", "alpha", "2e5", "1.5E3", "m_R"})
    CHECK(names_apart(whole, t) == whole);
}

TEST_CASE("a product written by hand, its factors run together, is judged as the product") {
  const Fixture plate("flying-plate");
  for (const char* right : {"mR^2/4", "mR²/4", "2mR²/8", "¼mR²"}) {
    INFO(right);
    REQUIRE(plate.check("I0", right).correct);
  }
  const auto halved = plate.check("I0", "mR²/8");
  REQUIRE_FALSE(halved.correct);
  REQUIRE_THAT(halved.feedback.at(0), Catch::Contains("factor 2 is off"));
  REQUIRE(plate.check("L0_body", "[mR²ω sin α/4, 0, mR²ω cos α/2]").correct);
  // The letters of a unit stay a unit: "g m^2" is grams times square metres.
  REQUIRE(plate.check("I0", "0.72 g m^2").correct);
  const Fixture top("heavy-top");
  REQUIRE(top.check("omega3_min", "2sqrt(lg(4l²+R²))/R²").correct);
  REQUIRE(top.check("energy_prime", "Mgl cos θ0").correct);
  // Rates run together with a function, as "φ̇cosθ" is typed and as it reads in ASCII.
  const Fixture euler("euler-angles");
  for (const char* right :
       {"(-φ̇sinθ, θ̇, φ̇cosθ + ψ̇)", "(-phidotsin(theta), thetadot, phidotcostheta + psidot)"}) {
    INFO(right);
    REQUIRE(euler.check("omega_primed", right).correct);
  }
  // The judge's search for a symbol of the same value reads it so too: θ̇ for I₃ is named.
  REQUIRE_THAT(euler.check("L_primed", "[-φ̇ I₁ sin θ, θ̇ I₁, θ̇ (φ̇cosθ + ψ̇)]").feedback.at(0),
               Catch::Contains("θ̇ (thetadot) where the key has I₃ (I3)?"));
  // A symbol in the other case, alone or run together, is named; not taken for a unit.
  REQUIRE_THROWS_WITH(plate.check("I0", "MR^2/4"), Catch::Contains("case-sensitive: m*R?"));
  REQUIRE_THROWS_WITH(plate.check("I0", "m r^2/4"),
                      Catch::Contains("undefined symbol 'r' (names are case-sensitive: R?)") &&
                          !Catch::Contains("unit"));
}

TEST_CASE("every closed form with its symbols run together is judged right, plain and printed") {
  int judged = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.symbolic.empty()) continue;
        const std::string text = run_together(a.symbolic, f.table);
        if (text == a.symbolic) continue;
        for (const std::string& written : {text, sym::to_unicode(text)}) {
          INFO(p.id << " " << a.name << ": " << written);
          REQUIRE(f.check(a.name, written).correct);
          ++judged;
        }
      }
    }
  }
  REQUIRE(judged > 100);  // 57 closed forms have two symbols side by side
}
