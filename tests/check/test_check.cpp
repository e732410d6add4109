// Checking answers: units, the key's own values accepted and 5% off rejected for every answer
// of every problem, and each known mistake recognised with its message.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>
#include <tuple>
#include <vector>

#include "check/check_fixture.hpp"
#include "check/diagnosis.hpp"
#include "check/judge.hpp"
#include "check/submission.hpp"
#include "problem/values.hpp"
#include "solvers/catalog.hpp"
#include "solvers/solve.hpp"
#include "symbolic/units.hpp"
#include "symbolic/value_text.hpp"
#include "temp_files.hpp"

using namespace wobble;
using namespace wobble::check;
using Catch::Matchers::WithinRel;
using Catch::Matchers::WithinULP;

namespace {
// An answer written the way a student types it: numbers to 17 digits, vectors and matrices in
// brackets.
std::string typed(const Value& v, double factor = 1.0) {
  const auto num = [&](double x) { return fmt::format("{:.17g}", x * factor); };
  if (v.shape == Value::Shape::scalar) return num(v.data[0]);
  if (v.shape == Value::Shape::vector) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.data.size(); ++i) s += (i ? ", " : "") + num(v.data[i]);
    return s + "]";
  }
  std::string s = "[";
  for (std::size_t r = 0; r < v.rows; ++r) {
    s += r ? ", [" : "[";
    for (std::size_t c = 0; c < v.cols; ++c) s += (c ? ", " : "") + num(v.data[r * v.cols + c]);
    s += "]";
  }
  return s + "]";
}

using Fixture = wobble::test::CheckFixture;
}  // namespace

TEST_CASE("units: SI factors, dimensions and the grammar's errors") {
  REQUIRE_THAT(parse_unit("kg m^2", "u").to_si, WithinRel(1.0, 1e-15));
  REQUIRE(parse_unit("kg*m^2/s", "u").dim == std::array<int, 3>{1, 2, -1});
  REQUIRE_THAT(parse_unit("g cm^2", "u").to_si, WithinRel(1e-7, 1e-15));
  REQUIRE_THAT(parse_unit("rev/s", "u").to_si, WithinRel(2 * M_PI, 1e-15));
  REQUIRE(parse_unit("deg", "u").angle);
  REQUIRE(parse_unit("1/s", "u").dim == std::array<int, 3>{0, 0, -1});
  REQUIRE(parse_unit("1/s", "u").same_dimension(parse_unit("s^-1", "u")));
  // The answer reader writes a signed exponent in parentheses ("s^-1", "s⁻¹" -> "s^(-1)").
  REQUIRE(parse_unit("kg m^(2) s^(-1)", "u").dim == std::array<int, 3>{1, 2, -1});
  REQUIRE_THAT(parse_unit("rad min^(-1)", "u").to_si, WithinRel(1.0 / 60, 1e-15));
  // A dot or hyphen between units multiplies, as engineers write them.
  REQUIRE(parse_unit("kg.m^2/s", "u").dim == std::array<int, 3>{1, 2, -1});
  REQUIRE(parse_unit("N-m-s", "u").dim == std::array<int, 3>{1, 2, -1});
  // Written out, singular or plural, and "per" for the '/'.
  REQUIRE_THAT(parse_unit("revolutions per minute", "u").to_si, WithinRel(2 * M_PI / 60, 1e-15));
  REQUIRE_THAT(parse_unit("degrees", "u").to_si, WithinRel(M_PI / 180, 1e-15));
  // A turn and a cycle are revolutions: "1.2 turns per year", "cycles per second" (Hz).
  REQUIRE_THAT(parse_unit("turns per year", "u").to_si,
               WithinRel(2 * M_PI / (365.25 * 86400), 1e-15));
  REQUIRE_THAT(parse_unit("cycles per second", "u").to_si,
               WithinRel(parse_unit("Hz", "u").to_si, 1e-15));
  REQUIRE(parse_unit("turn", "u").angle);
  // The sidereal day, two words: one turn of the Earth against the stars.
  REQUIRE_THAT(parse_unit("sidereal days", "u").to_si, WithinRel(86164.0905, 1e-15));
  REQUIRE_THAT(parse_unit("rev per Sidereal Day", "u").to_si,
               WithinRel(2 * M_PI / 86164.0905, 1e-15));
  REQUIRE_THROWS_WITH(parse_unit("sidereal", "u"),
                      Catch::Contains("'sidereal' is read before day or days only"));
  // A long text refused as a unit is quoted a line's worth, not whole.
  std::string long_unit = "theta_L";
  for (int i = 0; i < 300; ++i) long_unit += " + 2 theta_L";
  try {
    (void)parse_unit(long_unit, "u");
    FAIL("a unit of 300 terms read");
  } catch (const InputError& e) {
    const std::string said = e.what();
    REQUIRE_THAT(said, Catch::StartsWith("u: cannot read the unit 'theta_L + 2 theta_L"));
    REQUIRE_THAT(said, Catch::Contains("...': "));
    REQUIRE(said.size() < 600);
  }
  REQUIRE(parse_unit("kilogram metres^2 per second", "u").dim == std::array<int, 3>{1, 2, -1});
  REQUIRE(parse_unit("radians", "u").angle);
  // Kilograms as a hurried hand writes them: a plural, capitals (there is no kelvin to mistake).
  for (const std::string kilograms : {"kgs m^2", "Kg m^2", "KG m^2", "Kgs m2"}) {
    CAPTURE(kilograms);
    REQUIRE_THAT(parse_unit(kilograms, "u").to_si, WithinRel(1.0, 1e-15));
    REQUIRE(parse_unit(kilograms, "u").dim == std::array<int, 3>{1, 2, 0});
  }
  // A word in capitals, as a sentence or a table's heading starts it: each the unit it spells.
  for (const auto& [capitals, plain] :
       std::vector<std::pair<std::string, std::string>>{{"Days", "day"},
                                                        {"DAYS", "day"},
                                                        {"Hours", "h"},
                                                        {"Seconds", "s"},
                                                        {"SEC", "s"},
                                                        {"Weeks", "week"},
                                                        {"Years", "yr"},
                                                        {"Degrees", "deg"},
                                                        {"RAD", "rad"},
                                                        {"Radians per Second", "rad/s"}}) {
    CAPTURE(capitals);
    REQUIRE_THAT(parse_unit(capitals, "u").to_si, WithinULP(parse_unit(plain, "u").to_si, 0));
    REQUIRE(parse_unit(capitals, "u").dim == parse_unit(plain, "u").dim);
  }
  // Not a prefixed symbol: Ms is a megasecond, ms a millisecond.
  REQUIRE_THAT(parse_unit("Ms", "u").to_si, WithinRel(1e6, 1e-15));
  REQUIRE_THAT(parse_unit("ms", "u").to_si, WithinRel(1e-3, 1e-15));
  // Powers without a caret, as the SI writes them and a PDF's "m²" pastes.
  REQUIRE(parse_unit("kg m2 s-1", "u").dim == std::array<int, 3>{1, 2, -1});
  REQUIRE(parse_unit("kg m2/s", "u").dim == std::array<int, 3>{1, 2, -1});
  REQUIRE(parse_unit("kg-2", "u").dim == std::array<int, 3>{-2, 0, 0});
  REQUIRE_THAT(parse_unit("cm2", "u").to_si, WithinRel(1e-4, 1e-15));
  REQUIRE_THAT(parse_unit("1/min", "u").to_si, WithinRel(1.0 / 60, 1e-15));
  REQUIRE(parse_unit("J", "u").same_dimension(parse_unit("kg m^2/s^2", "u")));
  // Astronomy's units, as the Earth's wobble is given: the Julian year, seconds of arc.
  REQUIRE_THAT(parse_unit("yr", "u").to_si, WithinRel(365.25 * 86400, 1e-15));
  REQUIRE(parse_unit("years", "u").dim == std::array<int, 3>{0, 0, 1});
  REQUIRE_THAT(parse_unit("weeks", "u").to_si, WithinRel(7 * 86400, 1e-15));
  // Revolutions per second: 2π rad/s, the same as rev/s.
  REQUIRE_THAT(parse_unit("rps", "u").to_si, WithinRel(parse_unit("rev/s", "u").to_si, 1e-15));
  REQUIRE(parse_unit("RPS", "u").angle);
  REQUIRE_THROWS_WITH(parse_unit("months", "u"), Catch::Contains("a month has no one length"));
  REQUIRE_THROWS_WITH(parse_unit("d", "u"), Catch::Contains("'d' is not read as days"));
  REQUIRE_THAT(parse_unit("arcsec", "u").to_si, WithinRel(M_PI / 180 / 3600, 1e-15));
  REQUIRE_THAT(parse_unit("arcminutes", "u").to_si, WithinRel(M_PI / 180 / 60, 1e-15));
  REQUIRE(parse_unit("arcsec", "u").angle);
  // Each '/' or "per" after the first divides too, as "metres per second per second" is said.
  for (const auto& [written, same] :
       std::vector<std::pair<std::string, std::string>>{{"m/s/s", "m/s^2"},
                                                        {"m per s per s", "m/s^2"},
                                                        {"m / s per s", "m/s^2"},
                                                        {"1/s/s", "s^-2"},
                                                        {"rad/s/s", "rad/s^2"},
                                                        {"J/kg/s", "J/kg s"},
                                                        {"kg m^2/s/s", "J"},
                                                        {"per second", "1/s"},
                                                        {"per minute per s", "1/min s"}}) {
    INFO(written);
    const Unit u = parse_unit(written, "u");
    REQUIRE(u.dim == parse_unit(same, "u").dim);
    REQUIRE_THAT(u.to_si, WithinULP(parse_unit(same, "u").to_si, 0));
  }
  // "4 per second", as a rate is said: a leading "per" is "1/"; "per" with nothing after is not.
  REQUIRE_THROWS_WITH(parse_unit("per", "u"), Catch::Contains("cannot read the unit 'per'"));
  // Units run together are refused, with the same written apart to copy.
  REQUIRE_THROWS_WITH(parse_unit("kgm^2", "u"),
                      Catch::Contains("unknown unit 'kgm' ('kg m', with spaces?)"));
  REQUIRE_THROWS_WITH(parse_unit("Nm", "u"), Catch::Contains("('N m', with spaces?)"));
  REQUIRE_THROWS_WITH(parse_unit("furlong", "u"), !Catch::Contains("with spaces?"));
  // The split, the shortest name first, a power without its '^' kept with its name; none for a word
  // that is no run of units.
  for (const auto& [word, apart] :
       std::vector<std::pair<std::string, std::string>>{{"kgm", "kg m"},
                                                        {"Nms", "N m s"},
                                                        {"kgms", "kg m s"},
                                                        {"mm", "mm"},
                                                        {"kgm2", "kg m2"},
                                                        {"m2", "m2"},
                                                        {"kg", "kg"},
                                                        {"furlong", ""},
                                                        {"Q", ""},
                                                        {"kgQ", ""},
                                                        {"2kg", ""},
                                                        {"", ""}}) {
    INFO(word);
    REQUIRE(units_apart(word) == apart);
    // Run together: split into more than one name, and no unit as written.
    CHECK(units_run_together(word) == (!apart.empty() && apart.find(' ') != std::string::npos));
  }
  CHECK_FALSE(units_run_together("mN"));  // a millinewton, though m and N are names too
  for (const std::string bad :
       {"furlong", "kg^x", "m//s",    "/s",          "kg^123",      "",          "kg m^2 !",
        "1/",      "2/s",  "1/s/",    "s^(-1",       "s^()",        "s^(-)",     "s^(-1))",
        "kg-",     "kg.",  ".kg",     "-kg",         "m22",         "kg..m",     "rad/",
        "kg /",    "per",  "rad per", "m per s per", "m per per s", "m / per s", "pers",
        "m-",      "m2-",  "s--1"}) {
    INFO(bad);
    REQUIRE_THROWS_AS(parse_unit(bad, "--answer"), InputError);
  }
}

