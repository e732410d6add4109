// The dimension of an expression, read off its structure (check/expression_dimension):
// every closed form in the catalog has the dimension of its unit (a check of the key by
// dimensional analysis, independent of how its values were found), and a student's expression
// of another dimension, or one that mixes dimensions, is told so.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "check/check_fixture.hpp"
#include "check/expression_dimension.hpp"
#include "check/judge.hpp"
#include "solvers/catalog.hpp"
#include "symbolic/unicode_notation.hpp"
#include "symbolic/units.hpp"
#include "symbolic/value_text.hpp"

using namespace wobble;
using Fixture = wobble::test::CheckFixture;

namespace {
std::array<int, 3> dimension_of(const std::string& unit) {
  return unit.empty() ? std::array<int, 3>{0, 0, 0} : parse_unit(unit, "test").dim;
}

// The first parameter with a unit of mass, length or time, for a factor that changes an
// answer's dimension.
const ParameterValue* dimensional_parameter(const Key& key) {
  for (const auto& p : key.parameters) {
    if (dimension_of(p.unit) != std::array<int, 3>{0, 0, 0}) return &p;
  }
  return nullptr;
}

std::array<int, 3> sum(std::array<int, 3> a, const std::array<int, 3>& b) {
  for (std::size_t i = 0; i < 3; ++i) a[i] += b[i];
  return a;
}
}  // namespace

TEST_CASE("every closed form in the catalog has the dimension of its unit") {
  int entries = 0, dimensional = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.symbolic.empty()) continue;
        const auto value = sym::parse_value_text(a.symbolic, f.table, "key " + a.name);
        for (const auto& e : value.entries) {
          if (e.is_zero()) continue;  // a zero has every dimension
          INFO(p.id << " " << a.name << " [" << a.unit << "]: " << e);
          const auto d = check::expression_dimension(e, f.key);
          if (!d) {
            // Told for every entry in the symbols; a constant's unit is not written
            // (sqrt(2)/2 in an axis), and it evaluates with no parameter values.
            REQUIRE_NOTHROW(sym::evaluate(e, GiNaC::lst{}, "test"));
            continue;
          }
          REQUIRE_FALSE(d->mixed);
          REQUIRE(d->dim == dimension_of(a.unit));
          ++entries;
          dimensional += *d->dim != std::array<int, 3>{0, 0, 0};
        }
      }
    }
  }
  REQUIRE(entries > 270);      // the catalog's closed-form entries in the symbols (286 today)
  REQUIRE(dimensional > 170);  // most carry mass, length or time (184)
}

TEST_CASE("an expression of another dimension is told its dimension, one that mixes them too") {
  int scaled = 0, mixed = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    const ParameterValue* x = dimensional_parameter(f.key);
    if (x == nullptr) continue;
    Unit times_x;
    times_x.dim = dimension_of(x->unit);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.symbolic.empty() || a.value.data.size() != 1 || a.value.data[0] == 0.0) continue;
        if (a.kind == AnswerKind::principal_moments) continue;
        Unit wrong;
        wrong.dim = sum(dimension_of(a.unit), times_x.dim);
        const std::string product = "(" + a.symbolic + ")*" + x->name;
        INFO(p.id << " " << a.name << ": " << product);
        const check::Verdict v = f.check(a.name, product);
        INFO(v.line);
        REQUIRE_FALSE(v.correct);
        // Right at the set values by chance where x is 1 in SI (rect-solid's m = 1 kg): that is
        // said first, the dimension after it.
        const bool by_chance = x->value == 1.0;
        REQUIRE(v.line == "incorrect: " + a.name +
                              (by_chance ? " (your expression differs from the key's)"
                                         : " has the wrong dimension"));
        REQUIRE(v.feedback.size() == (by_chance ? 2U : 1U));
        CHECK(v.feedback.back().find("dimension is " + wrong.dimension_words() + ";") !=
              std::string::npos);
        ++scaled;
        if (dimension_of(a.unit) == times_x.dim) continue;  // a sum of like quantities
        const std::string total = "(" + a.symbolic + ") + " + x->name;
        INFO(total);
        const check::Verdict w = f.check(a.name, total);
        REQUIRE_FALSE(w.correct);
        CHECK(w.feedback.back().find("mixes dimensions") != std::string::npos);
        ++mixed;
      }
    }
  }
  REQUIRE(scaled > 60);  // the catalog's nonzero scalar closed forms (68 today)
  REQUIRE(mixed > 60);
}