TEST_CASE("every answer of every problem: the key's values are right, 5% off is wrong") {
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        INFO(p.id << " " << a.name);
        REQUIRE(f.check(a.name, typed(a.value)).correct);
        if (!a.symbolic.empty()) REQUIRE(f.check(a.name, a.symbolic).correct);
        const bool all_zero = std::all_of(a.value.data.begin(), a.value.data.end(),
                                          [](double x) { return x == 0.0; });
        // Axes are right up to sign and scale-free; a zero is judged against the key's scale.
        if (all_zero || a.name.rfind("principal_axes", 0) == 0) continue;
        REQUIRE_FALSE(f.check(a.name, typed(a.value, 1.05)).correct);
      }
    }
  }
}

TEST_CASE("known mistakes are named") {
  const Fixture taylor("taylor-10-35");
  const Verdict sign = taylor.check("I", "[[10,0,0],[0,6,-1],[0,-1,6]]");
  REQUIRE_FALSE(sign.correct);
  REQUIRE_THAT(sign.feedback.at(0), Catch::Contains("products of inertia have the wrong sign"));
  REQUIRE(taylor.check("principal_moments", "[10, 5, 7]").correct);  // any order
  // Moments are compared sorted, so a wrong one is named by its rank.
  REQUIRE_THAT(taylor.check("principal_moments", "[11, 5, 7]").feedback.at(0),
               Catch::Equals("the largest moment is off by 10%"));
  REQUIRE(taylor.check("principal_axes", "[[0,0,-1],[-0.70711,0.70711,0],[0.70711,0.70711,0]]")
              .correct);  // columns up to sign
  const Verdict dim = taylor.check("principal_moments", "[5, 7, 10] kg m");
  REQUIRE_THAT(dim.feedback.at(0),
               Catch::Contains("kg m (mass × length)") && Catch::Contains("mass × length²"));
  REQUIRE(taylor.check("principal_moments", "[5e7, 7e7, 1e8] g cm^2").correct);

  const Fixture plate("flying-plate");
  const auto value = [&](const std::string& name) {
    for (const auto& p : plate.key.parts) {
      for (const auto& a : p.answers) {
        if (a.name == name) return a.value.data[0];
      }
    }
    throw std::logic_error(name);
  };
  const double angle = value("angle_L_e3"), rate = value("Omega_space_rate");
  REQUIRE_THAT(plate.check("angle_L_e3", fmt::format("{}", angle * 180 / M_PI)).feedback.at(0),
               Catch::Contains("in degrees"));
  REQUIRE(plate.check("angle_L_e3", fmt::format("{} deg", angle * 180 / M_PI)).correct);
  REQUIRE_THAT(plate.check("Omega_space_rate", fmt::format("{}", rate / (2 * M_PI))).feedback.at(0),
               Catch::Contains("revolutions per second"));
  REQUIRE(plate.check("Omega_space_rate", fmt::format("{} rev/s", rate / (2 * M_PI))).correct);
  REQUIRE_THAT(
      plate.check("Omega_body_rate", fmt::format("{}", -value("Omega_body_rate"))).feedback.at(0),
      Catch::Contains("prolate"));
  // (m R²/2, twice it, is named by the problem file: the moment about the symmetry axis.)
  REQUIRE_THAT(plate.check("I0", "m*R^2/8").feedback.at(0), Catch::Contains("factor 2"));
  REQUIRE_THAT(plate.check("I0", fmt::format("{}", value("I0") * 12)).feedback.at(0),
               Catch::Contains("factor 12"));
  // Another answer of the key: the wobble angle for the cone's half angle.
  REQUIRE_THAT(plate.check("angle_L_e3", fmt::format("{}", value("max_angle"))).feedback.at(0),
               Catch::Contains("max_angle"));
  // No match: the size of the error, no guess.
  REQUIRE_THAT(plate.check("t_max", fmt::format("{}", value("t_max") * 1.37)).feedback.at(0),
               Catch::Contains("off by 37%"));
  // Significant figures: what rounds correctly to 3 digits is right, the next value is not.
  const double t = value("t_max");
  Options three;
  three.sigfigs = 3;
  const double place = std::pow(10.0, std::floor(std::log10(t)) - 2);
  REQUIRE(plate.check("t_max", fmt::format("{}", std::round(t / place) * place), three).correct);
  REQUIRE_FALSE(
      plate.check("t_max", fmt::format("{}", (std::round(t / place) + 1) * place), three).correct);
}

namespace {
// A known mistake: whether it applies to an answer, the wrong value a student would give, and
// the words its feedback must contain.
struct Mistake {
  std::string kind;
  std::function<bool(const Answer&)> applies;
  std::function<Value(const Answer&)> make;
  std::string words;
};

Value scaled(Value v, double f) {
  for (double& x : v.data) x *= f;
  return v;
}
bool nonzero(const Answer& a) {
  return std::any_of(a.value.data.begin(), a.value.data.end(), [](double x) { return x != 0; });
}
bool named(const Answer& a, const std::string& stem) {
  return a.name.rfind(stem, 0) == 0;
}
bool is_tensor(const Answer& a) {
  return a.value.shape == Value::Shape::matrix && (a.name == "I" || named(a, "I_"));
}

std::vector<Mistake> mistakes_to_make() {
  std::vector<Mistake> m;
  m.push_back({"products of inertia with the wrong sign",
               [](const Answer& a) {
                 if (!is_tensor(a)) return false;
                 for (std::size_t i = 0; i < 9; ++i) {
                   if (i / 3 != i % 3 && a.value.data[i] != 0) return true;
                 }
                 return false;
               },
               [](const Answer& a) {
                 Value v = a.value;
                 for (std::size_t i = 0; i < 9; ++i) {
                   if (i / 3 != i % 3) v.data[i] = -v.data[i];
                 }
                 return v;
               },
               "products of inertia have the wrong sign"});
  m.push_back({"degrees for radians", [](const Answer& a) { return a.unit == "rad" && nonzero(a); },
               [](const Answer& a) { return scaled(a.value, 180 / M_PI); }, "in degrees"});
  m.push_back({"rev/s for rad/s", [](const Answer& a) { return a.unit == "rad/s" && nonzero(a); },
               [](const Answer& a) { return scaled(a.value, 1 / (2 * M_PI)); },
               "revolutions per second"});
  m.push_back({"Omega_body reversed (prolate for oblate)",
               [](const Answer& a) { return named(a, "Omega_body") && nonzero(a); },
               [](const Answer& a) { return scaled(a.value, -1); }, "prolate"});
  for (const double f : {2.0, 12.0}) {
    m.push_back({fmt::format("a factor {:g} in a moment of inertia", f),
                 [](const Answer& a) {
                   return a.unit == "kg m^2" && nonzero(a) && !named(a, "principal_axes");
                 },
                 [f](const Answer& a) { return scaled(a.value, f); },
                 fmt::format("factor {:g} is off", f)});
  }
  // A unit converted the wrong way (g for kg) or a prefix dropped (cm as if m).
  for (const double f : {1e3, 1e-2}) {
    m.push_back({fmt::format("a power of ten: {:g} times", f),
                 [](const Answer& a) { return nonzero(a) && a.kind != AnswerKind::principal_axes; },
                 [f](const Answer& a) { return scaled(a.value, f); }, "a power of ten is off"});
  }
  return m;
}
}  // namespace

namespace {
std::ptrdiff_t nonzero_entries(const Value& v) {
  return std::count_if(v.data.begin(), v.data.end(), [](double x) { return x != 0; });
}
}  // namespace

TEST_CASE("each known mistake is named, on every answer of every problem where it applies") {
  std::map<std::string, int> seen;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        for (const auto& mistake : mistakes_to_make()) {
          if (!mistake.applies(a)) continue;
          const Value wrong = mistake.make(a);
          INFO(p.id << " " << a.name << ": " << mistake.kind << ": " << typed(wrong));
          const Verdict v = f.check(a.name, typed(wrong));
          REQUIRE_FALSE(v.correct);
          REQUIRE_FALSE(v.feedback.empty());
          // A wrong value that is exactly another answer of the key is named as that answer
          // (max_angle is twice angle_L_e3): the more specific diagnosis.
          // One the problem file names (the plate's I₃ = m R²/2 for I₀) is named as the file
          // says: tried before the factors.
          bool other = false;
          for (const auto& q : f.key.parts) {
            for (const auto& b : q.answers) {
              // Of another unit too where two entries are not zero (other_answer, diagnosis.cpp).
              other = other || (&b != &a && (b.unit == a.unit || nonzero_entries(b.value) > 1) &&
                                b.value.data == wrong.data);
            }
          }
          for (const auto& named : a.approximations) {
            other = other || (named.beside == "the answer" && named.values.size() == 1 &&
                              std::abs(named.values[0] - wrong.data.at(0)) <=
                                  check::Options{}.rel_tol * std::abs(named.values[0]));
          }
          REQUIRE_THAT(v.feedback[0], Catch::Contains(other ? "this is" : mistake.words));
          ++seen[mistake.kind];
        }
      }
    }
  }
  // Each mistake met at least once, so this test cannot pass by applying to nothing.
  for (const auto& mistake : mistakes_to_make()) {
    INFO(mistake.kind);
    REQUIRE(seen[mistake.kind] > 0);
  }
}

TEST_CASE("another part's vector or matrix given for an answer of another unit is named as it") {
  // A line pasted into the wrong box: the tennis racket's Euler coefficients (no unit) for its
  // dω/dt (rad/s²) are read in the answer's unit, SI, and name the answer they are.
  int seen = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        // Principal moments and axes are judged in any order, their diagnosis their own.
        if (a.value.data.size() < 2 || a.kind == AnswerKind::principal_axes ||
            a.kind == AnswerKind::principal_moments)
          continue;
        for (const auto& q : f.key.parts) {
          for (const auto& b : q.answers) {
            // Two numbers or more to match: one alone may match by chance.
            if (b.unit == a.unit || b.value.data.size() != a.value.data.size() ||
                nonzero_entries(b.value) < 2 || b.value.data == a.value.data)
              continue;
            INFO(p.id << ": " << b.name << " for " << a.name << ": " << typed(b.value));
            const Verdict v = f.check(a.name, typed(b.value));
            REQUIRE_FALSE(v.correct);
            REQUIRE(!v.feedback.empty());
            // b, or an answer of the same values (the angles read back are the angles; the
            // flying plate's L0 at t = 0 is the same in both frames), the first listed.
            bool named = false;
            for (const auto& r : f.key.parts) {
              for (const auto& c : r.answers) {
                const bool same =
                    c.value.data.size() == b.value.data.size() &&
                    std::equal(c.value.data.begin(), c.value.data.end(), b.value.data.begin(),
                               [](double x, double y) {
                                 return std::abs(x - y) <= check::Options{}.rel_tol * std::abs(y);
                               });
                named =
                    named || (same && v.feedback[0].starts_with("this is " + c.name + " (part " +
                                                                r.id + "), not " + a.name));
              }
            }
            INFO(v.feedback[0]);
            CHECK(named);
            ++seen;
          }
        }
      }
    }
  }
  REQUIRE(seen > 0);
}

TEST_CASE("a rotation's turns each taken the other way, or in reverse order, are named so") {
  // Both Euler problems: Taylor's R = Rz(a) Ry(b) Rz(c) and PHY 711's R = Rz(c)ᵀ Ry(b)ᵀ Rz(a)ᵀ,
  // with (a, b, c) the problem's angles. Each mistake typed two ways, apart from the judge's
  // route (the key's form at the angles negated): as a product of turns, which the answer reader
  // multiplies out, and as the numbers Eigen's turns make.
  const std::string other_way = "each turn is taken the other way";
  const std::string reversed = "the right turns multiplied in reverse order";
  int seen = 0;
  for (const auto& [id, a, b, c] : std::vector<std::array<std::string, 4>>{
           {"euler-angles", "φ", "θ", "ψ"}, {"euler-angles-phy711", "α", "β", "γ"}}) {
    const Fixture f(id);
    const auto angle = [&](std::size_t i) { return f.key.parameters.at(i).value; };
    const auto turn = [](const Eigen::Vector3d& axis, double by) {
      return Eigen::Matrix3d(Eigen::AngleAxisd(by, axis));
    };
    const Eigen::Vector3d y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
    const auto numbers = [&](const Eigen::Matrix3d& m) {
      std::vector<double> rows;
      for (int r = 0; r < 3; ++r)
        for (int col = 0; col < 3; ++col) rows.push_back(m(r, col));
      return typed(Value::matrix(3, 3, rows));
    };
    // The first three parameters are the angles, in order.
    const double ta = angle(0), tb = angle(1), tc = angle(2);
    const auto R = [&](const std::string& t) { return "Rz(" + t + ")"; };
    const auto Ry = [&](const std::string& t) { return "Ry(" + t + ")"; };
    for (const auto& [name, mistake, product, matrix] :
         std::vector<std::tuple<std::string, std::string, std::string, Eigen::Matrix3d>>{
             {"R_zyz", other_way, R("-" + a) + " " + Ry("-" + b) + " " + R("-" + c),
              turn(z, -ta) * turn(y, -tb) * turn(z, -tc)},
             {"R_zyz", reversed, R(c) + " " + Ry(b) + " " + R(a),
              turn(z, tc) * turn(y, tb) * turn(z, ta)},
             {"R_phy711", other_way, R(c) + " " + Ry(b) + " " + R(a),
              turn(z, tc) * turn(y, tb) * turn(z, ta)},
             {"R_phy711", reversed, R(a) + "ᵀ " + Ry(b) + "ᵀ " + R(c) + "ᵀ",
              turn(z, -ta) * turn(y, -tb) * turn(z, -tc)}}) {
      for (const std::string& answer : {product, numbers(matrix)}) {
        INFO(id << " " << name << ": " << answer);
        const Verdict v = f.check(name, answer);
        REQUIRE_FALSE(v.correct);
        REQUIRE_THAT(v.feedback.at(0), Catch::StartsWith(mistake));
        if (mistake == other_way)
          REQUIRE_THAT(v.feedback.at(0), Catch::Contains(a + ", " + b + ", " + c + " negated"));
        ++seen;
      }
    }
  }
  REQUIRE(seen == 16);
}

TEST_CASE("components in another frame are named as such (omega_body for omega_space, ...)") {
  int seen = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        for (const auto& q : f.key.parts) {
          for (const auto& b : q.answers) {
            const auto stem = [](const std::string& n) { return n.substr(0, n.rfind('_')); };
            const bool frames = a.name.find('_') != std::string::npos && &a != &b &&
                                stem(a.name) == stem(b.name) && a.unit == b.unit &&
                                a.value.data.size() == b.value.data.size();
            if (!frames || b.value.data == a.value.data) continue;
            const std::string other = b.name.substr(b.name.rfind('_') + 1);
            if (other != "body" && other != "space" && other != "primed") continue;
            INFO(p.id << ": " << b.name << " given for " << a.name);
            const Verdict v = f.check(a.name, typed(b.value));
            REQUIRE_FALSE(v.correct);
            REQUIRE_THAT(v.feedback.at(0), Catch::Contains("the " + other + "-frame components"));
            ++seen;
          }
        }
      }
    }
  }
  REQUIRE(seen >= 6);  // euler-angles and its PHY 711 twin: three bases each, both ways
}

TEST_CASE("bad answers: empty, unreadable, wrong shape, absurd unit") {
  const Fixture plate("flying-plate");
  for (const std::string bad :
       {"", "   ", "0.16m", "[1, 2", "[1, 2]", "0.16 furlong", "1/0", "q*2"}) {
    INFO("'" << bad << "'");
    REQUIRE_THROWS_AS(plate.check("t_max", bad), InputError);
  }
  // A decimal comma reads as a 2-vector: said so where a number is wanted.
  REQUIRE_THROWS_WITH(plate.check("t_max", "0,16"), Catch::Contains("a decimal comma?"));
  REQUIRE_THROWS_WITH(plate.check("t_max", "-0,16 s"), Catch::Contains("a decimal comma?"));
  REQUIRE_THROWS_WITH(plate.check("t_max", "1,6e-1 s"), Catch::Contains("a decimal comma?"));
  REQUIRE_THROWS_WITH(plate.check("t_max", "1,6e s"), !Catch::Contains("decimal comma"));
  // A unit glued on, as a number with a point may have it.
  REQUIRE_THROWS_WITH(plate.check("t_max", "0,16s"), Catch::Contains("a decimal comma?"));
  REQUIRE_THROWS_WITH(plate.check("angle_omega_e3", "15,5°"), Catch::Contains("a decimal comma?"));
  REQUIRE_THROWS_WITH(plate.check("angle_omega_e3", "15,5deg"),
                      Catch::Contains("a decimal comma?"));
  REQUIRE_THROWS_WITH(plate.check("t_max", "0,16.5"), !Catch::Contains("decimal comma"));
  REQUIRE_THROWS_WITH(plate.check("t_max", "0, 16"),
                      Catch::Contains("2-vector") && !Catch::Contains("decimal comma"));
  // Digits grouped by threes, with spaces or commas, where one number is wanted; a vector or
  // matrix written with decimal commas, one entry more per such comma. Each: answer, typed,
  // what the message says.
  for (const auto& [name, bad, says] : std::vector<std::array<std::string, 3>>{
           {"t_max", "1 600.5 s", "(digits grouped? write 1600.5)"},
           {"t_max", "1\u2009600,5 s", "(digits grouped? write 1600.5)"},
           {"t_max", "1,600,000 s", "(digits grouped? write 1600000)"},
           // One comma before three digits: a decimal comma, or a thousands' separator.
           {"t_max", "437,200 min",
            "(a decimal comma, or digits grouped? write 437.200 or 437200)"},
           {"t_max", "-1,600s", "(a decimal comma, or digits grouped? write -1.600 or -1600)"},
           // Not where no group could stand so: a leading 0, four digits before the comma.
           {"t_max", "0,160 s", "(a decimal comma? write the point: 0.5, not 0,5)"},
           {"t_max", "1600,500 s", "(a decimal comma? write the point: 0.5, not 0,5)"},
           {"t_max", "1,6000 s", "(a decimal comma? write the point: 0.5, not 0,5)"},
           {"t_max", "1,600e-3 s", "(a decimal comma? write the point: 0.5, not 0,5)"},
           {"L0_body", "(0,5, 1,5, 2,5) kg m^2/s", "not a 6-vector [..] (a decimal comma?"},
           {"I", "[[0,5, 0, 0], [0, 0,5, 0], [0, 0, 1,5]]",
            "not a 3x4 matrix [[..], ..] (a decimal comma?"}}) {
    INFO(name << " = " << bad);
    REQUIRE_THROWS_WITH(plate.check(name, bad), Catch::Contains(says));
  }
  // Neither where the text is no such number or the count does not fit.
  REQUIRE_THROWS_WITH(plate.check("t_max", "1 4"), !Catch::Contains("digits grouped"));
  REQUIRE_THROWS_WITH(plate.check("L0_body", "(1,2)"),
                      Catch::Contains("not a 2-vector") && !Catch::Contains("decimal comma"));
  REQUIRE_THROWS_WITH(plate.check("L0_body", "(1, 2, 3, 4)"), !Catch::Contains("decimal comma"));
  // A second decimal point (a typo, an ellipsis) is said so, never dropped: 1.5.3 is not 1.53.
  REQUIRE_THROWS_WITH(plate.check("t_max", "0.1.6 s"),
                      Catch::Contains("the number \"0.1.6\" has more than one decimal point"));
  REQUIRE_THROWS_WITH(plate.check("t_max", "0.333..."),
                      Catch::Contains("the number \"0.333...\" has more than one decimal point"));
  REQUIRE_THROWS_WITH(plate.check("I", "[[m*R^2/4, 0, 0], [0, m*R^2/4, 0], [0, 0, 1.2.3]]"),
                      Catch::Contains("more than one decimal point"));
}