TEST_CASE("what an expression's dimension says, in the plate's symbols") {
  const Fixture f("flying-plate");
  const auto said = [&](const std::string& text) {
    const check::Verdict v = f.check("I0", text);
    REQUIRE_FALSE(v.correct);
    REQUIRE(v.feedback.size() == 1);
    return v.line + " | " + v.feedback[0];
  };
  CHECK(said("m R/4") ==
        "incorrect: I0 has the wrong dimension | your expression's dimension is mass × length; "
        "the answer is in kg m² (mass × length²)");
  CHECK(said("sin(α)") ==
        "incorrect: I0 has the wrong dimension | your expression is a pure number; the answer "
        "is in kg m² (mass × length²)");
  CHECK(said("m R^2 sin(ω)") ==
        "incorrect: I0 (your expression differs from the key's) | your expression mixes "
        "dimensions: it adds unlike quantities, or takes a function such as sin or exp of a "
        "quantity with a unit");
  // Of the right dimension but wrong: the likely mistake, as for a number.
  CHECK(said("m R^2/8") ==
        "incorrect: I0 (your expression differs from the key's) | this is 1/2 of the answer: a "
        "factor 2 is off (a 1/12 or 1/3 in a moment of inertia, a 1/2 in an energy?)");
  // One the problem file names: the moment about the symmetry axis.
  CHECK_THAT(said("m R^2/2"), Catch::StartsWith("incorrect: I0 (your expression differs from the "
                                                "key's) | this is the moment about the symmetry "
                                                "axis, I₃ = m R²/2, 100% above the answer here"));
  // Right at the set values by chance (m = 1 kg would hide it; m² R²/4 is another dimension).
  CHECK(said("m^2 R^2/4") ==
        "incorrect: I0 has the wrong dimension | your expression's dimension is mass² × "
        "length²; the answer is in kg m² (mass × length²)");
  CHECK(said("sqrt(m) R") ==
        "incorrect: I0 has the wrong dimension | your expression's dimension is mass^(1/2) × "
        "length; the answer is in kg m² (mass × length²)");
  CHECK(said("m + R") ==
        "incorrect: I0 (your expression differs from the key's) | your expression mixes "
        "dimensions: it adds unlike quantities, or takes a function such as sin or exp of a "
        "quantity with a unit");
  // A number for R: right at the set values only, and so a mass.
  const check::Verdict number = f.check("I0", "m 0.12^2/4");
  REQUIRE(number.feedback.size() == 2);
  CHECK(number.feedback[1] ==
        "your expression's dimension is mass; the answer is in kg m² (mass × length²)");
  // A plain number's unit is not written: its size is what is wrong, not its dimension.
  const check::Verdict number_entry = f.check("L0_body", "[m R² ω sin α/4, 0, 0.02]");
  REQUIRE_FALSE(number_entry.correct);
  CHECK(number_entry.feedback == std::vector<std::string>{"entry e₃ is off by 43.8%"});
  // A vector: the entry of another dimension is named.
  const check::Verdict v = f.check("L0_body", "[m R^2 ω sin(α)/4, 0, m R ω cos(α)/2]");
  REQUIRE_FALSE(v.correct);
  REQUIRE(v.feedback.size() == 1);
  CHECK(v.feedback[0] ==
        "entry e₃'s dimension is mass × length / time; the answer is in kg m²/s (mass × length² "
        "/ time)");
}