TEST_CASE("equal expressions in other forms are right, unequal ones wrong") {
  const Fixture plate("flying-plate");
  for (const std::string same :
       {"m*R^2/4", "(m/4)*R*R", "R^2*m*0.25", "m*R^2/2 - m*R^2/4", "(m*R^3 + m*R^2)/(4*(R + 1))",
        // A bracket against a factor, without a space, as books write a product.
        "2(m R^2)/8", "(1/4)m R^2", "(m)(R^2)/4", "m(R^2)/4", "(1/4)(m)(R^2)", "m(R+R)(R/8)"}) {
    INFO(same);
    const Verdict v = plate.check("I0", same);
    REQUIRE(v.correct);
    REQUIRE_THAT(v.line, Catch::Contains("simplifies to the key's"));
  }
  // Identities simplification cannot prove are judged by evaluation: atan(tan(alpha)/2) is
  // atan2(sin(alpha), 2 cos(alpha)) for alpha in [0, pi/2).
  for (const std::string same : {"atan(tan(alpha)/2)", "asin(sin(alpha)/sqrt(1+3*cos(alpha)^2))",
                                 "arctan(tan(α)/2)", "arcsin(sin(α)/√(1 + 3·cos²(α)))"}) {
    INFO(same);
    const Verdict v = plate.check("angle_L_e3", same);
    REQUIRE(v.correct);
    REQUIRE_THAT(v.line, Catch::Contains("three more points"));
  }
  REQUIRE(plate.check("Omega_space_rate", "omega*sqrt(4 - 3*sin(alpha)^2)").correct);
  // A factor outside a vector or matrix, as books write a common factor: before or after the
  // bracket, glued or spaced, in LaTeX, with a unit after.
  for (const auto& [name, same] : std::vector<std::pair<std::string, std::string>>{
           {"L0_body", "m R^2 omega/4 [sin(alpha), 0, 2 cos(alpha)]"},
           {"L0_body", "[sin(alpha), 0, 2*cos(alpha)]*m*R^2*omega/4"},
           {"L0_body", "(m R^2 omega/4)(sin(alpha), 0, 2 cos(alpha))"},
           // A symbol against the bracket, as a statement writes ω(sin α, 0, cos α): no call.
           {"L0_body", "m R²ω(sin α, 0, 2cos α)/4"},
           {"Omega_space", "ω(sin α, 0, 2 cos α) rad/s"},
           // A power against it: MATLAB's rows in parentheses, the factor glued.
           {"I", "mR²(1 0 0; 0 1 0; 0 0 2)/4"},
           {"L0_body", "2 (0.0009317485625, 0, 0.00695466595) kg m^2/s"},
           {"I", "m R^2/4 [[1, 0, 0], [0, 1, 0], [0, 0, 2]]"},
           {"I",
            "\\frac{m R^{2}}{4} \\begin{pmatrix} 1 & 0 & 0 \\\\ 0 & 1 & 0 \\\\ 0 & 0 & 2 "
            "\\end{pmatrix}"},
           {"I", "0.00072 [1 0 0; 0 1 0; 0 0 2] kg m²"}}) {
    INFO(name << " = " << same);
    REQUIRE(plate.check(name, same).correct);
  }
  // A sign alone before the bracket is its factor: -(..) is -1 (..).
  const Fixture box("box-corner");  // the centre of mass (a/2, b/2, c/2)
  for (const char* negated : {"-(-a, -b, -c)/2", "−(−a/2, −b/2, −c/2)", "-[-a, -b, -c]/2"}) {
    INFO(negated);
    REQUIRE(box.check("center_of_mass", negated).correct);
  }
  const Verdict reversed = box.check("center_of_mass", "-(a, b, c)/2");
  REQUIRE_FALSE(reversed.correct);
  REQUIRE_THAT(reversed.feedback.at(0), Catch::Contains("sign is reversed"));
  // Only a product: the rest must be a factor times the bracket.
  REQUIRE_FALSE(plate.check("I", "m R^2/2 [[1, 0, 0], [0, 1, 0], [0, 0, 2]]").correct);
  for (const std::string none :
       {"[sin(alpha), 0, 2 cos(alpha)]/4 + 1", "sqrt([1, 0, 2])", "2 [1, 0, 2] [1, 0, 2]",
        "1/[1, 0, 2]", "[1, 0, 2]^2", "2^[1, 0, 2]", "atan2(sin(alpha), 0, 2)"}) {
    INFO(none);
    REQUIRE_THROWS_AS(plate.check("L0_body", none), InputError);
  }
  // A symbol that spells a unit (m) ending an entry of symbols is a factor, as after a whole
  // answer, not the entry's metres.
  REQUIRE(
      plate.check("L0_body", "[R^2 omega sin(alpha) m/4, 0, R^2 omega cos(alpha)/2 m]").correct);
  REQUIRE_FALSE(plate.check("angle_L_e3", "atan(2*tan(alpha))").correct);
  for (const std::string other : {"m*R^2/4 + 1e-3*m", "m*R/4", "m^2*R^2/4", "R(m)/4", "2(m R)/8"}) {
    INFO(other);
    REQUIRE_FALSE(plate.check("I0", other).correct);
  }
  // Numbers against brackets too; a function's call stays a call.
  REQUIRE(plate.check("I0", "(1/4)(0.2)(0.12)^2").correct);
  REQUIRE(plate.check("angle_omega_e3", "(1)(alpha)").correct);
  REQUIRE_FALSE(plate.check("Omega_space_rate", "omega sqrt(4 - 3 sin(alpha)^2)(2)").correct);
  // A symbol against a bracket that still does not read is named as no function.
  REQUIRE_THROWS_WITH(plate.check("I0", "m(R^2"),
                      Catch::Contains("'m' is one of the problem's symbols, not a function"));
}

TEST_CASE("a key written with a parameter's value holds it there: the general form is right") {
  // At θ0 = 90° the heavy top's forms have cos θ0 = 0 written in (2 g l/(R² ψ̇0)): the lecture's
  // general form in cos(theta0) is right at this tilt, and so is the gyroscope's, without it.
  const Fixture horizontal("heavy-top", {"theta0=90deg"});
  REQUIRE(horizontal.key.held == std::vector<std::string>{"theta0"});
  for (const std::string same :
       {"2*M*g*l/(M R^2/2*psidot0 + sqrt((M R^2/2)^2 psidot0^2 - 4 (M R^2/4 + M l^2) M g l "
        "cos(theta0)))",
        "M g l/(M R^2/2 psidot0)", "2 g l/(R^2 ψ̇0) sin(θ0)"}) {
    INFO(same);
    REQUIRE(horizontal.check("phidot_slow", same).correct);
  }
  REQUIRE_FALSE(horizontal.check("phidot_slow", "g l/(R^2 psidot0)").correct);
  // At 30° nothing is held: the gyroscope's form is right nowhere but at 90°.
  const Fixture tilted("heavy-top");
  REQUIRE(tilted.key.held.empty());
  REQUIRE_FALSE(tilted.check("phidot_slow", "M g l/(M R^2/2 psidot0)").correct);
}

TEST_CASE("components along unit vectors read as a vector") {
  const Fixture plate("flying-plate");
  const std::vector<double>& key = plate.answer("L0_body").value.data;  // (x, 0, z)
  REQUIRE(key.at(1) == 0.0);
  const std::string x = fmt::format("{:.17g}", key.at(0)), z = fmt::format("{:.17g}", key.at(2));
  for (const std::string& same :
       {x + " i + " + z + " k", x + "i + " + z + "k", x + " î + " + z + " k̂",
        "(" + x + " x̂ + " + z + " ẑ) kg m²/s", z + " k + " + x + " i + 0 j",
        std::string("m R^2 omega sin(alpha)/4 i + m R^2 omega cos(alpha)/2 k"),
        std::string("i m R^2 omega sin(alpha)/4 + k m R^2 omega/2 cos(alpha)")}) {
    INFO(same);
    REQUIRE(plate.check("L0_body", same).correct);
  }
  REQUIRE_FALSE(plate.check("L0_body", x + " i - " + z + " k").correct);
  REQUIRE_FALSE(plate.check("L0_body", x + " j + " + z + " k").correct);
  // Not a sum of coefficients times unit vectors: named, with what to write instead.
  for (const std::string& none : {x + " i + 2", std::string("sin(i) + k"), std::string("2/i + k"),
                                  std::string("i*k"), x + " i^2 + k"}) {
    INFO(none);
    REQUIRE_THROWS_WITH(plate.check("L0_body", none),
                        Catch::Contains("cannot read the components along unit vectors") &&
                            Catch::Contains("[x, y, z]"));
  }
}

TEST_CASE(
    "a unit after the last unit vector is the sum's, after (or before) each, the component's") {
  const Fixture plate("flying-plate");
  const std::vector<double>& key = plate.answer("L0_body").value.data;  // (x, 0, z) kg m²/s
  const std::string x = fmt::format("{:.6g}", key.at(0)), z = fmt::format("{:.6g}", key.at(2));
  const std::string gram = fmt::format("{:.6g}", key.at(2) * 1e7);  // in g cm²/s
  for (const std::string& same :
       {x + " î + " + z + " k̂ kg m²/s", x + " e₁ + " + z + " e₃ kg m^2 s^-1",
        x + " î + " + z + " k̂ (kg m²/s)", x + " î kg m²/s + " + z + " k̂ kg m²/s",
        // m is the mass, and after the symbols a factor; kg m²/s is a unit all the same.
        std::string("(m R² ω sin α/4) e₁ + (m R² ω cos α/2) e₃ kg m²/s"),
        // the first coefficient in brackets is no "(sum) unit"
        std::string("(m R² ω sin α/4) e₁ + (m R² ω cos α/2) e₃"),
        // and in LaTeX, the unit in \mathrm or \text, brackets sized by \left \right
        x + "\\,\\hat{x} + " + z + "\\,\\hat{z}\\ \\mathrm{kg\\,m^{2}/s}",
        x + "\\,\\mathbf{i}\\,\\text{kg m^2/s} + " + z + "\\,\\mathbf{k}\\,\\text{kg m^2/s}",
        "\\left(" + x + " \\hat{e}_1 + " + z + " \\hat{e}_3\\right) \\mathrm{kg\\,m^2\\,s^{-1}}",
        // before each unit vector, as "F = 5 N x̂" is written; in LaTeX and siunitx too
        x + " kg m²/s î + " + z + " kg m²/s k̂", x + " kg m^2 s^-1 e₁ + " + z + " kg m^2 s^-1 e₃",
        x + "\\,\\mathrm{kg\\,m^2/s}\\,\\hat{x} + " + z + "\\,\\mathrm{kg\\,m^2/s}\\,\\hat{z}",
        "\\qty{" + x + "}{kg.m^2/s}\\,\\hat{x} + \\qty{" + z + "}{kg.m^2/s}\\,\\hat{z}"}) {
    INFO(same);
    REQUIRE(plate.check("L0_body", same).correct);
  }
  // The unit is the whole sum's: in g cm²/s only the z component is right.
  REQUIRE_FALSE(plate.check("L0_body", x + " î + " + gram + " k̂ g cm²/s").correct);
  REQUIRE_FALSE(plate.check("L0_body", x + " î - " + z + " k̂ kg m²/s").correct);
  REQUIRE_FALSE(plate.check("L0_body", x + " kg m²/s î - " + z + " kg m²/s k̂").correct);
  // Each component in a unit of its own.
  REQUIRE(plate.check("L0_body", x + " kg m²/s î + " + gram + " g cm²/s k̂").correct);
  REQUIRE_FALSE(plate.check("L0_body", x + " kg m²/s î + " + z + " g cm²/s k̂").correct);
  // After some terms but not the last, twice, or inside and outside brackets: refused.
  for (const std::string& none :
       {x + " î kg m²/s + " + z + " k̂", x + " î + " + z + " k̂ kg m²/s + 0 k̂ kg m²/s",
        "(" + x + " î + " + z + " k̂ kg m²/s) kg m²/s", x + " kg m²/s î + " + z + " k̂",
        x + " kg m²/s î + " + z + " kg m²/s k̂ kg m²/s"}) {
    INFO(none);
    REQUIRE_THROWS_WITH(plate.check("L0_body", none),
                        Catch::Contains("cannot read the components along unit vectors (î, k̂)"));
  }
  // m after an expression in the symbols is the mass, a factor: the wrong dimension's value.
  REQUIRE_FALSE(plate.check("L0_body", "m R² ω sin α/4 e₁ + m R² ω cos α/2 e₃ m").correct);
}

TEST_CASE("a matrix answered as an earlier one transposed, R_zyzᵀ, reads in every spelling") {
  // PHY 711's R(α, β, γ) acts on components: it is Taylor's R transposed, as the steps say.
  const Fixture phy711("euler-angles-phy711");
  const std::string note =
      "read with R_zyz as the key's answer to part (a): right as far as your R_zyz is";
  for (const char* same : {"R_zyz^T", "R_zyzᵀ", "(R_zyz)ᵀ", "R_zyz'", "transpose(R_zyz)",
                           "np.transpose(R_zyz)", "R_phy711 = R_zyz^T"}) {
    INFO(same);
    const auto v = phy711.check("R_phy711", same);
    REQUIRE(v.correct);
    REQUIRE(v.feedback == std::vector<std::string>{note});
  }
  // Untransposed it is the other matrix, and said so.
  const auto untransposed = phy711.check("R_phy711", "R_zyz");
  REQUIRE_FALSE(untransposed.correct);
  REQUIRE_THAT(untransposed.feedback.front(), Catch::Contains("this is R_zyz (part a)"));
  // A matrix of numbers transposed by a call, or in round brackets before its mark, as MATLAB,
  // NumPy and Mathematica write it.
  const std::string zyz = typed(phy711.answer("R_zyz").value);  // "[[..], [..], [..]]"
  for (const std::string& same : {"transpose(" + zyz + ")", "Transpose[" + zyz + "]",
                                  "(" + zyz + ")ᵀ", "((" + zyz + "))^T"}) {
    INFO(same);
    REQUIRE(phy711.check("R_phy711", same).correct);
    REQUIRE_FALSE(phy711.check("R_zyz", same).correct);
  }
  // A name that is no answer, transposed, is refused as that name.
  REQUIRE_THROWS_WITH(phy711.check("R_phy711", "Qᵀ"), Catch::Contains("undefined symbol 'Q'"));
  // transpose of a number is no transpose: the function is refused as unknown.
  REQUIRE_THROWS_WITH(phy711.check("kinetic_energy", "transpose(2)"),
                      Catch::Contains("unknown function 'transpose'"));
}

TEST_CASE("angle brackets write a vector; a transpose mark transposes a matrix") {
  const Fixture euler("euler-angles");
  const Answer& zyz = euler.answer("R_zyz");
  const Answer& phy711 = euler.answer("R_phy711");  // R_zyz transposed
  const std::string transposed = typed(phy711.value);
  REQUIRE_FALSE(euler.check("R_zyz", transposed).correct);
  for (const std::string mark : {"ᵀ", "^T", "^{T}", "'"}) {
    INFO(mark);
    REQUIRE(euler.check("R_zyz", transposed + mark).correct);
    REQUIRE_FALSE(euler.check("R_zyz", typed(zyz.value) + mark).correct);
  }
  const Fixture box("box-corner");
  const std::string com = typed(box.answer("center_of_mass").value);  // "[x, y, z]"
  const std::string inside = com.substr(1, com.size() - 2);
  std::string with_ampersands = inside;
  for (auto at = with_ampersands.find(','); at != std::string::npos; at = with_ampersands.find(','))
    with_ampersands.replace(at, 1, " &");
  std::string with_semicolons = inside;  // a column, as MATLAB's [x; y; z] and in parentheses
  std::replace(with_semicolons.begin(), with_semicolons.end(), ',', ';');
  for (const std::string& same :
       {"<" + inside + ">", "⟨" + inside + "⟩", "〈" + inside + "〉 m", "[" + inside + "]ᵀ",
        "[" + with_semicolons + "]", "(" + with_semicolons + ") m", "(" + inside + ")^T m",
        // LaTeX's row vector, transposed
        "\\begin{pmatrix}" + with_ampersands + "\\end{pmatrix}^{\\top}"}) {
    INFO(same);
    REQUIRE(box.check("center_of_mass", same).correct);
  }
}

namespace {
// The entries of a value text, each rewritten by `f`, back in brackets.
std::string rewritten(const sym::ValueText& v,
                      const std::function<std::string(const GiNaC::ex&)>& f) {
  if (!v.is_vector && !v.is_matrix) return f(v.entries[0]);
  std::string s = "[";
  for (std::size_t r = 0; r < v.rows; ++r) {
    if (v.is_matrix) s += r ? ", [" : "[";
    for (std::size_t c = 0; c < v.cols; ++c) {
      s += (c || (!v.is_matrix && r) ? ", " : "") + f(v.entries[r * v.cols + c]);
    }
    if (v.is_matrix) s += "]";
  }
  return s + "]";
}
std::string ginac_text(const GiNaC::ex& e) {
  std::ostringstream o;
  o << e;
  return o.str();
}
}  // namespace

TEST_CASE("every closed form of every problem: other forms of it right, look-alikes wrong") {
  int equal = 0, lookalike = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.symbolic.empty()) continue;
        const sym::ValueText v = sym::parse_value_text(a.symbolic, f.table, a.name);
        INFO(p.id << " " << a.name << ": " << a.symbolic);
        // The same expression expanded, in GiNaC's own order and spelling: right.
        const std::string expanded =
            rewritten(v, [](const GiNaC::ex& e) { return ginac_text(GiNaC::expand(e)); });
        INFO("expanded: " << expanded);
        REQUIRE(f.check(a.name, expanded).correct);
        ++equal;
        // Equal at the set values but not elsewhere: each entry times (P / its value) for a
        // parameter P the answer depends on. Only the other points can tell: wrong.
        std::string param;
        for (const auto& name : f.table.names()) {
          bool used = false;
          for (const auto& e : v.entries) used = used || e.has(f.table.at(name));
          if (used && f.values.at(name) != 0.0) param = name;
        }
        if (param.empty()) continue;
        const std::string factor = fmt::format("*({}/{:.17g})", param, f.values.at(param));
        const std::string lookalike_text =
            rewritten(v, [&](const GiNaC::ex& e) { return "(" + ginac_text(e) + ")" + factor; });
        INFO("look-alike: " << lookalike_text);
        const bool all_zero = std::all_of(a.value.data.begin(), a.value.data.end(),
                                          [](double x) { return x == 0.0; });
        // Axes are judged by direction, so a look-alike that only scales them is right.
        if (all_zero || a.name.rfind("principal_axes", 0) == 0) continue;
        REQUIRE_FALSE(f.check(a.name, lookalike_text).correct);
        ++lookalike;
      }
    }
  }
  REQUIRE(equal >= 50);
  REQUIRE(lookalike >= 40);
}

TEST_CASE("answers too large to simplify are judged by evaluation (fuzzing: 44 s, out of memory)") {
  const Fixture plate("flying-plate");
  // Many powers with symbolic exponents: normal() grew without bound on these (the fuzzer's
  // own spelling, R^++++R, is refused now: a signed exponent needs parentheses).
  REQUIRE_THROWS_AS(plate.check("I0", "m*R^++++R+m*R^++++R"), InputError);
  const Verdict v =
      plate.check("I0", "m*R^R+m*R^(2*R)+m*R^(3*R)+m*R^(4*R)+m*R^(5*R)+m*R^(6*R)+m*R^(7*R)");
  REQUIRE_FALSE(v.correct);
  REQUIRE_THAT(v.line, Catch::Contains("differs from the key's"));
  // An equal form with many symbolic powers is still right, by evaluation.
  const Verdict same = plate.check("I0", "m*R^2/4 + (2^m - 2^m) + (R^m - R^m) + (3^R - 3^R)");
  REQUIRE(same.correct);
}

TEST_CASE("axes of a degenerate pair: any orthonormal pair of the plane is right") {
  const std::string file =
      wobble::test::write_file("check/degenerate.toml", R"TOML(id = "degenerate"
title = "t"
solver = "inertia"
statement = "s"

[[parameters]]
name = "k"
unit = "kg m^2"
default = 1
range = "(0, inf)"

[body]
tensor = [["2*k", "0", "0"], ["0", "2*k", "0"], ["0", "0", "3*k"]]

[[parts]]
id = "a"
question = "q"
answers = ["principal_moments", "principal_axes"]
)TOML")
          .string();
  const Fixture f(file);
  // Turned by an arbitrary angle in the x-y plane, signs of our own choosing: right.
  REQUIRE(f.check("principal_axes", "[[0.6, -0.8, 0], [0.8, 0.6, 0], [0, 0, 1]]").correct);
  REQUIRE(f.check("principal_axes", "[[0, 1, 0], [1, 0, 0], [0, 0, -1]]").correct);
  // A column out of the plane: wrong.
  REQUIRE_FALSE(
      f.check("principal_axes", "[[0.6, -0.8, 0], [0, 0.6, 0.8], [0.8, 0, 0.6]]").correct);
}

TEST_CASE("a problem file's per-answer tolerance, and the user's overriding it") {
  const std::string file = wobble::test::write_file("check/tolerant.toml", R"TOML(id = "tolerant"
title = "t"
solver = "inertia"
statement = "s"

[[parameters]]
name = "m"
unit = "kg"
default = 1
range = "(0, inf)"

[body]
masses = [ { mass = "m", at = ["1", "0", "0"] }, { mass = "m", at = ["0", "1", "0"] } ]

[[parts]]
id = "a"
question = "q"
answers = [ { name = "I", quantity = "I", tolerance = 0.1 } ]
)TOML")
                               .string();
  const Fixture f(file);
  const std::string five_percent_off = "[[1.05, 0, 0], [0, 1.05, 0], [0, 0, 2.1]]";
  REQUIRE(f.check("I", "[[1, 0, 0], [0, 1, 0], [0, 0, 2]]").correct);
  REQUIRE(f.check("I", five_percent_off).correct);  // within the file's 10%
  Options strict;
  strict.rel_tol = 0.01;
  strict.rel_tol_given = true;
  REQUIRE_FALSE(f.check("I", five_percent_off, strict).correct);  // the user's 1% wins
}