TEST_CASE("a time given for a rate, or a rate for a time, is told what its reciprocal is") {
  // Over the catalog: every one-number answer in a time or a rate, given as 1/x in the other
  // (a time constant), as 2π/x (a period and an angular rate), and a period as turns per time.
  constexpr std::array<int, 3> kTime{0, 0, 1};
  constexpr std::array<int, 3> kRate{0, 0, -1};
  int told = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        const auto dim = dimension_of(a.unit);
        if (a.value.data.size() != 1 || a.value.data[0] == 0.0 || (dim != kTime && dim != kRate))
          continue;
        const double si = a.value.data[0] * parse_unit(a.unit, "test").to_si;
        const std::string other = dim == kTime ? "1/s" : "s";
        // What each reading is said to be, 1/x first, then 2π/x.
        const std::array<std::string, 2> said =
            dim == kTime ? std::array<std::string, 2>{"a rate or frequency given for the time (its "
                                                      "reciprocal)?",
                                                      "the rate given for the period?"}
                         : std::array<std::string, 2>{"a time given for the rate (its reciprocal)?",
                                                      "the period given for the rate?"};
        // Eight digits: the printed number reads back within any tolerance.
        const auto typed = [](double x, const std::string& unit) {
          return fmt::format("{:.8g} {}", x, unit);
        };
        const std::array<std::string, 2> texts{typed(1 / si, other),
                                               typed(2 * M_PI / si, dim == kTime ? "rad/s" : "s")};
        for (std::size_t r = 0; r < 2; ++r) {
          INFO(p.id << " " << a.name << ": " << texts[r]);
          const check::Verdict v = f.check(a.name, texts[r]);
          REQUIRE(v.wrong_dimension);
          REQUIRE(v.feedback.size() == 2);
          CHECK_THAT(v.feedback.back(),
                     Catch::StartsWith(r == 0 ? "1/(" : "2π/(") && Catch::EndsWith(said[r]));
          ++told;
        }
        // Without a unit, the number is in the key's unit, here SI: the same lines without one.
        if (parse_unit(a.unit, "test").to_si == 1.0) {
          for (std::size_t r = 0; r < 2; ++r) {
            const double number = (r == 0 ? 1.0 : 2 * M_PI) / si;
            const check::Verdict bare = f.check(a.name, fmt::format("{:.8g}", number));
            INFO(p.id << " " << a.name << ": " << number << " without a unit");
            REQUIRE(bare.feedback.size() == 1);
            // A negative number in brackets: "2π/(-1.301) = -4.83 rad/s".
            const std::string shown =
                number < 0 ? fmt::format("({:.4g})", number) : fmt::format("{:.4g}", number);
            CHECK_THAT(bare.feedback[0],
                       Catch::StartsWith((r == 0 ? "1/" : "2π/") + shown + " = ") &&
                           Catch::EndsWith(said[r]));
          }
        }
        if (dim == kTime) {
          const check::Verdict hz = f.check(a.name, typed(1 / si, "Hz"));
          INFO(p.id << " " << a.name << " in Hz");
          REQUIRE(hz.feedback.size() == 2);
          CHECK_THAT(
              hz.feedback.back(),
              Catch::StartsWith("1/(") && Catch::EndsWith("the frequency given for the period?"));
        }
        // Neither: only the dimension is told.
        const check::Verdict off = f.check(a.name, typed(1.5 / si, other));
        INFO(p.id << " " << a.name << " neither");
        REQUIRE(off.wrong_dimension);
        CHECK(off.feedback.size() == 1);
      }
    }
  }
  // One over a rate in degrees per second is no time a student means (1/x in SI is not 1/x of
  // the number typed): not told; two pi over it is a period, as in rad/s.
  const Fixture earth("earth-free-precession");
  const double period = earth.answer("precession_period_body").value.data[0];  // s
  const check::Verdict deg_s =
      earth.check("precession_period_body", fmt::format("{:.8g} deg/s", 180 / M_PI / period));
  REQUIRE(deg_s.wrong_dimension);
  CHECK(deg_s.feedback.size() == 1);
  const check::Verdict turn_deg =
      earth.check("precession_period_body", fmt::format("{:.8g} deg/s", 360 / period));
  CHECK_THAT(turn_deg.feedback.back(),
             Catch::StartsWith("2π/(") && Catch::EndsWith("the rate given for the period?"));
  REQUIRE(told > 40);  // 26 answers in a time or a rate, two readings each (52 today)
}

TEST_CASE("a right number in a unit of another dimension is told that the number is right") {
  // Over the catalog: every answer with a unit, its key's numbers typed in a unit of another
  // dimension (kg, or m where the key is a mass), said to be right in the key's unit; ten times
  // them is not.
  int told = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.unit.empty() || a.kind == AnswerKind::principal_axes) continue;
        const std::string other = dimension_of(a.unit) == dimension_of("kg") ? "m" : "kg";
        const auto typed = [&](double scale) {
          std::string entries;
          for (const double x : a.value.data)
            entries += fmt::format("{}{:.10g}", entries.empty() ? "" : ", ", scale * x);
          return (a.value.data.size() == 1 ? entries : "[" + entries + "]") + " " + other;
        };
        if (a.value.shape == Value::Shape::matrix) continue;  // rows, not one list
        INFO(p.id << " " << a.name << ": " << typed(1));
        const check::Verdict v = f.check(a.name, typed(1));
        REQUIRE(v.wrong_dimension);
        // In the units the question asks in ("rad/s or 1/s" for a rate that is either).
        CHECK(v.feedback.back() == "in " + sym::to_unicode(asked_unit(a)) +
                                       (a.value.data.size() == 1 ? " the number" : " the numbers") +
                                       " would be right");
        ++told;
        // Ten times zero is zero: only where some number is not.
        if (std::all_of(a.value.data.begin(), a.value.data.end(),
                        [](double x) { return x == 0.0; }))
          continue;
        const check::Verdict ten = f.check(a.name, typed(10));
        REQUIRE(ten.wrong_dimension);
        CHECK(ten.feedback.back().find("would be right") == std::string::npos);
      }
    }
  }
  REQUIRE(told > 100);
  // A number with no value (not real) in a wrong unit is told its dimension, as before.
  const Fixture racket("tennis-racket");
  const check::Verdict root = racket.check("rate_axis2", "sqrt(-83.4) kg");
  REQUIRE(root.wrong_dimension);
  CHECK(root.feedback.size() == 1);
}