TEST_CASE("the diagnosis table: each known mistake is named by the value that makes it") {
  using wobble::check::Finding;
  Answer rate;
  rate.name = "Omega_body_rate";
  rate.kind = AnswerKind::rate;
  rate.sign = SignConvention::sense_of_precession;
  rate.unit = "rad/s";
  rate.value = Value::scalar(-2.0);
  Answer L_body, L_space;
  L_body.name = "L0_body";
  L_body.frame = AnswerFrame::body;
  L_space.name = "L0_space";
  L_space.frame = AnswerFrame::space;
  for (Answer* a : {&L_body, &L_space}) {
    a->kind = AnswerKind::vector;
    a->unit = "kg m^2/s";
  }
  L_body.value = Value::vector({1.0, 0.0, 3.0});
  L_space.value = Value::vector({2.0, 0.5, 2.5});
  Answer I;
  I.name = "I";
  I.kind = AnswerKind::tensor;
  I.unit = "kg m^2";
  I.value = Value::matrix(3, 3, {2, -1, 0, -1, 2, 0, 0, 0, 3});
  Answer space_rate;
  space_rate.name = "Omega_space_rate";
  space_rate.kind = AnswerKind::rate;
  space_rate.unit = "rad/s";
  space_rate.value = Value::scalar(3.0);
  Key key;
  key.parts.push_back({"a", "?", {rate, L_body, L_space, I, space_rate}, {}, {}, {}, {}});
  const auto close = [](double v, double k) { return std::abs(v - k) <= 0.01 * std::abs(k) + 1e-12; };
  const auto first = [&](const Answer& a, std::vector<double> typed, const std::string& unit) {
    const Unit u = unit.empty() ? Unit{} : parse_unit(unit, "unit");  // "": a pure number
    const Finding f{a, key, std::move(typed), a.value.data, u, close, 1.0};
    return wobble::check::diagnose(f).at(0);
  };
  CHECK_THAT(first(key.parts[0].answers[3], {2, 1, 0, 1, 2, 0, 0, 0, 3}, "kg m^2"),
             Catch::Contains("products of inertia have the wrong sign"));
  CHECK_THAT(first(key.parts[0].answers[0], {2.0}, "rad/s"),
             Catch::Contains("the size is right but not the sign") &&
                 Catch::Contains("against the spin"));
  CHECK_THAT(first(key.parts[0].answers[0], {-2.0 / (2 * M_PI)}, "rad/s"),
             Catch::Contains("revolutions per second"));
  CHECK_THAT(first(key.parts[0].answers[0], {-4 * M_PI}, "rad/s"), Catch::Contains("2π times"));
  CHECK_THAT(first(key.parts[0].answers[0], {-2.0 * 180 / M_PI}, "rad/s"),
             Catch::StartsWith("this is the rate in degrees per second"));
  CHECK_THAT(first(key.parts[0].answers[0], {-2.0 * 60 / (2 * M_PI)}, "rad/s"),
             Catch::StartsWith("this is revolutions per minute"));
  // A growth rate (1/s) turns no degrees: 57.3 times it is only that.
  Answer growth = rate;
  growth.unit = "1/s";
  growth.sign = SignConvention::none;
  CHECK_THAT(first(growth, {-2.0 * 180 / M_PI}, "1/s"), Catch::Equals("57.3 times the answer"));
  CHECK_THAT(first(key.parts[0].answers[0], {3.0}, "rad/s"),
             Catch::Contains("this is Omega_space_rate (part a), not Omega_body_rate"));
  CHECK_THAT(first(key.parts[0].answers[2], {1.0, 0.0, 3.0}, "kg m^2/s"),
             Catch::Contains("these are the body-frame components (L0_body)") &&
                 Catch::Contains("L0_space asks for the space-frame ones"));
  CHECK_THAT(first(key.parts[0].answers[1], {2.0, 0.0, 6.0}, "kg m^2/s"),
             Catch::Contains("2 times the answer"));
  CHECK_THAT(first(key.parts[0].answers[1], {1.0, 0.0, 3.3}, "kg m^2/s"),
             Catch::Contains("entry e₃ is off by 10%"));  // body frame: along e₁, e₂, e₃
  // Zeros for a vector that is not zero: one line, not each entry off by 100%.
  CHECK_THAT(first(key.parts[0].answers[1], {0.0, 0.0, 0.0}, "kg m^2/s"),
             Catch::Equals("every entry is zero; the answer is not"));
  CHECK_THAT(first(key.parts[0].answers[2], {2.0, 0.5, 2.75}, "kg m^2/s"),
             Catch::Equals("entry z is off by 10%"));  // the fixed axes: x, y, z
  // Entries the question names (c₁, c₂, c₃ of Euler's equations) are named so.
  Answer named = L_space;
  named.named_entries = {"c₁", "c₂", "c₃"};
  CHECK_THAT(first(named, {2.0, 0.5, 2.75}, "kg m^2/s"), Catch::Equals("c₃ is off by 10%"));
  CHECK_THAT(first(named, {0.5, 2.0, 2.5}, "kg m^2/s"), Catch::Contains("c₁ and c₂ are swapped"));
  Answer angle;
  angle.name = "alpha";
  angle.kind = AnswerKind::angle;
  angle.unit = "rad";
  angle.value = Value::scalar(0.5);
  CHECK_THAT(first(angle, {0.5 * 180 / M_PI}, "rad"), Catch::Contains("in degrees"));
  // 720 g cm² for 7200 g cm²: a unit converted the wrong way.
  CHECK_THAT(first(I, {0.2, -0.1, 0, -0.1, 0.2, 0, 0, 0, 0.3}, "kg m^2"),
             Catch::Contains("1/10 of the answer: a power of ten is off") &&
                 Catch::Contains("1 g cm² = 10⁻⁷ kg m²"));
  CHECK_THAT(first(space_rate, {3e7}, "rad/s"),
             Catch::Contains("10^7 times the answer: a power of ten is off (a prefix, or a "
                             "unit converted the wrong way?)"));
  // Far off and no power of ten: a ratio, not a percentage of many digits.
  CHECK_THAT(first(space_rate, {3e10}, "rad/s"), Catch::Equals("1e+10 times the answer"));
  CHECK_THAT(first(space_rate, {-924.0}, "rad/s"), Catch::Equals("-308 times the answer"));
  CHECK_THAT(first(space_rate, {0.0369}, "rad/s"), Catch::Equals("0.0123 times the answer"));
  // Nearer than a factor of 10, a percentage.
  CHECK_THAT(first(space_rate, {26.7}, "rad/s"), Catch::Equals("off by 790% of the answer"));
  CHECK_THAT(first(space_rate, {0.35}, "rad/s"), Catch::Equals("off by 88.3% of the answer"));
  CHECK_THAT(first(space_rate, {3e-9}, "rad/s"), Catch::Contains("1/10^9 of the answer"));
  // One entry a power of ten off and the others right is no such mistake.
  CHECK_THAT(first(key.parts[0].answers[1], {10.0, 0.0, 3.0}, "kg m^2/s"),
             Catch::Equals("entry e₁ is 10 times its right value"));
  CHECK_THAT(first(key.parts[0].answers[1], {1.0, 0.0, 25.0}, "kg m^2/s"),
             Catch::Equals("entry e₃ is off by 733%"));
  // One entry's sign turned: said so, not "off by 200%"; a zero entry has no sign to turn.
  CHECK_THAT(first(key.parts[0].answers[1], {-1.0, 0.0, 3.0}, "kg m^2/s"),
             Catch::Equals("entry e₁ has the wrong sign"));
  CHECK_THAT(first(key.parts[0].answers[1], {-1.0, 0.0, 3.3}, "kg m^2/s"),
             Catch::Equals("entry e₁ has the wrong sign"));  // and entry e₃, off by 10%, next
  CHECK_THAT(first(key.parts[0].answers[1], {1.0, -0.5, 3.0}, "kg m^2/s"),
             !Catch::Contains("sign"));
  // The right entries in other places: swapped, in a cycle, a matrix transposed.
  CHECK_THAT(first(key.parts[0].answers[2], {2.5, 0.5, 2.0}, "kg m^2/s"),
             Catch::Equals("the right entries in another order: entry x and entry z are swapped"));
  CHECK_THAT(first(key.parts[0].answers[2], {0.5, 2.5, 2.0}, "kg m^2/s"),
             Catch::Equals("the right entries in another order (the axes relabelled?)"));
  Answer R;
  R.name = "R";
  R.kind = AnswerKind::matrix;
  R.value = Value::matrix(3, 3, {0, -1, 0, 1, 0, 0, 0, 0, 1});  // a quarter turn about z
  CHECK_THAT(first(R, {0, 1, 0, -1, 0, 0, 0, 0, 1}, ""),
             Catch::StartsWith("this is the transpose of the answer"));
  CHECK_THAT(first(R, {0, 1, 0, -1, 0, 0, 0, 0, -1}, ""), !Catch::Contains("transpose"));
  // Its off-diagonal signs turned are no products of inertia.
  CHECK_THAT(first(R, {0, 1, 0, -1, 0, 0, 0, 0, 1}, ""), !Catch::Contains("inertia"));
  // An approximation a course teaches, given for the exact value: named, with how far off.
  Answer slow;
  slow.name = "phidot_slow";
  slow.kind = AnswerKind::rate;
  slow.unit = "rad/s";
  slow.value = Value::scalar(5.0);
  slow.approximations.push_back({"the approximation A", "the rate is B", {4.0}});
  CHECK_THAT(first(slow, {4.0}, "rad/s"),
             Catch::Equals("this is the approximation A, 20% below the exact value here: the rate "
                           "is B"));
  CHECK_THAT(first(slow, {4.5}, "rad/s"), Catch::Equals("off by 10% of the answer"));
  // The other quantity's number in the key's unit, as a quiz takes it: 1/x or 2π/x is right.
  CHECK_THAT(first(space_rate, {1.0 / 3}, "rad/s"),
             Catch::Equals("1/0.3333 = 3 rad/s is the answer: a time given for the rate (its "
                           "reciprocal)?"));
  CHECK_THAT(first(space_rate, {2 * M_PI / 3}, "rad/s"),
             Catch::Equals("2π/2.094 = 3 rad/s is the answer: the period given for the rate?"));
  REQUIRE(wobble::check::known_mistakes().size() == 13);
}

TEST_CASE("the heavy top's fast-top approximations are named where given for the exact rates") {
  const Fixture top("heavy-top");
  const auto parameter = [&](const std::string& name) {
    for (const auto& p : top.key.parameters)
      if (p.name == name) return p.value;
    throw std::logic_error(name);
  };
  // From the parameters, apart from the solver: a disc about its axle, spinning at ψ̇₀ (φ̇₀ = 0
  // at the defaults, so ω₃ = ψ̇₀), its centre l from the pivot.
  REQUIRE(parameter("phidot0") == 0.0);
  const double M = parameter("M"), R = parameter("R"), l = parameter("l"), g = parameter("g");
  const double I3 = M * R * R / 2, I1 = M * R * R / 4 + M * l * l, w3 = parameter("psidot0");
  const double slow = M * g * l / (I3 * w3), fast = I3 * w3 / (I1 * std::cos(parameter("theta0")));
  // Typed to four digits, as a student's calculator gives them.
  const Verdict slow_given = top.check("phidot_slow", fmt::format("{:.4g} rad/s", slow));
  REQUIRE_FALSE(slow_given.correct);
  REQUIRE_THAT(slow_given.feedback.at(0),
               Catch::StartsWith("this is the fast-top approximation M g l / (I3 ω3), 16.2% "
                                 "below the exact value here") &&
                   Catch::Contains("nearer zero"));
  const Verdict fast_given = top.check("phidot_fast", fmt::format("{:.4g} rad/s", fast));
  REQUIRE_FALSE(fast_given.correct);
  REQUIRE_THAT(fast_given.feedback.at(0),
               Catch::StartsWith("this is the fast-top approximation I3 ω3 / (I1 cos θ), 19.3% "
                                 "above the exact value here") &&
                   Catch::Contains("farther from zero"));
  // The key's notes give the same approximations, to the digits they print.
  const auto notes = [&](const std::string& name) {
    for (const auto& p : top.key.parts)
      for (const auto& a : p.answers)
        if (a.name == name) return fmt::format("{}", fmt::join(a.notes, " "));
    throw std::logic_error(name);
  };
  REQUIRE_THAT(notes("phidot_slow"),
               Catch::Contains(fmt::format("{:.4g} rad/s, 16.2% below", slow)));
  REQUIRE_THAT(notes("phidot_fast"),
               Catch::Contains(fmt::format("{:.4g} rad/s, 19.3% above", fast)));
  // Each rate's approximation given for the other rate: the one it approximates is named.
  const Verdict fast_for_slow = top.check("phidot_slow", fmt::format("{:.4g} rad/s", fast));
  REQUIRE_FALSE(fast_for_slow.correct);
  CHECK(fast_for_slow.feedback.at(0) ==
        "this is the fast-top approximation I3 ω3 / (I1 cos θ) of phidot_fast (part d), not "
        "phidot_slow");
  const Verdict slow_for_fast = top.check("phidot_fast", "M g l/(I3 omega3)");
  REQUIRE_FALSE(slow_for_fast.correct);
  CHECK(slow_for_fast.feedback.at(0) ==
        "this is the fast-top approximation M g l / (I3 ω3) of phidot_slow (part d), not "
        "phidot_fast");
}

TEST_CASE("a value the problem file names as a mistake is named when given as the file writes it") {
  int named = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : p.parts) {
      for (const auto& spec : part.answers) {
        for (const auto& m : spec.mistakes) {
          // As the file writes it, and as a student may: "433 days" for "433 day"; one in the
          // problem's parameters (the flying plate's "m*R^2/2") as an expression and as its
          // value, in the answer's unit.
          const Answer& a = f.answer(spec.name);
          REQUIRE(a.approximations.size() == spec.mistakes.size());
          bool constant = false;  // a value with its unit, which reads as no expression
          try {
            (void)p.symbol_table().parse(m.value, "value");
          } catch (const InputError&) {
            constant = true;
          }
          const std::string value = fmt::format(
              "{:.10g} {}", a.approximations[&m - spec.mistakes.data()].values.at(0), a.unit);
          for (const std::string& typed :
               constant ? std::vector{m.value, m.value + "s"} : std::vector{m.value, value}) {
            INFO(p.id << " " << spec.name << ": " << typed);
            const Verdict v = f.check(spec.name, typed);
            REQUIRE_FALSE(v.correct);
            REQUIRE_THAT(v.feedback.at(0), Catch::StartsWith("this is " + m.what + ", ") &&
                                               Catch::Contains("the answer here: " + m.remedy));
            ++named;
          }
        }
      }
    }
  }
  REQUIRE(named >= 6);  // the Earth's observed wobble (a period, a rate); the plate's I₃ for I₀
  // The Earth's: 433 days against the rigid Earth's 303.6 days is 42.6% above, read in days.
  const Fixture earth("earth-free-precession");
  const double days = earth.answer("precession_period_body").value.data.at(0) / 86400;
  const Verdict chandler = earth.check("precession_period_body", "433 d");
  REQUIRE_THAT(chandler.feedback.at(0),
               Catch::Contains(fmt::format("{:.3g}% above the answer", 100 * (433 / days - 1))));
}

namespace {
// A submission's answer by its name.
const SubmittedAnswer& submitted(const SubmissionResult& r, const std::string& name) {
  for (const auto& s : r.answers) {
    if (s.name == name) return s;
  }
  throw std::logic_error("no answer " + name);
}
}  // namespace

TEST_CASE(
    "a submission names answers as written, in LaTeX too; a second line and a stray name are "
    "reported") {
  const Fixture plate("flying-plate");
  const std::string text =
      "# the flying plate\n"
      "I_0 = \\frac{m R^{2}}{4}\n"  // as a LaTeX handout sets the name
      "L_{0,\\mathrm{body}}: [m*R^2*omega*sin(alpha)/4, 0, m*R^2*omega*cos(alpha)/2]\n"
      "I0 = m*R^2/2\n"  // I0 again: the first line is judged
      "Omega: 3\n"
      "t_max = [1, 2\n";
  const SubmissionResult r = judge_submission({plate.key, plate.table, plate.values}, text, {});
  const auto verdict = [&](const std::string& name) { return submitted(r, name).verdict; };
  REQUIRE(verdict("I0").correct);
  REQUIRE(verdict("L0_body").correct);
  REQUIRE_FALSE(verdict("I").correct);  // not answered
  REQUIRE_THAT(verdict("I").line, Catch::Equals("incorrect: I is not answered"));
  // Unreadable: wrong, but named apart from a wrong value, with its line.
  REQUIRE_FALSE(verdict("t_max").correct);
  REQUIRE_THAT(verdict("t_max").line, Catch::StartsWith("unreadable: t_max (line 6): "));
  REQUIRE(r.problems.size() == 2);
  REQUIRE_THAT(r.problems, Catch::VectorContains(
                               std::string("line 4: 'I0' answers I0 again (the first is judged)")));
  REQUIRE_THAT(r.problems[0] + r.problems[1],
               Catch::Contains("line 5: 'Omega' is no answer of this problem (answers: I0, I, "));
}

TEST_CASE(
    "a submission names answers as check does: by the steps' names, a prime apart, '≈' for '='; "
    "its problems in line order") {
  const Fixture top("heavy-top");
  const Context ctx{top.key, top.table, top.values};
  const auto value = [&](const std::string& name) {
    return fmt::format("{:.10g}", top.answer(name).value.data.at(0));
  };
  const std::string text =
      "zz = 1\n"
      "E = " +
      value("energy") + " J\n" +                  // the steps' E
      "E′ = " + value("energy_prime") + " J\n" +  // the question's E′
      "energy = 1 J\n"                            // E's answer again
      "aa = 2\n"
      "φ̇_slow ≈ " +
      value("phidot_slow") + " rad/s\n";
  const SubmissionResult r = judge_submission(ctx, text, {});
  const auto verdict = [&](const std::string& name) { return submitted(r, name).verdict; };
  REQUIRE(verdict("energy").correct);
  REQUIRE(verdict("energy_prime").correct);
  REQUIRE(verdict("phidot_slow").correct);
  REQUIRE(r.problems.size() == 3);
  REQUIRE_THAT(r.problems[0], Catch::StartsWith("line 1: 'zz' is no answer"));
  REQUIRE(r.problems[1] == "line 4: 'energy' answers energy again (the first is judged)");
  REQUIRE_THAT(r.problems[2], Catch::StartsWith("line 5: 'aa' is no answer"));
}

TEST_CASE("a submission's line of Euler's equations answers their coefficients") {
  const Fixture top("asymmetric-top");
  const SubmissionResult r =
      judge_submission({top.key, top.table, top.values},
                       "dω₁/dt = -0.5 ω₂ω₃, dω₂/dt = 0.7 ω₃ω₁, dω₃/dt = -0.25 ω₁ω₂\n"
                       "dω/dt = (-0.5, 1, -0.015) rad/s²\n",
                       {});
  REQUIRE(r.problems.empty());
  REQUIRE(r.answers.at(0).name == "euler_coefficients");
  REQUIRE(r.answers[0].verdict.line == "incorrect: euler_coefficients");
  REQUIRE(r.answers[0].verdict.feedback.at(0) == "c₂ is off by 5%");
  REQUIRE(r.answers.at(1).name == "dw_dt0");
  REQUIRE(r.answers[1].verdict.correct);
}

TEST_CASE("a submission's comments, part headings and part marks name no answer") {
  const Fixture plate("flying-plate");
  const std::string i0 = fmt::format("{:.6g}", plate.answer("I0").value.data[0]);
  const double angle = plate.answer("angle_omega_e3").value.data[0] * 180 / M_PI;
  const std::string text =
      "Part a:\n"
      "I0 = " +
      i0 +
      " kg m^2   # from the table\n"
      "(b)\n"
      "% a MATLAB comment line\n"
      "(c) angle_omega_e3 = " +
      fmt::format("{:.6g}", angle) +
      " deg; % read\n"
      "c) angle_L_e3 = 3 rad\n"
      "part (d).\n"
      "Omega_body_rate [rad/s] = 1\n";  // the worksheet's prompt pasted, its unit shown
  const SubmissionResult r = judge_submission({plate.key, plate.table, plate.values}, text, {});
  const auto verdict = [&](const std::string& name) { return submitted(r, name); };
  INFO(fmt::format("{}", fmt::join(r.problems, "; ")));
  REQUIRE(r.problems.empty());  // no heading or comment taken for a name
  REQUIRE(verdict("I0").verdict.correct);
  REQUIRE(verdict("angle_omega_e3").verdict.correct);
  REQUIRE(verdict("angle_L_e3").answered);
  REQUIRE_FALSE(verdict("angle_L_e3").verdict.correct);  // 3 rad is not the key's
  REQUIRE_FALSE(verdict("L0_body").answered);
  REQUIRE(verdict("Omega_body_rate").answered);
  // A '%' right after a number is no comment: "5%" is read, and refused.
  const SubmissionResult percent =
      judge_submission({plate.key, plate.table, plate.values}, "I0 = 5%\n", {});
  REQUIRE_FALSE(percent.answers.at(0).verdict.correct);
  REQUIRE_THAT(percent.answers.at(0).verdict.line, Catch::StartsWith("unreadable: I0"));
}

namespace {
// `text` (ASCII) as UTF-16 with its byte-order mark, little- or big-endian.
std::string utf16(const std::string& text, bool little_endian) {
  std::string out = little_endian ? "\xff\xfe" : "\xfe\xff";
  for (const char c : text) {
    out += little_endian ? std::string{c, '\0'} : std::string{'\0', c};
  }
  return out;
}
}  // namespace

TEST_CASE("a submission is read as an editor saved it: UTF-16, a UTF-8 mark, CR LF or lone CR") {
  const Fixture plate("flying-plate");
  const std::string i0 = fmt::format("{:.6g}", plate.answer("I0").value.data[0]);
  const std::string lines = "I0 = " + i0 + " kg m^2\nangle_L_e3 = 3 rad\n";
  const auto crlf = [](std::string t) {
    for (std::size_t at = t.find('\n'); at != std::string::npos; at = t.find('\n', at + 2))
      t.replace(at, 1, "\r\n");
    return t;
  };
  std::string lone_cr = lines;
  std::replace(lone_cr.begin(), lone_cr.end(), '\n', '\r');
  for (const std::string& text : {lines, utf16(crlf(lines), true), utf16(lines, false),
                                  "\xef\xbb\xbf" + crlf(lines), lone_cr}) {
    const SubmissionResult r = judge_submission({plate.key, plate.table, plate.values}, text, {});
    INFO(fmt::format("{}", fmt::join(r.problems, "; ")));
    REQUIRE(r.problems.empty());
    REQUIRE(submitted(r, "I0").verdict.correct);
    REQUIRE(submitted(r, "angle_L_e3").answered);
    REQUIRE_FALSE(submitted(r, "angle_L_e3").verdict.correct);
  }
  // UTF-16 without its mark, and a file cut in the middle of a character: said, not misread.
  const auto refusal = [&](const std::string& text) -> std::string {
    try {
      (void)judge_submission({plate.key, plate.table, plate.values}, text, {});
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  CHECK_THAT(refusal(utf16(lines, true).substr(2)),
             Catch::Equals("--answers: the file holds a NUL byte (at byte 1): it is not text, or "
                           "UTF-16 without its mark; save it as UTF-8"));
  CHECK_THAT(refusal(utf16(lines, true) + "\x3d"),
             Catch::StartsWith("--answers: the file starts as UTF-16 but breaks off at byte "));
}

TEST_CASE("a submission's matrix over several lines, as NumPy prints one, is one answer") {
  const Fixture box("box-corner");
  const auto& m = box.answer("I_corner").value.data;  // kg m^2, row-major
  std::string rows;
  for (int r = 0; r < 3; ++r) {
    rows += fmt::format("{}[{:.8f} {:.8f} {:.8f}]{}\n", r == 0 ? "[" : " ", m[3 * r], m[3 * r + 1],
                        m[3 * r + 2], r == 2 ? "]" : "");
  }
  const auto judged = [&](const std::string& text) {
    return judge_submission({box.key, box.table, box.values}, text, {});
  };
  const SubmissionResult r =
      judged("I_corner = " + rows + "  # NumPy's print\ncenter_of_mass = (0.5, 1, 1.5) m\n");
  INFO(fmt::format("{}", fmt::join(r.problems, "; ")));
  REQUIRE(r.problems.empty());  // no row taken for a line of its own
  REQUIRE(r.answers.at(0).verdict.correct);
  REQUIRE(r.answers.at(1).verdict.correct);
  // A blank line ends a bracket left open: the answer is judged as it stands, and the lines
  // after it are answers of their own.
  const SubmissionResult open =
      judged("I_corner = [[1, 0, 0],\n\ncenter_of_mass = (0.5, 1, 1.5) m\n");
  REQUIRE(open.problems.empty());
  REQUIRE_THAT(open.answers.at(0).verdict.line, Catch::StartsWith("unreadable: I_corner"));
  REQUIRE(open.answers.at(1).verdict.correct);
  // The key's matrix pasted as it prints, one row in brackets a line and the unit after the
  // last: the rows that follow a row continue it (each was a line naming nothing).
  std::string key_rows;
  for (int row = 0; row < 3; ++row) {
    key_rows += fmt::format("{}[ {:.10g} {:.10g} {:.10g} ]{}\n", row == 0 ? "I_corner = " : "    ",
                            m[3 * row], m[3 * row + 1], m[3 * row + 2], row == 2 ? " kg m²" : "");
  }
  const SubmissionResult pasted = judged(key_rows + "center_of_mass = (0.5, 1, 1.5) m\n");
  INFO(key_rows << fmt::format("{}", fmt::join(pasted.problems, "; ")));
  REQUIRE(pasted.problems.empty());
  REQUIRE(pasted.answers.at(0).verdict.correct);
  REQUIRE(pasted.answers.at(1).verdict.correct);
  // A row after a vector's answer continues it too, and makes it no vector: refused as a matrix.
  const SubmissionResult vector_and_row = judged("center_of_mass = [0.5, 1, 1.5]\n[1, 2, 3]\n");
  REQUIRE(vector_and_row.problems.empty());
  REQUIRE_THAT(vector_and_row.answers.at(1).verdict.line,
               Catch::StartsWith("unreadable: center_of_mass"));
}

TEST_CASE("a submission's value under its closed form is the key's line; a sign alone names none") {
  const Fixture plate("flying-plate");
  const auto judged = [&](const std::string& text) {
    return judge_submission({plate.key, plate.table, plate.values}, text, {});
  };
  // As the key prints it: both sides judged, a wrong value named as that side.
  const SubmissionResult two_lines = judged("I0 = m·R²/4\n     = 0.00072 kg m²\n");
  REQUIRE(two_lines.problems.empty());
  REQUIRE(two_lines.answers.at(0).verdict.correct);
  const SubmissionResult wrong_value = judged("I0 = m·R²/4\n     ≈ 0.0007 kg m²\n");
  REQUIRE(wrong_value.problems.empty());
  REQUIRE_FALSE(wrong_value.answers.at(0).verdict.correct);
  REQUIRE(wrong_value.answers.at(0).verdict.feedback.at(0) ==
          "the side \"0.0007 kg m²\" of your '='");
  // With nothing above it to go on, the line names no answer, and says so.
  const SubmissionResult alone = judged("= 0.00072 kg m²\n\nI0 = 0.00072 kg m²\n");
  REQUIRE(alone.problems ==
          std::vector<std::string>{
              "line 1: '= 0.00072 kg m²' has no name before its sign; write NAME = ANSWER"});
  REQUIRE(alone.answers.at(0).verdict.correct);
}

TEST_CASE("a zero left by rounding has no reciprocal and no percentage to be off by") {
  // The flying plate's identity residual is 0 rad/s in the key, a few eps in some variants.
  const Fixture plate("flying-plate");
  const auto wrong = plate.check("identity_residual", "0.5");
  REQUIRE_FALSE(wrong.correct);
  CHECK(wrong.feedback == std::vector<std::string>{"the answer is zero"});
  Answer residual = plate.answer("identity_residual");
  residual.value = Value::scalar(3.552713678800501e-15);  // a variant's value
  const Unit rad_s = parse_unit("rad/s", "test");
  CHECK_FALSE(wobble::check::reciprocal_mistake(
      residual, 1 / residual.value.data[0], nullptr, rad_s,
      wobble::check::zero_scale(plate.key, residual), [](double, double) { return true; }));
  for (const auto& w : wobble::check::wrong_answers(residual, plate.key, rad_s))
    CHECK_THAT(w.message, !Catch::Contains("reciprocal") && !Catch::Contains("period"));
}

TEST_CASE("one line's name and answer, as a submission and one word to check read it") {
  using wobble::check::answer_line;
  for (const auto& [line, name, answer, separator] :
       std::vector<std::tuple<std::string, std::string, std::string, std::string>>{
           {"rate_axis2 = 1.772 1/s", "rate_axis2", "1.772 1/s", "="},
           {"rate_axis2: 1.772 1/s", "rate_axis2", "1.772 1/s", ":"},
           {"(b) rate_axis2 = 1.772", "rate_axis2", "1.772", "="},
           {"b) rate_axis2=1.772", "rate_axis2", "1.772", "="},
           {"rate_axis2 [rad/s or 1/s] = 1.772 1/s", "rate_axis2", "1.772 1/s", "="},
           {"I₀ = m·R²/4 = 0.00072 kg m²", "I₀", "m·R²/4 = 0.00072 kg m²", "="},
           {"rate_axis2 =", "rate_axis2", "", "="},
           {"rate_axis2 == 1.772 1/s", "rate_axis2", "1.772 1/s", "="},
           {"k := 0.8", "k", "0.8", ":"},
           {"rate_axis2 : = -1.772", "rate_axis2", "-1.772", ":"},
           {"rate_axis2 ==", "rate_axis2", "", "="},
           // As the judge reads them, '≈', '≃' and '∼' stand for '='.
           {"φ̇_slow ≈ 4.995 rad/s", "φ̇_slow", "4.995 rad/s", "≈"},
           {"phidot_fast ≃ 25.8", "phidot_fast", "25.8", "≃"},
           {"k ∼ 0.8", "k", "0.8", "∼"},
           {"k ≈", "k", "", "≈"},
           {"I₀ = m·R²/4 ≈ 0.00072 kg m²", "I₀", "m·R²/4 ≈ 0.00072 kg m²", "="}}) {
    INFO(line);
    const auto read = answer_line(line);
    REQUIRE(read.has_value());
    CHECK(read->name == name);
    CHECK(read->answer == answer);
    CHECK(read->separator == separator);
  }
  CHECK_FALSE(answer_line("1.772 1/s").has_value());
}

TEST_CASE("a name and its answer with only a space between, and where the word is a factor") {
  for (const auto& [line, name, answer] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
           {"omega3_min 118.8 rad/s", "omega3_min", "118.8 rad/s"},
           {"(c) I₀   0.00072 kg m²", "I₀", "0.00072 kg m²"},
           {"c) theta_max -0.78", "theta_max", "-0.78"},
           {"energy −7.37 J", "energy", "−7.37 J"},
           {"I0 m·R²/4", "I0", "m·R²/4"},
           {"omega3 (0, 0, 150)", "omega3", "(0, 0, 150)"}}) {
    INFO(line);
    const auto read = spaced_answer_line(line);
    REQUIRE(read.has_value());
    CHECK(read->name == name);
    CHECK(read->answer == answer);
  }
  // A separator makes it answer_line's; an operator after the word makes it an expression; a
  // relation makes it a bound, a range or a rule.
  for (const char* expression :
       {"omega3_min = 118.8", "omega3_min", "omega3 * 2", "ω3 − 3", "omega3 - x", "omega3 + 1",
        "omega3 ·2", "omega3 /2", "w ^2", "omega3 ×2", "", "E < 8 J", "E -> 8 J", "E ∈ [7, 8] J",
        "theta_max in (0.5, 0.8)", "theta_max ≤ 0.8"}) {
    INFO(expression);
    CHECK_FALSE(spaced_answer_line(expression).has_value());
  }
  for (const char* number :
       {"118.8 rad/s", "-0.5", "−2e-3", ".5", "+3", "[1, 0, 2]", "(1, 0, 1)/√2"})
    CHECK(starts_as_number(number));
  for (const char* name : {"m a²/6", "", "-", "√2", "psidot0"}) CHECK_FALSE(starts_as_number(name));
  // The answer judged is labelled by its own name; another answer's name before a number is a
  // factor (ω₃ = ψ̇₀ is the heavy top's spin, as its steps write it): 118.8/150 of it is
  // omega3_min's value, judged as an expression.
  const Fixture top("heavy-top");
  const double omega3_min = top.answer("omega3_min").value.data[0];
  REQUIRE(top.check("omega3_min", fmt::format("omega3_min {:.6g} rad/s", omega3_min)).correct);
  REQUIRE_FALSE(
      top.check("omega3_min", fmt::format("omega3_min {:.6g}", omega3_min * 1.05)).correct);
  const Verdict factor = top.check("omega3_min", "omega3 118.8/150");
  REQUIRE_FALSE(factor.correct);
  REQUIRE_THAT(fmt::format("{}", fmt::join(factor.feedback, "\n")),
               Catch::Contains("read with ω3 = ψ̇0"));
}
