// Notations students write that name the parts of an answer instead of laying them out, or
// that write a number as a calculator or a textbook does: each read as the key's answer when it
// is the key's value, and as wrong when it is not. Every value is the key's own, formatted here.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cctype>
#include <cmath>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include "check/answer_choice.hpp"
#include "check/check_fixture.hpp"
#include "check/diagnosis.hpp"
#include "check/inequality.hpp"
#include "check/judge.hpp"
#include "check/lost_power.hpp"
#include "check/written_forms.hpp"
#include "core/input_error.hpp"
#include "solvers/catalog.hpp"
#include "symbolic/unicode_notation.hpp"
#include "symbolic/units.hpp"
#include "temp_files.hpp"

using namespace wobble;
using Catch::Matchers::WithinRel;
using Fixture = wobble::test::CheckFixture;

namespace {
constexpr double kPi = 3.14159265358979323846;

// The first "diag(...)" in the steps of the key's parts: as `wobble solve` prints it.
std::string printed_diagonal(const Fixture& f) {
  for (const auto& part : f.key.parts) {
    for (const auto& step : part.steps) {
      const auto at = step.text.find("diag(");
      if (at == std::string::npos) continue;
      int depth = 0;
      for (std::size_t i = at + 4; i < step.text.size(); ++i) {
        depth += step.text[i] == '(' ? 1 : step.text[i] == ')' ? -1 : 0;
        if (depth == 0) return step.text.substr(at, i + 1 - at);
      }
    }
  }
  throw std::logic_error("no diag(..) in the key's steps");
}

// `text` with each whole-word occurrence of the symbol `name` replaced by "(value)".
std::string with_symbol_replaced(const std::string& text, const std::string& name,
                                 const std::string& value) {
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const bool here = text.compare(i, name.size(), name) == 0 && (i == 0 || !word(text[i - 1])) &&
                      (i + name.size() == text.size() || !word(text[i + name.size()]));
    if (here) {
      out += "(" + value + ")";
      i += name.size();
    } else {
      out += text[i++];
    }
  }
  return out;
}

// Each answer in the catalog with a closed form (principal axes aside, judged by meaning), with
// its problem solved at the defaults.
void for_each_closed_form(const std::function<void(const Fixture&, const Answer&)>& visit) {
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (!a.symbolic.empty() && a.kind != AnswerKind::principal_axes) visit(f, a);
      }
    }
  }
}

// How many times the symbol `name` stands in `text` as a whole word.
std::size_t occurrences(const std::string& text, const std::string& name) {
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::size_t n = 0;
  for (std::size_t i = text.find(name); i != std::string::npos; i = text.find(name, i + 1)) {
    n += (i == 0 || !word(text[i - 1])) &&
         (i + name.size() == text.size() || !word(text[i + name.size()]));
  }
  return n;
}

// The diagonal of a 3x3 key, each entry times `factor`, formatted by `f`.
std::vector<std::string> diagonal_of(const Fixture& fx, const std::string& name,
                                     double factor = 1.0) {
  const auto& d = fx.answer(name).value.data;
  return {fmt::format("{:.10g}", d[0] * factor), fmt::format("{:.10g}", d[4] * factor),
          fmt::format("{:.10g}", d[8] * factor)};
}
}  // namespace

TEST_CASE("the plural rads with a power after it is rad s to that power, written without a space") {
  const std::array<int, 3> per_second{0, 0, -1};
  for (const std::string unit : {"rads^-1", "rads^(-1)", "rads-1", "rads^-2"}) {
    INFO(unit);
    const Unit u = parse_unit(unit, "u");
    REQUIRE(u.angle);
    REQUIRE(u.dim == (unit == "rads^-2" ? std::array<int, 3>{0, 0, -2} : per_second));
  }
  // Alone it is radians, as "radians" is.
  const Unit plural = parse_unit("rads", "u");
  REQUIRE(plural.angle);
  REQUIRE(plural.dim == (std::array<int, 3>{0, 0, 0}));
}

TEST_CASE("units with SI prefixes") {
  const double eps = std::numeric_limits<double>::epsilon();
  for (const auto& [unit, to_si] :
       std::vector<std::pair<std::string, double>>{{"kJ", 1e3},
                                                   {"mJ", 1e-3},
                                                   {"mN m", 1e-3},
                                                   {"km", 1e3},
                                                   {"mus", 1e-6},  // µs, as read into ASCII
                                                   {"us", 1e-6},
                                                   {"mrad/s", 1e-3},
                                                   {"kHz", 2e3 * kPi},
                                                   {"mg cm^2", 1e-10}}) {
    INFO(unit);
    REQUIRE_THAT(parse_unit(unit, "u").to_si, WithinRel(to_si, 4 * eps));
  }
  REQUIRE(parse_unit("MJ", "u").same_dimension(parse_unit("J", "u")));
  // A name that is a unit of its own keeps its meaning: minutes, not milli-inches.
  REQUIRE_THAT(parse_unit("min", "u").to_si, WithinRel(60.0, eps));
  for (const std::string& bad :
       std::vector<std::string>{"xJ", "kdeg", "kkg", "mday", "k", "Mrpm", "krad", "Mrad"}) {
    INFO(bad);
    REQUIRE_THROWS_AS(parse_unit(bad, "u"), InputError);
  }
  // An angle has no gigaradians: "Grad" is German for degrees, and gradians are not read.
  REQUIRE_THROWS_WITH(parse_unit("Grad", "u"), Catch::Contains("write deg for degrees"));
  REQUIRE_THROWS_WITH(parse_unit("gon", "u"), Catch::Contains("gradians (400 to a turn)"));
  REQUIRE_THAT(parse_unit("nrad", "u").to_si, WithinRel(1e-9, 4 * eps));
}

TEST_CASE("numbers as calculators and textbooks write them") {
  const Fixture top("heavy-top");
  const double theta0 = top.answer("theta_min").value.data[0];  // pi/6 at the defaults
  REQUIRE_THAT(theta0, WithinRel(kPi / 6, 1e-15));
  // A number glued to pi, or beside it; a symbol that spells no unit glued to its number.
  for (const std::string& same :
       std::vector<std::string>{"2π/12", "2pi/12", "2 π/12", "1/6 π", "0.16667 π", "0.16667π",
                                "0.16667π rad", "(1/6)π", "π/6 rad"}) {
    INFO(same);
    REQUIRE(top.check("theta_min", same).correct);
  }
  REQUIRE_FALSE(top.check("theta_min", "2π/13").correct);
  REQUIRE(top.check("omega3_min", "2√(l g (4l²+R²))/R²").correct);
  REQUIRE(top.check("p_psi", "0.5M R^2 psidot0").correct);
  REQUIRE(top.check("omega3_min", "2sqrt(l g (4l^2+R^2))/R^2").correct);
  // An exponent stays one: 1e-3 is no 1 times a symbol e.
  REQUIRE_FALSE(top.check("p_psi", "1e-3 M").correct);

  const double rate = top.answer("phidot_slow").value.data[0];
  const std::string r = fmt::format("{:.6g}", rate);
  // Per second without its 1; approximately equal; an SI prefix.
  for (const std::string& same : std::vector<std::string>{
           r + "/s", r + " /s", "≈ " + r + " rad/s", "~" + r + " rad/s", "φ̇ ≈ " + r + " rad/s",
           "phidot_slow ≃ " + r, "about " + r + " rad/s", "Approx. " + r + "/s",
           "roughly " + r, fmt::format("{:.6g} mrad/s", rate * 1e3)}) {
    INFO(same);
    REQUIRE(top.check("phidot_slow", same).correct);
  }
  REQUIRE_FALSE(top.check("phidot_slow", r + "/min").correct);
  REQUIRE_FALSE(top.check("phidot_slow", "≈ " + fmt::format("{:.6g}", rate * 1.05)).correct);
  REQUIRE_FALSE(top.check("phidot_slow", "about " + fmt::format("{:.6g}", rate * 1.05)).correct);
  const double energy = top.answer("energy").value.data[0];
  REQUIRE(top.check("energy", fmt::format("{:.6g} mJ", energy * 1e3)).correct);
  REQUIRE(top.check("energy", fmt::format("{:.6g} kJ", energy * 1e-3)).correct);
  REQUIRE_FALSE(top.check("energy", fmt::format("{:.6g} kJ", energy)).correct);

  // Degrees, minutes and seconds of arc.
  const double deg = top.answer("theta_max").value.data[0] * 180 / kPi;
  const int d = static_cast<int>(deg), m = static_cast<int>((deg - d) * 60);
  const double s = ((deg - d) * 60 - m) * 60;
  for (const std::string& same : std::vector<std::string>{
           fmt::format("{}°{}′{:.1f}″", d, m, s), fmt::format("{}° {}′ {:.1f}″", d, m, s),
           fmt::format("{}°{}'{:.1f}\"", d, m, s), fmt::format("{}°{:.2f}′", d, m + s / 60),
           fmt::format("{} deg {} arcmin {:.1f} arcsec", d, m, s)}) {
    INFO(same);
    REQUIRE(top.check("theta_max", same).correct);
  }
  REQUIRE_FALSE(top.check("theta_max", fmt::format("{}°{}′", d + 2, m)).correct);
  REQUIRE_FALSE(top.check("theta_max", fmt::format("-{}°{}′", d, m)).correct);

  // A Greek letter is one symbol: beside a Latin letter it is a product or a function's
  // argument, never part of a longer name ("Homega"); π may stand against a bracket.
  const Fixture earth("earth-free-precession");
  for (const auto& [name, same] : std::vector<std::pair<std::string, std::string>>{
           {"Omega_body_rate", "Hωcos(α)/(1-H)"},
           {"precession_period_body", "2π(1-H)/(Hω cos α)"},
           {"precession_period_body", "2π(1 - H)/(H ω cosα)"}}) {
    INFO(same);
    REQUIRE(earth.check(name, same).correct);
  }
  REQUIRE_FALSE(earth.check("precession_period_body", "2π(1-H)/(Hω sin α)").correct);
  // A rate's dot above, or a subscript, is the letter's own; a function after it is apart.
  const Fixture euler_top("euler-angles");
  REQUIRE(euler_top.check("kinetic_energy", "I1/2 (φ̇²sin²θ+θ̇²) + I3/2 (φ̇cosθ+ψ̇)²").correct);
  REQUIRE(euler_top.check("omega_primed", "(-φ̇sinθ, θ̇, φ̇cosθ + ψ̇)").correct);
  // A root after a factor, a number glued to a function, a power on a function's name before a
  // bare argument: "ω√(4 - 3sin²α)" is ω*sqrt(4 - 3*sin(α)^2).
  const Fixture plate("flying-plate");
  for (const std::string& same : std::vector<std::string>{
           "ω√(4 - 3sin²α)", "omega sqrt(4 - 3 sin^2 alpha)", "ω√(1 + 3cos²α)"}) {
    INFO(same);
    REQUIRE(plate.check("Omega_space_rate", same).correct);
  }
  REQUIRE_FALSE(plate.check("Omega_space_rate", "ω√(4 - 3cos²α)").correct);
  // A power on the argument too is no bare argument: the message asks for the parentheses.
  REQUIRE_THROWS_WITH(plate.check("Omega_space_rate", "omega sqrt(4 - 3 sin^2 alpha^2)"),
                      Catch::Contains("a function's argument parentheses"));
  // A size named as such before its value.
  const Fixture asym("asymmetric-top");
  const std::string size = fmt::format("{:.6g} kg m²/s", asym.answer("L_magnitude").value.data[0]);
  REQUIRE(asym.check("L_magnitude", "|L| = " + size).correct);
  REQUIRE(asym.check("L_magnitude", "‖L‖ = " + size).correct);
  // Seconds and minutes of arc typed with the keyboard's quotes.
  const double arcsec = earth.answer("angle_L_e3").value.data[0] * 180 / kPi * 3600;
  for (const std::string& same :
       std::vector<std::string>{fmt::format("{:.4f}\"", arcsec), fmt::format("{:.4f}''", arcsec),
                                fmt::format("{:.6f}'", arcsec / 60)}) {
    INFO(same);
    REQUIRE(earth.check("angle_L_e3", same).correct);
  }
  REQUIRE_FALSE(earth.check("angle_L_e3", fmt::format("{:.4f}'", arcsec)).correct);

  // Where m is a mass, a glued "2m" is still two masses or two metres, and refused; in a
  // product with another symbol it is the mass.
  REQUIRE(plate.check("I0", "0.25m R^2").correct);
  REQUIRE_THROWS_WITH(plate.check("I0", "2m"), Catch::Contains("one of the problem's symbols"));
}

TEST_CASE("a diagonal matrix written as a call reads as the matrix") {
  const Fixture box("box-corner");
  // The key's own step, pasted: "diag(M·(b² + c²)/12, ...)".
  const std::string step = printed_diagonal(box);
  REQUIRE(box.check("I_cm", step).correct);
  const auto v = diagonal_of(box, "I_cm");
  const std::string list = v[0] + ", " + v[1] + ", " + v[2];
  for (const std::string& same : std::vector<std::string>{
           "diag(" + list + ") kg m^2", "np.diag([" + list + "])", "numpy.diag([" + list + "])",
           "diag([" + v[0] + " " + v[1] + " " + v[2] + "])", "diagm([" + list + "])",
           "DiagonalMatrix[{" + list + "}]", "sp.diag(" + list + ")",
           "M/12 diag(b²+c², a²+c², a²+b²)", "\\operatorname{diag}(" + list + ")"}) {
    INFO(same);
    REQUIRE(box.check("I_cm", same).correct);
  }
  REQUIRE_FALSE(box.check("I_cm", "diag(" + v[0] + ", " + v[2] + ", " + v[1] + ")").correct);
  REQUIRE_THROWS_WITH(box.check("I_cm", "diag(" + v[0] + ", " + v[1] + ")"),
                      Catch::Contains("3x3 matrix") && Catch::Contains("2x2"));
  // More entries than a 3x3 matrix's are refused before they are written out (n² of them).
  REQUIRE_THROWS_WITH(box.check("I_cm", "diag(1, 2, 3, 4)"),
                      Catch::Contains("diag(..) with 4 entries"));
}

TEST_CASE("components given one by one with their labels") {
  const Fixture box("box-corner");
  const auto& c = box.answer("center_of_mass").value.data;
  const auto f = [&](std::size_t k) { return fmt::format("{:.10g}", c[k]); };
  for (const std::string& same : std::vector<std::string>{
           "x = " + f(0) + ", y = " + f(1) + ", z = " + f(2),
           "z = " + f(2) + " m, x = " + f(0) + " m, y = " + f(1) + " m",  // any order
           "x_cm = a/2, y_cm = b/2, z_cm = c/2",
           "x=a/2 y=b/2 z=c/2",  // parted by spaces alone
           "r₁ = " + f(0) + ", r₂ = " + f(1) + ", r₃ = " + f(2)}) {
    INFO(same);
    REQUIRE(box.check("center_of_mass", same).correct);
  }
  REQUIRE_FALSE(
      box.check("center_of_mass", "x = " + f(1) + ", y = " + f(0) + ", z = " + f(2)).correct);
  for (const std::string& none : std::vector<std::string>{
           "x = 1, y = 2, w = 3", "x = 1, x = 2, z = 3", "a = 1, b = 2, c = 3"}) {
    INFO(none);
    REQUIRE_THROWS_WITH(box.check("center_of_mass", none),
                        Catch::Contains("components given one by one"));
  }
  // Two of three: the third not given is zero, and the line says so.
  const auto two = box.check("center_of_mass", "x = 1, y = 2");
  REQUIRE_FALSE(two.correct);
  REQUIRE(two.feedback.back() == "read as [1, 2, 0]: z not given, taken as zero");
  const auto& moments = box.answer("principal_moments_corner").value.data;
  REQUIRE(box.check("principal_moments_corner",
                    fmt::format("I₁ = {:.6g} kg m², I₂ = {:.6g} kg m², I₃ = {:.6g} kg m²",
                                moments[0], moments[1], moments[2]))
              .correct);
  // Principal axes by name are the key's columns, and the line says each vector is an axis (not
  // "as rows" or "as columns": the student wrote no matrix).
  const auto& axes = box.answer("principal_axes_corner").value.data;  // row-major, axes columns
  const auto column = [&](std::size_t k) {
    return fmt::format("({:.8f}, {:.8f}, {:.8f})", axes[k], axes[3 + k], axes[6 + k]);
  };
  const check::Verdict by_name = box.check(
      "principal_axes_corner", "e1 = " + column(0) + ", e2 = " + column(1) + ", e3 = " + column(2));
  REQUIRE(by_name.correct);
  REQUIRE_THAT(by_name.line, Catch::Contains("(each of your vectors an axis, in any order") &&
                                 !Catch::Contains("as columns") && !Catch::Contains("as rows"));
  // A matrix is read either way, and which is said.
  const std::string matrix =
      fmt::format("[[{:.8f}, {:.8f}, {:.8f}], [{:.8f}, {:.8f}, {:.8f}], [{:.8f}, {:.8f}, {:.8f}]]",
                  axes[0], axes[1], axes[2], axes[3], axes[4], axes[5], axes[6], axes[7], axes[8]);
  REQUIRE_THAT(box.check("principal_axes_corner", matrix).line, Catch::Contains("(as columns,"));

  // A tensor by its entries' two indices: one not given is its mirror's, else zero.
  const Fixture cone("solid-cone");
  for (const std::string& same : std::vector<std::string>{
           "I_xx = I_yy = 3M(R²+4h²)/20, I_zz = 3MR²/10",
           "I₁₁ = I₂₂ = 3M(R² + 4h²)/20, I₃₃ = 3M R²/10, I₁₂ = 0",
           "Izz = 3 M R^2/10 Ixx = 3M(R^2 + 4h^2)/20 Iyy = 3M(R^2 + 4h^2)/20"}) {
    INFO(same);
    REQUIRE(cone.check("I_apex", same).correct);
  }
  REQUIRE_FALSE(cone.check("I_apex", "I_xx = 3M(R²+4h²)/20, I_zz = 3MR²/10").correct);
  const Fixture masses("four-masses");  // I_xy = −m a²/2, told once
  REQUIRE(masses.check("I", "Ixx = Iyy = Izz = 3 m a^2, Ixy = -m a^2/2").correct);
  REQUIRE_FALSE(masses.check("I", "Ixx = Iyy = Izz = 3 m a^2, Ixz = -m a^2/2").correct);
  // A last item saying the rest are zero, as they are read anyway.
  for (const char* same : {"Ixx = Iyy = Izz = 3 m a^2, Ixy = -m a^2/2, others 0",
                           "I_xx = I_yy = I_zz = 3ma², I_xy = −ma²/2, the rest are zero",
                           "Ixx = Iyy = Izz = 3ma^2, Ixy = -ma^2/2, all other products = 0"}) {
    INFO(same);
    REQUIRE(masses.check("I", same).correct);
  }
  REQUIRE_FALSE(masses.check("I", "Ixx = Iyy = Izz = 3 m a^2, Ixz = -m a^2/2, others 0").correct);
  REQUIRE(cone.check("center_of_mass", "z = -3h/4, others 0").correct);
  // A unit after the last value alone is the whole list's, where that value is told once for
  // several labels too.
  REQUIRE(masses.check("I", "Ixy = -0.5e7, Ixx = Iyy = Izz = 3e7 g cm²").correct);
  REQUIRE(masses.check("I", "Ixy = Iyx = -0.5e7, Ixx = Iyy = Izz = 3e7 (g cm²)").correct);
  // The list's unit after the rule, as after its last value: bracketed (with "in" or not), after
  // "in", or bare. In g cm² (10⁷ of the key's numbers), so that a unit dropped would be judged
  // wrong.
  for (const char* unit : {" (g cm²)", " (in g cm²)", " in g cm^2", " g cm²"}) {
    INFO(unit);
    REQUIRE(masses.check("I", std::string("Ixx = Iyy = Izz = 3e7, Ixy = -0.5e7, others 0") + unit)
                .correct);
    REQUIRE(masses.check("I", std::string("Ixy = -0.5e7, Ixx = Iyy = Izz = 3e7, others 0") + unit)
                .correct);
    REQUIRE_FALSE(
        masses.check("I", std::string("Ixx = Iyy = Izz = 3, Ixy = -0.5, the rest are zero") + unit)
            .correct);
  }
  // A formula between a label and its value, the plane body's I₃ = I₁ + I₂: read past, and the
  // feedback says it was not judged.
  const Fixture molecule("three-atom-molecule");  // moments about the origin, a plane body
  const auto& planar = molecule.answer("principal_moments").value.data;
  const auto listed = [&](double third) {
    return fmt::format("I₁ = {:.6g}, I₂ = {:.6g}, I₃ = I₁ + I₂ = {:.6g} kg m²", planar[0],
                       planar[1], third);
  };
  const auto past = molecule.check("principal_moments", listed(planar[2]));
  REQUIRE(past.correct);
  REQUIRE_THAT(past.feedback, Catch::VectorContains(std::string(
                                  "I₁ + I₂ (before I₃'s value) is not judged: its value is")));
  REQUIRE_FALSE(molecule.check("principal_moments", listed(planar[2] * 1.05)).correct);
  using wobble::check::without_others_zero;
  CHECK(without_others_zero("x = 1, others 0") == "x = 1");
  // Not without a label before it, nor where the words say more than that the rest are zero.
  CHECK(without_others_zero("1, others 0") == "1, others 0");
  CHECK(without_others_zero("x = 1, others 2") == "x = 1, others 2");
  CHECK(without_others_zero("x = 1, y equals 0") == "x = 1, y equals 0");
  CHECK(without_others_zero("x = 1, others 0 (kg m²)") == "x = 1 (kg m²)");
  // After the zero, only a unit: "or 1" says more.
  CHECK(without_others_zero("x = 1, others 0 or 1") == "x = 1, others 0 or 1");
  CHECK(without_others_zero("x = 1, others 0 furlongs") == "x = 1, others 0 furlongs");

  // A pair: the racket spun about e₂ has (Ω₃, Ω₁) in the key, (Ω₁, Ω₂) as the lecture writes
  // the pair about e₃ and the question asks for it; both name the entries, in any order.
  const Fixture racket("tennis-racket");
  const auto& pair = racket.answer("Omega_axis2").value.data;
  const auto g = [&](std::size_t k) { return fmt::format("{:.10g}", pair[k]); };
  for (const std::string& same : std::vector<std::string>{
           "Ω₃ = " + g(0) + ", Ω₁ = " + g(1), "Omega1 = " + g(1) + ", Omega3 = " + g(0) + " rad/s",
           "Ω₁ = " + g(0) + ", Ω₂ = " + g(1), "Ω_2 = " + g(1) + ", Ω_1 = " + g(0)}) {
    INFO(same);
    REQUIRE(racket.check("Omega_axis2", same).correct);
  }
  const check::Verdict swapped = racket.check("Omega_axis2", "Ω₁ = " + g(0) + ", Ω₃ = " + g(1));
  REQUIRE_FALSE(swapped.correct);
  REQUIRE(swapped.feedback ==
          std::vector<std::string>{"the right entries in another order: Ω₃ and Ω₁ are swapped"});
  REQUIRE_THROWS_WITH(racket.check("Omega_axis2", "Ω₁ = " + g(0) + ", Ω₄ = " + g(1)),
                      Catch::Contains("the key's names of the entries (Ω₃, Ω₁)"));

  // Euler's angles by name, in the order of the key's vector.
  const Fixture euler("euler-angles");
  const auto& angles = euler.answer("angles_phy711").value.data;
  const auto degrees = [&](std::size_t k) { return fmt::format("{:.8g}°", angles[k] * 180 / kPi); };
  REQUIRE(euler
              .check("angles_phy711",
                     "γ = " + degrees(2) + ", α = " + degrees(0) + ", β = " + degrees(1))
              .correct);
  REQUIRE(
      euler.check("angles_phy711", "α=" + degrees(0) + " β=" + degrees(1) + "  γ = " + degrees(2))
          .correct);
  // Spaces part labelled components only where the labels place them: a line with a product
  // in it stays a line ("I1 ω" is no label and value), read as a label, a formula in a name the
  // problem lacks, and the value.
  const auto line = euler.check("kinetic_energy", "T = I1 ω = 3");
  REQUIRE_FALSE(line.correct);
  REQUIRE_THAT(line.feedback.back(), Catch::Contains("the side \"I1 ω\" of your '=' is taken as a "
                                                     "label"));
  REQUIRE(euler
              .check("angles_phy711",
                     "phi = " + degrees(0) + ", theta = " + degrees(1) + ", psi = " + degrees(2))
              .correct);
  REQUIRE_FALSE(euler
                    .check("angles_phy711",
                           "α = " + degrees(1) + ", β = " + degrees(0) + ", γ = " + degrees(2))
                    .correct);
}

TEST_CASE("a unit glued to a bracket, and numbers in lines as MATLAB shows them") {
  const Fixture box("box-corner");
  const auto& c = box.answer("center_of_mass").value.data;  // metres
  const std::string list = fmt::format("{:.10g}, {:.10g}, {:.10g}", c[0], c[1], c[2]);
  for (const std::string& same : std::vector<std::string>{
           "[" + list + "]m", "(" + list + ")m",
           fmt::format("({:.10g},{:.10g},{:.10g})cm", c[0] * 100, c[1] * 100, c[2] * 100),
           fmt::format("{:.4f} {:.4f} {:.4f}", c[0], c[1], c[2]),
           fmt::format("ans =\n\n   {:10.4f}{:10.4f}{:10.4f}\n", c[0], c[1], c[2]),
           fmt::format("{:.4f}\n{:.4f}\n{:.4f}", c[0], c[1], c[2])}) {
    INFO(same);
    REQUIRE(box.check("center_of_mass", same).correct);
  }
  REQUIRE_FALSE(box.check("center_of_mass", "[" + list + "]cm").correct);
  const auto& tensor = box.answer("I_cm").value.data;
  std::string shown;
  for (std::size_t r = 0; r < 3; ++r) {
    for (std::size_t k = 0; k < 3; ++k) shown += fmt::format("{:10.4f}", tensor[3 * r + k]);
    shown += "\n";
  }
  REQUIRE(box.check("I_cm", shown).correct);
  // MATLAB's literal with a row on each line, commas between entries or not, a ';' or ','
  // ending a row, a unit after it: rows (before, "-0.75,\n -0.5" read as -0.75 - 0.5).
  const auto& corner = box.answer("I_corner").value.data;  // kg m^2
  const auto row = [&](std::size_t r, const char* sep) {
    return fmt::format("{:.6f}{}{:.6f}{}{:.6f}", corner[3 * r], sep, corner[3 * r + 1], sep,
                       corner[3 * r + 2]);
  };
  for (const auto& [sep, end] : std::vector<std::pair<std::string, std::string>>{
           {" ", ""}, {", ", ""}, {" ", ";"}, {", ", ","}}) {
    const std::string rows = "[" + row(0, sep.c_str()) + end + "\n " + row(1, sep.c_str()) + end +
                             "\n " + row(2, sep.c_str()) + "]";
    INFO(rows);
    REQUIRE(box.check("I_corner", rows).correct);
    REQUIRE(box.check("I_corner", rows + " kg m^2").correct);
    REQUIRE_FALSE(box.check("I_corner", rows + " g cm^2").correct);
  }
  // The same rows with one entry changed are wrong where it is.
  const std::string changed = "[" + row(0, " ") + "\n" + row(1, " ") + "\n" +
                              fmt::format("{:.6f} {:.6f} 1.2]", corner[6], corner[7]);
  REQUIRE_THAT(box.check("I_corner", changed).feedback.at(0), Catch::Contains("entry (3, 3)"));
  // Lines of unequal length are no matrix.
  REQUIRE_THROWS_AS(box.check("I_cm", "1 0 0\n0 1\n0 0 1"), InputError);
}

TEST_CASE("a symbol by the name its LaTeX spells, where that spelling is no other thing") {
  // The asymmetric top's w1 is set as \omega_1: its statement prints "ω₁".
  const Fixture top("asymmetric-top");
  REQUIRE(top.check("energy", "(I₁ω₁² + I₂ω₂² + I₃ω₃²)/2").correct);
  REQUIRE(top.check("energy", "(I_1 omega_1^2 + I2 omega2^2 + I3 omega3^2)/2").correct);
  REQUIRE_FALSE(top.check("energy", "(I₁ω₂² + I₂ω₁² + I₃ω₃²)/2").correct);  // ω₁, ω₂ swapped

  // A spelling two symbols share names neither; one that is a symbol or a unit keeps its meaning.
  const std::string file = wobble::test::write_file("check/spellings.toml", R"TOML(id = "spellings"
title = "t"
solver = "inertia"
statement = "s"

[[parameters]]
name = "a"
latex = "\\alpha"
unit = "kg m^2"
default = 4
range = "(0, inf)"

[[parameters]]
name = "b"
latex = "\\omega_1"
unit = "kg m^2"
default = 2
range = "(0, inf)"

[[parameters]]
name = "c"
latex = "\\omega_1"
unit = "kg m^2"
default = 3
range = "(0, inf)"

[[parameters]]
name = "d"
latex = "m"
unit = "kg m^2"
default = 1
range = "(0, inf)"

[[parameters]]
name = "e"
latex = "d"
unit = "kg m^2"
default = 2
range = "(0, inf)"

[body]
tensor = [["a", "0", "0"], ["0", "b + c", "0"], ["0", "0", "d + e"]]

[[parts]]
id = "a"
question = "q"
answers = ["I"]
)TOML")
                               .string();
  const Fixture f(file);
  REQUIRE(f.check("I", "[[α, 0, 0], [0, b + c, 0], [0, 0, d + e]]").correct);
  REQUIRE_THROWS_AS(f.check("I", "[[a, 0, 0], [0, ω₁ + c, 0], [0, 0, d + e]]"), InputError);
  // "d" is the symbol d, not e, whose LaTeX is d; "m" is no symbol, though d's LaTeX is m.
  REQUIRE_FALSE(f.check("I", "[[a, 0, 0], [0, b + c, 0], [0, 0, d + d]]").correct);
  REQUIRE_THROWS_AS(f.check("I", "[[a, 0, 0], [0, b + c, 0], [0, 0, m + e]]"), InputError);
}

TEST_CASE("an answer copied from an equation editor: styled letters, invisible operators") {
  const Fixture plate("flying-plate");
  for (const std::string& same :
       std::vector<std::string>{"𝑚𝑅^2/4", "(𝑚𝑅²)/𝟒", "1/4 𝑚𝑅²", "𝑚\u2062𝑅^2/4"}) {
    INFO(same);
    REQUIRE(plate.check("I0", same).correct);
  }
  REQUIRE_FALSE(plate.check("I0", "𝑚𝑅^2/2").correct);
  const Fixture earth("earth-free-precession");
  REQUIRE(earth.check("Omega_body_rate", "𝐻𝜔cos\u2061𝛼/(1−𝐻)").correct);
  REQUIRE_FALSE(earth.check("Omega_body_rate", "𝐻𝜔sin\u2061𝛼/(1−𝐻)").correct);
  // The lunate epsilon of LaTeX's \epsilon is the tennis racket's ε.
  const Fixture racket("tennis-racket");
  const std::string rate = racket.answer("dw_dt0").symbolic;
  REQUIRE(racket.check("dw_dt0", sym::to_unicode(rate)).correct);
  std::string lunate = sym::to_unicode(rate);
  for (auto at = lunate.find("ε"); at != std::string::npos; at = lunate.find("ε", at)) {
    lunate.replace(at, std::string("ε").size(), "ϵ");
  }
  REQUIRE(lunate != sym::to_unicode(rate));
  REQUIRE(racket.check("dw_dt0", lunate).correct);
}

TEST_CASE("a program's array or matrix inside an expression, times the problem's symbols") {
  const Fixture taylor("taylor-10-35");  // I = m a² [[10, 0, 0], [0, 6, 1], [0, 1, 6]]
  for (const char* same : {"m*a**2*np.array([[10, 0, 0], [0, 6, 1], [0, 1, 6]])",
                           "np.array([[10,0,0],[0,6,1],[0,1,6]])*m*a**2",
                           "m*a**2 * np.matrix([[10,0,0],[0,6,1],[0,1,6]])",
                           "matrix([[10, 0, 0], [0, 6, 1], [0, 1, 6]])",
                           "Matrix([[10, 0, 0], [0, 6, 1], [0, 1, 6]])*m*a**2",
                           "m*a**2*sp.Matrix([[10, 0, 0], [0, 6, 1], [0, 1, 6]])"}) {
    INFO(same);
    REQUIRE(taylor.check("I", same).correct);
  }
  REQUIRE_FALSE(taylor.check("I", "m*a**2*np.array([[10, 0, 0], [0, 6, -1], [0, -1, 6]])").correct);
  REQUIRE(taylor.check("principal_moments", "m*a**2*np.array([5, 7, 10])").correct);
  // A name that merely ends in one ("myarray(") is no container, nor a call of no list.
  REQUIRE_THROWS_WITH(taylor.check("I", "m*a**2*myarray([[10, 0, 0], [0, 6, 1], [0, 1, 6]])"),
                      Catch::Contains("myarray"));
  REQUIRE_THROWS_WITH(taylor.check("principal_moments", "array(5)*m*a**2"),
                      Catch::Contains("array"));
}

TEST_CASE("Mathematica's rules, as Solve gives them, are equations") {
  const Fixture top("heavy-top");
  const std::string energy = fmt::format("{:.6g}", top.answer("energy").value.data.at(0));
  for (const std::string& same : {"E -> " + energy, "{{E -> " + energy + "}}",
                                  "{E -> " + energy + " J}", "E → " + energy + " J"}) {
    INFO(same);
    REQUIRE(top.check("energy", same).correct);
  }
  REQUIRE_FALSE(top.check("energy", "{{E -> 8}}").correct);
  const auto several = top.check("energy", "{{energy -> " + energy + ", theta_min -> 0.5}}");
  REQUIRE(several.correct);
  REQUIRE_THAT(several.feedback.at(0), Catch::StartsWith("theta_min = 0.5 not judged here"));
  using wobble::check::rules_as_equations;
  CHECK(rules_as_equations("{{a -> 1, b -> 2}}") == "a = 1, b = 2");
  // Not a list with an item that is no rule, an arrow with an empty side, or two arrows.
  CHECK(rules_as_equations("{a -> 1, 2}") == "{a -> 1, 2}");
  CHECK(rules_as_equations("a -> ") == "a -> ");
  CHECK(rules_as_equations("a -> b -> 1") == "a -> b -> 1");
}

TEST_CASE("results as programs print them: NumPy 2's scalars, Out[n] labels") {
  const Fixture box("box-corner");
  const auto& c = box.answer("center_of_mass").value.data;  // metres
  const auto numpy = [](double x) { return fmt::format("np.float64({:.10g})", x); };
  const std::string listed = "[" + numpy(c[0]) + ", " + numpy(c[1]) + ", " + numpy(c[2]) + "]";
  for (const std::string& same :
       std::vector<std::string>{listed, "Out[3]= " + listed, "Out[12]: " + listed,
                                "Out[4]//N= " + listed, "numpy.float64(1)*" + listed}) {
    INFO(same);
    REQUIRE(box.check("center_of_mass", same).correct);
  }
  REQUIRE_FALSE(
      box.check("center_of_mass", "[" + numpy(c[0]) + ", " + numpy(c[2]) + ", " + numpy(c[1]) + "]")
          .correct);
  const Fixture plate("flying-plate");
  const std::string i0 = fmt::format("{:.6g}", plate.answer("I0").value.data[0]);
  REQUIRE(plate.check("I0", "np.float64(" + i0 + ") kg m^2").correct);
  REQUIRE(plate.check("I0", "Out[3]= m R^2/4 = " + i0 + " kg m^2").correct);
  REQUIRE_FALSE(plate.check("I0", "Out[3]= 2*" + i0).correct);
  // Only a whole label is dropped silently; "Out[]" is read as typed, a formula in a name the
  // problem lacks, and so a label said unjudged; NumPy's functions are read
  // (program_notation.hpp), a name NumPy has that no answer uses is refused.
  REQUIRE_THAT(plate.check("I0", "Out[]= " + i0).feedback,
               Catch::Equals(std::vector<std::string>{
                   "the side \"Out[]\" of your '=' is taken as a label, not judged: Out is no "
                   "symbol here"}));
  REQUIRE(plate.check("I0", "np.sqrt(" + i0 + "**2)").correct);
  REQUIRE_FALSE(plate.check("I0", "np.sqrt(" + i0 + ")").correct);
  REQUIRE_THROWS_AS(plate.check("I0", "np.cbrt(" + i0 + "**3)"), InputError);
}

TEST_CASE("Newton's dot as a PDF copies it, and a rate the problem has not") {
  const Fixture euler("euler-angles");
  const std::string dotted = sym::to_unicode(euler.answer("omega_primed").symbolic);
  std::string spacing = dotted;  // "φ̇" with the spacing dot above, as copied from a PDF: "φ˙"
  for (auto at = spacing.find("\u0307"); at != std::string::npos; at = spacing.find("\u0307", at))
    spacing.replace(at, 2, "˙");
  REQUIRE(spacing != dotted);
  REQUIRE(euler.check("omega_primed", spacing).correct);
  REQUIRE_FALSE(euler.check("omega_primed", "(φ˙ sin θ, θ˙, φ˙ cos θ + ψ˙)").correct);  // a sign
  // The heavy top has ψ̇₀, no ψ̇: "dψ/dt" names nothing, and is refused with the rate it has,
  // as "psidot" is.
  const Fixture top("heavy-top");
  REQUIRE(top.check("p_psi", "M R² (dψ₀/dt)/2").correct);
  for (const char* rate : {"M R² (dψ/dt)/2", "M R^2 dpsi/dt / 2", "M R^2 (d psi/dt)/2"}) {
    INFO(rate);
    REQUIRE_THROWS_WITH(top.check("p_psi", rate),
                        Catch::Contains("the problem's is ψ̇₀ (psidot0), the initial spin rate"));
  }
  REQUIRE_THROWS_AS(top.check("p_psi", "\\frac{1}{2} M R^2 \\frac{d\\psi}{dt}"), InputError);
}

TEST_CASE("a call with a space before its parentheses, as a PDF's text sets it") {
  const Fixture euler("euler-angles");
  const std::string key = sym::to_unicode(euler.answer("omega_space").symbolic);
  std::string spaced = key;  // "cos(φ)" -> "cos (φ)", and so on
  for (const std::string f : {"sin(", "cos("}) {
    for (auto at = spaced.find(f); at != std::string::npos; at = spaced.find(f, at + 1))
      spaced.insert(at + 3, " ");
  }
  REQUIRE(spaced != key);
  REQUIRE(euler.check("omega_space", spaced).correct);
  // A symbol before a bracket stays a product, a space or none.
  const Fixture plate("flying-plate");
  REQUIRE(plate.check("I0", "m (R^2)/4").correct);
  REQUIRE_FALSE(plate.check("I0", "m (R^2)/2").correct);
}

TEST_CASE("a comment after an answer, as a script or a LaTeX source has one") {
  const Fixture plate("flying-plate");
  const std::string i0 = fmt::format("{:.6g}", plate.answer("I0").value.data[0]);  // kg m^2
  for (const std::string& same : std::vector<std::string>{
           "m*R**2/4  # a disc about a diameter", i0 + " kg m^2 # table", i0 + "; % kg m^2",
           "\\frac{m R^2}{4} % disc", "% the disc\nm R^2/4"}) {
    INFO(same);
    REQUIRE(plate.check("I0", same).correct);
  }
  // What comes before the comment is judged: a factor 2 off stays wrong.
  REQUIRE_FALSE(plate.check("I0", "m*R**2/2  # m R^2/4").correct);
  REQUIRE_THROWS_AS(plate.check("I0", "# m R^2/4"), InputError);
}

TEST_CASE("an angle in degrees and minutes whose minutes run over 59 is refused") {
  const Fixture plate("flying-plate");  // angle_omega_e3 = alpha = 15 deg
  REQUIRE(plate.check("angle_omega_e3", "14°59′59.9″").correct);
  REQUIRE_FALSE(plate.check("angle_omega_e3", "14°30′").correct);
  // 14°75′ might be 14°57′ or 15°15′; 14°60′ is 15° written as no one writes it.
  for (const char* over : {"14°75′", "14°60′", "15°0′60″", "14 deg 59 arcmin 75 arcsec"}) {
    INFO(over);
    REQUIRE_THROWS_WITH(plate.check("angle_omega_e3", over),
                        Catch::Contains("in an angle") && Catch::Contains("carry the"));
  }
}

TEST_CASE("components along the body's e₁, e₂, e₃ or LaTeX's unit vectors read as a vector") {
  const Fixture plate("flying-plate");  // L0_body = (L1, 0, L3)
  const auto& l = plate.answer("L0_body").value.data;
  const std::string l1 = fmt::format("{:.6g}", l[0]), l3 = fmt::format("{:.6g}", l[2]);
  for (const std::string& same : std::vector<std::string>{
           l1 + " e₁ + " + l3 + " e₃", "(" + l3 + " e3 + " + l1 + " e1) kg m²/s",
           l1 + " \\hat{e}_1 + " + l3 + " \\hat{e}_3", "m R² ω sin α/4 e₁ + m R² ω cos α/2 e₃",
           "\\frac{m R^2 \\omega \\sin\\alpha}{4} \\hat{\\mathbf{e}}_1 + \\frac{m R^2 \\omega "
           "\\cos\\alpha}{2} \\vec{e}_{3}"}) {
    INFO(same);
    REQUIRE(plate.check("L0_body", same).correct);
  }
  REQUIRE_FALSE(plate.check("L0_body", l1 + " e₃ + " + l3 + " e₁").correct);  // axes swapped
  // Two bases in one sum are no vector's components: x̂ is in space, e₃ in the body.
  REQUIRE_THROWS_WITH(plate.check("L0_body", l1 + " x̂ + " + l3 + " e₃"),
                      Catch::Contains("mix bases"));
  // A primed e is a third basis (the Euler angles'); \vec{x} is a position, no unit vector.
  REQUIRE_THROWS_WITH(plate.check("L0_body", l1 + " e₁′ + " + l3 + " e₃"),
                      Catch::Contains("mix bases"));
  REQUIRE_THROWS_AS(plate.check("L0_body", l1 + " \\vec{x} + " + l3 + " \\vec{z}"), InputError);
  // Glued to its component, e₁ is a unit vector still (its subscript no exponent's digit: the
  // reading as written took 0.5e₁ for 5), and so refused where a number is asked for.
  REQUIRE(plate.check("L0_body", l1 + "e₁ + " + l3 + "e_3").correct);
  REQUIRE_THROWS_WITH(plate.check("I0", "7.2e₁"), Catch::Contains("not a 3-vector"));
  // An exponent's e stays a number's: 2e1 is 20, wherever unit vectors are read.
  REQUIRE_THROWS_WITH(plate.check("L0_body", "2e1"), Catch::Contains("not a number"));
  REQUIRE(plate.check("I0", fmt::format("{:.6g}e-2 kg m^2", plate.answer("I0").value.data[0] * 100))
              .correct);
}

TEST_CASE("a factor before a sum along unit vectors, and the statement's bare x, y, z") {
  // The flying plate's statement: ω(0) = ω(sin α x + cos α z). Ω_space = ω(sin α, 0, 2 cos α).
  const Fixture plate("flying-plate");
  for (const char* right : {"ω(sin α î + 2cos α k̂)", "ω (sin α x̂ + 2 cos α ẑ) rad/s",
                            "ω(sin α x + 2cos α z)", "10(0.2588190451 x + 1.931851653 z) rad/s",
                            "2.588190451 x + 19.31851653 z", "2.588190451x + 19.31851653z"}) {
    INFO(right);
    REQUIRE(plate.check("Omega_space", right).correct);
  }
  REQUIRE_FALSE(plate.check("Omega_space", "ω(sin α î + cos α k̂)").correct);
  const auto negated = plate.check("Omega_space", "-ω(sin α î + 2cos α k̂)");
  REQUIRE_FALSE(negated.correct);
  REQUIRE_THAT(negated.feedback.at(0), Catch::Contains("the sign is reversed"));
  // Not a sum before the bracket, a division by it, or a unit inside it with a factor outside.
  for (const char* refused :
       {"a + ω(sin α î + cos α k̂)", "ω/(sin α î + cos α k̂)", "ω(sin α î rad/s + 2cos α k̂)"}) {
    INFO(refused);
    REQUIRE_THROWS_WITH(plate.check("Omega_space", refused),
                        Catch::Contains("cannot read the components along unit vectors"));
  }
  // A bare x is a unit vector only in a sum of two terms or more along bare axes: not one term,
  // not an x between factors, not the times sign before a power of ten.
  REQUIRE_THROWS_WITH(plate.check("Omega_space", "19.31851653 z"), Catch::Contains("unit 'z'"));
  REQUIRE_THROWS_WITH(plate.check("I0", "m x R^2/4"), Catch::Contains("undefined symbol 'x'"));
  REQUIRE(plate.check("I0", "7.2 x 10^-4").correct);
  // In a list of axes a lone x, y or z is that axis, as the statements write e₁ = x; signed, or
  // after a label. The list still judges which vectors are axes.
  const Fixture masses("four-masses");  // axes (x̂ + ŷ)/√2, ẑ, (x̂ − ŷ)/√2
  for (const char* right : {"z, (x + y)/√2, (x − y)/√2", "(x + y)/√2, (x - y)/√2, -z",
                            "e1 = (x+y)/√2, e2 = −z, e3 = (x−y)/√2", "[x + y, z, x - y]"}) {
    INFO(right);
    REQUIRE(masses.check("principal_axes", right).correct);
  }
  REQUIRE_FALSE(masses.check("principal_axes", "x, y, z").correct);
}

TEST_CASE("components along the Euler angles' primed basis, e₁′, e₂′, e₃′, read as a vector") {
  const Fixture euler("euler-angles");  // omega_primed = (-φ̇ sin θ, θ̇, φ̇ cos θ + ψ̇)
  for (const std::string& same : std::vector<std::string>{
           "-φ̇ sin θ e₁′ + θ̇ e₂′ + (φ̇ cos θ + ψ̇) e₃′",
           "-phidot sin(theta) e_1' + thetadot e_2' + (phidot cos(theta) + psidot) e_3'",
           "-\\dot\\phi \\sin\\theta\\, \\hat{e}_1^\\prime + \\dot\\theta\\, "
           "\\hat{e}_{2}^{\\prime} + "
           "(\\dot\\phi\\cos\\theta + \\dot\\psi) \\hat{e}_3'"}) {
    INFO(same);
    REQUIRE(euler.check("omega_primed", same).correct);
  }
  REQUIRE_FALSE(euler.check("omega_primed", "φ̇ sin θ e₁′ + θ̇ e₂′ + (φ̇ cos θ + ψ̇) e₃′").correct);
  // The hint's ω = φ̇ z + θ̇ e₂′ + ψ̇ e₃ adds vectors of three bases: no one basis's components.
  REQUIRE_THROWS_WITH(euler.check("omega_primed", "φ̇ ẑ + θ̇ e₂′ + ψ̇ e₃"),
                      Catch::Contains("ẑ, ê₂′, ê₃ mix bases"));
}

TEST_CASE("the PHY 711 problem reads Taylor's φ, θ, ψ as its α, β, γ, and says so") {
  // Its [motion] table gives Taylor's angles as α, β, γ: the question relates the two, and a
  // student may answer in either names.
  const Fixture phy711("euler-angles-phy711");
  const std::string all = "read in Taylor's names, as this problem's symbols: φ = α, θ = β, ψ = γ";
  for (const auto& [name, typed, note] : std::vector<std::array<std::string, 3>>{
           {"angles_phy711", "(φ, θ, ψ)", all},
           {"angles_phy711", "(phi, theta, psi)", all},
           {"angles_zxz", "(φ + π/2, θ, ψ − π/2)", all},
           {"angles_phy711", "(α, θ, γ)",
            "read in Taylor's names, as this problem's symbols: θ = β"},
           {"R_phy711", "Rz(ψ)ᵀ Ry(θ)ᵀ Rz(φ)ᵀ", all},
           {"omega_primed", "(−φ̇ sin θ, θ̇, φ̇ cos θ + ψ̇)",
            "read in Taylor's names, as this problem's symbols: θ = β, φ̇ = α̇, θ̇ = β̇, ψ̇ = γ̇"},
           {"kinetic_energy", "I1/2 (φ̇² sin²θ + θ̇²) + I3/2 (φ̇ cos θ + ψ̇)²",
            "read in Taylor's names, as this problem's symbols: θ = β, φ̇ = α̇, θ̇ = β̇, ψ̇ = γ̇"},
           // Run together with the problem's own names, as a hand writes a product.
           {"L_primed", "(−I1φ̇ sin θ, I1θ̇, I3(φ̇cosθ + ψ̇))",
            "read in Taylor's names, as this problem's symbols: θ = β, φ̇ = α̇, θ̇ = β̇, ψ̇ = γ̇"},
           // In LaTeX, as a LaTeX key of Taylor's problem writes them.
           {"angles_zxz", "(\\phi + \\frac{\\pi}{2}, \\theta, \\psi - \\pi/2)", all},
           {"omega_primed",
            "\\begin{pmatrix} -\\dot\\phi \\sin\\theta \\\\ \\dot{\\theta} \\\\ "
            "\\dot\\phi\\cos\\theta + \\dot\\psi \\end{pmatrix}",
            "read in Taylor's names, as this problem's symbols: θ = β, φ̇ = α̇, θ̇ = β̇, ψ̇ = γ̇"},
           {"kinetic_energy",
            "\\frac{I_1}{2}(\\dot{\\varphi}^2 \\sin^2\\theta + \\dot\\theta^2) + "
            "\\frac{I_3}{2}(\\dot\\phi\\cos\\theta + \\dot\\psi)^2",
            "read in Taylor's names, as this problem's symbols: θ = β, φ̇ = α̇, θ̇ = β̇, ψ̇ = γ̇"}}) {
    INFO(name << ": " << typed);
    const auto v = phy711.check(name, typed);
    REQUIRE(v.correct);
    REQUIRE(v.feedback == std::vector<std::string>{note});
  }
  // Read so, a wrong answer is still wrong, and says how it was read (in the convention's
  // order, as every note is).
  const auto swapped = phy711.check("angles_phy711", "(θ, φ, ψ)");
  REQUIRE_FALSE(swapped.correct);
  REQUIRE(swapped.feedback.back() == all);
  // What still keeps such an answer from reading is said: a vector for a matrix, a name the
  // problem lacks (in the entry it is in).
  REQUIRE_THROWS_WITH(phy711.check("R_phy711", "(φ, θ, ψ)"),
                      !Catch::Contains("undefined symbol") && Catch::Contains("3-vector"));
  REQUIRE_THROWS_WITH(phy711.check("angles_phy711", "(φ, θ, q)"),
                      Catch::StartsWith("--answer[2]: cannot read expression \"q\": undefined "
                                        "symbol 'q'"));
  REQUIRE_THROWS_WITH(phy711.check("angles_phy711", "(φ + q, θ, ψ)"),
                      Catch::StartsWith("--answer[0]: cannot read expression \"phi + q\": "
                                        "undefined symbol 'q'"));
  // In LaTeX too: the name that still keeps the answer from reading is said, not Taylor's.
  REQUIRE_THROWS_WITH(phy711.check("angles_phy711", "(\\phi, \\theta, q)"),
                      Catch::Contains("q is not one of this problem's symbols"));
  const auto swapped_latex = phy711.check("angles_phy711", "(\\theta, \\phi, \\psi)");
  REQUIRE_FALSE(swapped_latex.correct);
  REQUIRE(swapped_latex.feedback.back() == all);
  // Taylor's problem has no other names: PHY 711's there are refused, with its symbols listed.
  const Fixture taylor("euler-angles");
  REQUIRE_THROWS_WITH(taylor.check("angles_phy711", "(α, β, γ)"),
                      Catch::Contains("undefined symbol 'alpha'"));
  REQUIRE_THROWS_WITH(taylor.check("angles_phy711", "(\\alpha, \\beta, \\gamma)"),
                      Catch::Contains("\\alpha is not one of this problem's symbols"));
}

TEST_CASE("an earlier answer's name in an answer is its closed form, said; others are refused") {
  // Question (a) writes I = I₀ diag(…): a student answers I so, with part (a)'s I₀, read as the
  // key's I₀ and said so.
  const Fixture plate("flying-plate");
  const std::string i0_note =
      "read with I0 = m·R²/4, the key's answer to part (a): right as far as your I0 is";
  for (const char* same : {"I₀ diag(1, 1, 2)", "I = I₀ diag(1, 1, 2)", "I_0*diag(1,1,2)",
                           "diag(1, 1, 2)I₀", "[[I0, 0, 0], [0, I0, 0], [0, 0, 2I0]]"}) {
    INFO(same);
    const auto v = plate.check("I", same);
    REQUIRE(v.correct);
    REQUIRE(v.feedback == std::vector<std::string>{i0_note});
  }
  // In LaTeX too, as the question draws I_0.
  for (const char* same : {"I_0 \\mathrm{diag}(1, 1, 2)", "I_{0}\\,\\mathrm{diag}(1,1,2)",
                           "\\begin{pmatrix} I_0 & 0 & 0 \\\\ 0 & I_0 & 0 \\\\ 0 & 0 & 2 I_0 "
                           "\\end{pmatrix}"}) {
    INFO(same);
    const auto v = plate.check("I", same);
    REQUIRE(v.correct);
    REQUIRE(v.feedback == std::vector<std::string>{i0_note});
  }
  // Run together with a symbol, "I₀ω", and in a sum along unit vectors, hatted or not: L at
  // t = 0 as I₀ω(sin α e₁ + 2 cos α e₃).
  for (const char* same :
       {"(I₀ω sin α, 0, 2I₀ω cos α)", "I₀ω (sin α, 0, 2 cos α)", "I₀ω sin α ê₁ + 2I₀ω cos α ê₃",
        "I₀ω sin α e₁ + 2I₀ω cos α e₃", "I0*omega*sin(alpha) e1 + 2*I0*omega*cos(alpha) e3"}) {
    INFO(same);
    const auto v = plate.check("L0_body", same);
    REQUIRE(v.correct);
    REQUIRE(v.feedback == std::vector<std::string>{i0_note});
  }
  REQUIRE_FALSE(plate.check("L0_body", "I₀ω sin α ê₁ + I₀ω cos α ê₃").correct);
  // Two bases stay refused so: x̂ is in space, ê₃ in the body.
  REQUIRE_THROWS_WITH(plate.check("L0_body", "I₀ω sin α x̂ + 2I₀ω cos α ê₃"),
                      Catch::Contains("mix bases"));
  const auto doubled = plate.check("I", "I₀ diag(2, 2, 4)");
  REQUIRE_FALSE(doubled.correct);
  // Read so and wrong: the line says how, not that it is "right as far as" I0 is.
  REQUIRE_THAT(doubled.feedback.back(),
               Catch::Equals("read with I0 = m·R²/4, the key's answer to part (a)"));
  // t_max in terms of part (e)'s rate, as half its period.
  const auto half = plate.check("t_max", "π/Ω_space_rate");
  REQUIRE(half.correct);
  REQUIRE_THAT(half.feedback.back(), Catch::StartsWith("read with Omega_space_rate = ω·√("));
  REQUIRE_FALSE(plate.check("t_max", "2π/Omega_space_rate").correct);
  // Before an '=' and a value, such a formula is a side, judged, where it is right; else a label.
  const std::string t_max = fmt::format("{:.6g} s", plate.answer("t_max").value.data.at(0));
  const auto both = plate.check("t_max", "π/Ω_space_rate = " + t_max);
  REQUIRE(both.correct);
  REQUIRE(both.feedback.size() == 1);
  REQUIRE_THAT(both.feedback[0], Catch::StartsWith("read with Omega_space_rate"));
  const auto value_wrong = plate.check("t_max", "π/Ω_space_rate = 0.2 s");
  REQUIRE_FALSE(value_wrong.correct);
  REQUIRE(value_wrong.feedback.at(0) == "the side \"0.2 s\" of your '='");
  REQUIRE_THAT(plate.check("t_max", "2π/Ω_space_rate = " + t_max).feedback.back(),
               Catch::Contains("taken as a label"));
  // A form too long for the line is not written out: the tennis racket's period, some 400
  // characters of elliptic integral, is named.
  const Fixture racket("tennis-racket");
  const auto half_period = racket.check("flip_interval", "period/2");
  REQUIRE(half_period.correct);
  REQUIRE(half_period.feedback ==
          std::vector<std::string>{"read with period as the key's answer to part (c): right as "
                                   "far as your period is"});
  // A vector's name reads where a vector does: L in space at t = 0 is L in the body, the frames
  // being one then. Its closed form is not written out in the line, its name says which.
  const auto at_start = plate.check("L0_space", "L0_body");
  REQUIRE(at_start.correct);
  REQUIRE(at_start.feedback == std::vector<std::string>{"read with L0_body as the key's answer to "
                                                        "part (b): right as far as your L0_body "
                                                        "is"});
  // After a number, where a unit would stand, the name is read all the same: twice L is wrong.
  const auto twice = plate.check("L0_space", "2 L0_body");
  REQUIRE_FALSE(twice.correct);
  REQUIRE_THAT(twice.feedback.front(), Catch::StartsWith("this is 2 times the answer"));
  // Not a later part's answer, not the answer itself: refused with whose name it is.
  REQUIRE_THROWS_WITH(plate.check("Omega_space_rate", "2 t_max/π"),
                      Catch::Contains("t_max is the answer to part (h)"));
  REQUIRE_THROWS_WITH(plate.check("t_max", "t_max"),
                      Catch::Contains("t_max is the answer to part (h)"));
  // Where another name still keeps it from reading, that name is said, in the text as typed.
  const Fixture asymmetric("asymmetric-top");
  REQUIRE_THROWS_WITH(
      asymmetric.check("period", "4K(k)/μ"),
      Catch::Contains("\"4*EllipticK(k)/mu\": undefined symbol 'mu'") && !Catch::Contains("sqrt"));
  // A Greek subscript after '_' belongs to the name: p_ψ is the heavy top's p_psi, not "p_".
  const Fixture top("heavy-top");
  for (const char* with_other_answer : {"p_ψ cos θ₀", "p_ψ·cos(θ₀)", "p_psi cos θ₀"}) {
    INFO(with_other_answer);
    const auto v = top.check("p_phi", with_other_answer);
    REQUIRE(v.correct);
    REQUIRE_THAT(v.feedback.back(), Catch::StartsWith("read with p_psi = M·R²·ψ̇0/2"));
  }
  // A name that is no answer gets no such line.
  REQUIRE_THROWS_WITH(plate.check("I0", "M R^2/4"), !Catch::Contains("is the answer to"));
  // Ω_body as the Earth's question (a) writes the answer Omega_body_rate: the one answer the
  // name begins is read, and the line says which; Ω alone begins two and is refused.
  const Fixture wobble_rate("earth-free-precession");
  const auto euler_period = wobble_rate.check("precession_period_body", "2π/Ω_body");
  REQUIRE(euler_period.correct);
  REQUIRE(euler_period.feedback ==
          std::vector<std::string>{"read with Ω_body as Omega_body_rate = H·ω·cos(α)/(1 - "
                                   "H), the key's answer to part (a): right as far as your "
                                   "Ω_body is"});
  REQUIRE_FALSE(wobble_rate.check("precession_period_body", "π/Ω_body").correct);
  REQUIRE_THROWS_WITH(wobble_rate.check("Omega_body_rate", "Ω_body"),
                      Catch::Contains("Omega_body names the answer Omega_body_rate (part (a))"));
  // Ω as a book writes the precession rate: the answers it names, and no "unit 'pi/Omega'".
  const Fixture earth("earth-free-precession");
  REQUIRE_THROWS_WITH(
      earth.check("precession_period_body", "2π/Ω"),
      Catch::Contains("undefined symbol 'Omega'") &&
          Catch::Contains("Omega names the answers Omega_body_rate (part (a)), Omega_space_rate") &&
          !Catch::Contains("unit"));
}

TEST_CASE("a refused norm(..) names the norms that read here, over the catalog") {
  // norm(..) reads only around an earlier vector answer's name; where it is refused (a typo, a
  // number's name), the line lists those it reads around, and each listed one reads.
  constexpr std::string_view kSaid = "(norm(..) reads only around a vector answer's name: ";
  std::size_t listed = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.value.shape != Value::Shape::scalar || a.symbolic.empty()) continue;
        INFO(p.id << " " << a.name);
        std::string message;
        try {
          (void)f.check(a.name, "1/norm(x~y)");
        } catch (const InputError& e) {
          message = e.what();
        }
        const std::size_t at = message.find(kSaid);
        REQUIRE(at != std::string::npos);
        REQUIRE_THAT(message, Catch::EndsWith("; a number's size is abs(..))"));
        // "here norm(L0_body), norm(Omega_space)", or that there is none.
        for (std::size_t open = message.find("norm(", at + kSaid.size()); open != std::string::npos;
             open = message.find("norm(", open + 1)) {
          const std::string call = message.substr(open, message.find(')', open) + 1 - open);
          INFO(call);
          REQUIRE_NOTHROW(f.check(a.name, "1/" + call));
          ++listed;
        }
      }
    }
  }
  REQUIRE(listed > 0);
}

TEST_CASE("a magnitude in bars reads, of an expression or of an earlier vector answer") {
  // |x| as a student writes it, with a bar after an operand closing the one open.
  const Fixture plate("flying-plate");
  for (const char* same :
       {"|m R^2/4|", "m |R|^2/4", "|−m R²/4|", "2|m R^2/8|", "|m| |R|^2/4", "‖m R²/4‖"}) {
    INFO(same);
    REQUIRE(plate.check("I0", same).correct);
  }
  REQUIRE_FALSE(plate.check("I0", "|m R^2/2|").correct);
  // A bar that pairs with none is refused, not dropped.
  REQUIRE_THROWS_AS(plate.check("I0", "m R^2/4 |"), InputError);
  // The statement writes t = π/|Ω_space|: the vector answer's magnitude, and the line says so.
  const std::string note =
      "read with Omega_space as the key's answer to part (e): right as far as your Omega_space is";
  for (const char* same : {"π/|Ω_space|", "pi/norm(Omega_space)", "π/‖Ω_space‖"}) {
    INFO(same);
    const auto v = plate.check("t_max", same);
    REQUIRE(v.correct);
    REQUIRE(v.feedback == std::vector<std::string>{note});
  }
  const auto twice = plate.check("t_max", "2π/|Ω_space|");
  REQUIRE_FALSE(twice.correct);  // read so, and not "right as far as" Ω_space is
  REQUIRE(twice.feedback.back() == "read with Omega_space as the key's answer to part (e)");
  // In LaTeX, with the subscript in words as the statement writes it (\mathrm, \text).
  for (const char* same :
       {"\\frac{\\pi}{|\\Omega_{space}|}", "\\pi/\\lvert\\Omega_\\mathrm{space}\\rvert",
        "\\frac{\\pi}{\\left|\\Omega_\\text{space}\\right|}"}) {
    INFO(same);
    const auto v = plate.check("t_max", same);
    REQUIRE(v.correct);
    REQUIRE(v.feedback == std::vector<std::string>{note});
  }
  // A subscript of words joined by commas is the name they join: Ω_space_rate, L0_body.
  REQUIRE(plate.check("t_max", "\\frac{\\pi}{\\Omega_{space,rate}}").correct);
  REQUIRE(plate.check("L0_space", "L_{0,\\mathrm{body}}").correct);
  // A vector's name alone where a number is wanted is its size, as books write Ω for the rate:
  // typed or in LaTeX, and the line says so. Where the vector itself is wanted it is refused.
  const std::string size_note =
      "read with Omega_space as its size |Omega_space| (the key's "
      "answer to part (e) is a vector)";
  for (const char* same : {"π/Ω_space", "pi/Omega_space", "\\pi/\\Omega_\\mathrm{space}"}) {
    INFO(same);
    const auto v = plate.check("t_max", same);
    REQUIRE(v.correct);
    REQUIRE(v.feedback ==
            std::vector<std::string>{size_note + ": right as far as your Omega_space is"});
  }
  const auto period = plate.check("t_max", "2π/Ω_space");
  REQUIRE_FALSE(period.correct);
  REQUIRE(period.feedback.back() == size_note);
  // A vector's name in a sum with a number: read, the text is refused with how it was read.
  REQUIRE_THROWS_WITH(plate.check("Omega_space", "Ω_body + ω"),
                      Catch::Contains("\"Omega_body + omega\", read with Omega_body as the key's "
                                      "answer to part (e): it is not a complete expression"));
  REQUIRE_THROWS_WITH(plate.check("Omega_space", "Ω_body + Q"),
                      Catch::Contains("undefined symbol 'Q'") &&
                          Catch::Contains("(the key's answers' names up to part (e) read too)"));
  // The magnitude of a name that is no answer is refused as that name.
  REQUIRE_THROWS_WITH(plate.check("t_max", "π/|Q|"), Catch::Contains("undefined symbol 'Q'"));
}

TEST_CASE(
    "a part's answers in one box, each labelled: this answer's is judged, the rest said not") {
  // Both precession rates of the heavy top's part (d), as a student writes them down.
  const Fixture top("heavy-top");
  const std::string slow = format_number(top.answer("phidot_slow").value.data.at(0));
  const std::string fast = format_number(top.answer("phidot_fast").value.data.at(0));
  const std::string both = "φ̇_slow = " + slow + " rad/s, φ̇_fast = " + fast + " rad/s";
  const auto v = top.check("phidot_slow", both);
  REQUIRE(v.correct);
  REQUIRE(v.feedback == std::vector<std::string>{"φ̇_fast = " + fast +
                                                 " rad/s (phidot_fast) not judged here: give "
                                                 "each answer on its own"});
  REQUIRE(top.check("phidot_fast", both).correct);
  // This answer's value is judged as it stands: a wrong one is wrong.
  REQUIRE_FALSE(top.check("phidot_fast", "φ̇_slow = " + slow + " rad/s, φ̇_fast = 30 rad/s").correct);
  // Labels that are no answer's name, or the answer labelled twice, are no such list.
  REQUIRE_THROWS(top.check("phidot_slow", "slow = " + slow + ", fast = " + fast));
  REQUIRE_THROWS(top.check("phidot_slow", "φ̇_slow = " + slow + ", φ̇_slow = " + fast));
}

TEST_CASE("a 3-vector's components given in part are read with the others zero, and said so") {
  // The cone's centre of mass on its axis, as "z_cm = −3h/4" gives it.
  const Fixture cone("solid-cone");
  for (const std::string same : {"z = −3h/4", "z_cm = -3h/4", "x_cm = 0, z_cm = -3h/4"}) {
    INFO(same);
    const auto v = cone.check("center_of_mass", same);
    REQUIRE(v.correct);
    REQUIRE_THAT(v.feedback.back(), Catch::EndsWith("not given, taken as zero"));
  }
  REQUIRE(cone.check("center_of_mass", "z = -3h/4").feedback.back() ==
          "read as [0, 0, -3h/4]: x, y not given, taken as zero");
  // The wrong axis, or a component not zero left out, is wrong, the reading said.
  const auto wrong_axis = cone.check("center_of_mass", "x_cm = -3h/4");
  REQUIRE_FALSE(wrong_axis.correct);
  REQUIRE(wrong_axis.feedback.back() == "read as [-3h/4, 0, 0]: y, z not given, taken as zero");
  // Along the body's axes the entries are named as the key names them.
  const Fixture plate("flying-plate");
  const std::string along_e3 = format_number(plate.answer("L0_body").value.data.at(2));
  const auto body = plate.check("L0_body", "L₃ = " + along_e3);
  REQUIRE_FALSE(body.correct);  // its e₁ component is not zero
  REQUIRE(body.feedback.back() ==
          "read as [0, 0, " + along_e3 + "]: e₁, e₂ not given, taken as zero");
  // A name whose last letter is no axis ("Ω_body") labels the whole vector; a number answer
  // keeps its label; principal moments are never given in part.
  const Fixture square("flying-square-plate");
  REQUIRE(square.check("Omega_body", "Ω_body = (0, 0, 9.659258263)").correct);
  REQUIRE(square.check("Omega_body", "ω_z = 9.659258263 rad/s").correct);
  const Fixture top("heavy-top");
  REQUIRE(top.check("omega3", "ω₃ = 150 rad/s").correct);
  const Fixture taylor("taylor-10-35");
  REQUIRE_THROWS_WITH(taylor.check("principal_moments", "I1 = 5"),
                      Catch::Contains("wants a 3-vector"));
  // The primed basis's components, labelled with their primes.
  const Fixture euler("euler-angles-phy711");
  const auto primed = euler.check("omega_primed", "ω₁′ = −α̇ sin β, ω₃′ = α̇ cos β + γ̇");
  REQUIRE_FALSE(primed.correct);  // its e₂′ component, β̇, is not zero
  REQUIRE(primed.feedback.back() ==
          "read as [−α̇ sin β, 0, α̇ cos β + γ̇]: e₂′ not given, taken as zero");
}

TEST_CASE("an entry refused is named, not an earlier one whose bare call the reader mends") {
  // "sin β" reads once the factors' stars are written in; the third entry's prime never does.
  const Fixture euler("euler-angles-phy711");
  REQUIRE_THROWS_WITH(euler.check("L_primed", "[sin β, 1, q′]"),
                      Catch::StartsWith("--answer[2]: expression \"q′\" is refused"));
  REQUIRE_THROWS_WITH(euler.check("L_primed", "L₁′ = −I₁ α̇ sin β, L₂′ = I₁ β̇, L₃′ = I₃ q′"),
                      Catch::StartsWith("--answer[2]:") && !Catch::Contains("sin is a function"));
  // With the steps' ω₃′ the same entries read, each as any answer's value does.
  REQUIRE(euler.check("L_primed", "L₁′ = −I₁ α̇ sin β, L₂′ = I₁ β̇, L₃′ = I₃ ω₃′").correct);
}

TEST_CASE(
    "a factor after a list's last number is that entry's, and the line says how to share it") {
  // Taylor 10.35's moments (5, 7, 10) m a², as "5, 7, 10 ma²" reads: 10 m a² alone.
  const Fixture taylor("taylor-10-35");
  for (const std::string typed : {"5, 7, 10 ma²", "5, 7, 10 * m*a^2", "λ = 5, 7, 10 m a^2"}) {
    INFO(typed);
    const auto v = taylor.check("principal_moments", typed);
    REQUIRE_FALSE(v.correct);
    REQUIRE(v.feedback.size() == 1);
    REQUIRE_THAT(v.feedback[0], Catch::Contains("after the last number multiplies that entry "
                                                "alone; for it to multiply each, write (5, 7, "
                                                "10) m"));
  }
  REQUIRE(taylor.check("principal_moments", "(5, 7, 10) ma²").correct);
  // Not where sharing the factor is wrong too: the usual diagnosis.
  const auto off = taylor.check("principal_moments", "5, 7, 11 ma²");
  REQUIRE_FALSE(off.correct);
  REQUIRE_THAT(off.feedback.at(0), !Catch::Contains("after the last number"));
}

TEST_CASE("where a number is asked for, a bare k is a name of the student's own, no unit vector") {
  // The asymmetric top's modulus k, its square and k'² = 1 - k², as a student labels them.
  const Fixture top("asymmetric-top");
  const auto value = [&](const std::string& name) {
    return format_number(top.answer(name).value.data.at(0));
  };
  const std::string kc2 = value("kc2");
  // k′² names kc2 itself, as its note writes it (k'² = 1 − k²): the label of its own answer,
  // nothing to say; another answer's, k², is said to be taken as a label.
  for (const std::string label : {"k'^2", "k′²"}) {
    INFO(label);
    const auto v = top.check("kc2", label + " = " + kc2);
    REQUIRE(v.correct);
    REQUIRE(v.feedback.empty());
  }
  const auto other = top.check("kc2", "k^2 = " + kc2);
  REQUIRE(other.correct);
  REQUIRE(other.feedback == std::vector<std::string>{"the side \"k^2\" of your '=' is taken as a "
                                                     "label, not judged: k is the key's answer to "
                                                     "part (c), no symbol"});
  // 1 − k², in the same part's k, is a side: judged with the key's k, and said so (by name: its
  // form is longer than a line).
  for (const std::string side : {"1 − k²", "1 - k^2"}) {
    INFO(side);
    const auto v = top.check("kc2", side + " = " + kc2);
    REQUIRE(v.correct);
    REQUIRE(v.feedback.size() == 1);
    REQUIRE_THAT(v.feedback[0], Catch::StartsWith("read with k as the key's answer to part (c)"));
  }
  REQUIRE(top.check("k2", "k² = " + value("k2")).correct);
  // Which answer a labelled value is, where it is another part's.
  REQUIRE_THAT(top.check("k2", "k′² = " + kc2).feedback.at(0), Catch::Contains("this is kc2"));
  // A formula in an earlier answer's name (k) and the steps' (λ) between a label and the value
  // is judged too, and the lines say how; K is the complete integral.
  const std::string period = value("period") + " s";
  const auto labelled = top.check("period", "T = 4K(k)/λ = " + period);
  REQUIRE(labelled.correct);
  REQUIRE(labelled.feedback.size() == 2);
  REQUIRE_THAT(labelled.feedback.front(), Catch::StartsWith("read with λ = √("));
  REQUIRE_THAT(labelled.feedback.back(), Catch::StartsWith("read with k as the key's answer"));
  // Wrong, that side is a label, not judged: k is an answer, no symbol, and the line says
  // whose.
  const auto wrong_side = top.check("period", "T = 2K(k)/λ = " + period);
  REQUIRE(wrong_side.correct);
  REQUIRE(wrong_side.feedback ==
          std::vector<std::string>{"the side \"2K(k)/λ\" of your '=' is taken as a label, not "
                                   "judged: k is the key's answer to part (c), no symbol"});
  // K(k) as books write the complete elliptic integral of the first kind (of the modulus, as the
  // key's EllipticK): glued to its factor or not, in LaTeX, and in the problem's symbols.
  const double lambda = 4 * std::comp_ellint_1(top.answer("k").value.data.at(0)) /
                        top.answer("period").value.data.at(0);
  const std::string k = value("k"), rate = format_number(lambda);
  for (const std::string& same :
       {"4K(" + k + ")/" + rate, "4 K(" + k + ") / " + rate + " s", "4*K(" + k + ")/" + rate,
        "\\frac{4K(" + k + ")}{" + rate + "}", "4K\\left(" + k + "\\right)/" + rate,
        std::string("4K(√((I₁−I₂)(I₁ω₁²(I₁−I₃) + I₂ω₂²(I₂−I₃))/((I₂−I₃)(I₂ω₂²(I₁−I₂) + "
                    "I₃ω₃²(I₁−I₃)))))/√((I₁I₂ω₂² + I₁I₃ω₃² − I₂²ω₂² − I₃²ω₃²)(I₂ − "
                    "I₃)/(I₁I₂I₃))")}) {
    INFO(same);
    REQUIRE(top.check("period", same).correct);
  }
  // K alone, not before a bracket, is still no symbol here; where a problem has a symbol K, K(..)
  // is not the integral.
  REQUIRE_THROWS_WITH(top.check("period", "K/" + rate), Catch::Contains("undefined symbol 'K'"));
  const auto none = [](const std::string&) { return false; };
  const auto has_K = [](const std::string& name) { return name == "K"; };
  CHECK(check::elliptic_integral_named("4 K(k)/L", none) == "4*EllipticK(k)/L");
  CHECK(check::elliptic_integral_named("(a+b)K(k)", none) == "(a+b)*EllipticK(k)");
  CHECK(check::elliptic_integral_named("K (k) + MK(k) + K_1(k)", none) ==
        "EllipticK (k) + MK(k) + K_1(k)");
  CHECK(check::elliptic_integral_named("4 K(k)/L", has_K) == "4 K(k)/L");
  REQUIRE(top.check("period", period + " = 4K(k)/λ").correct);
  const auto wrong = top.check(
      "period", "4K(k)/λ = " + format_number(top.answer("period").value.data.at(0) * 1.1) + " s");
  REQUIRE_FALSE(wrong.correct);
  // The value's side is wrong (the formula's, read with the key's k and the steps' λ, is right).
  REQUIRE_THAT(wrong.feedback.at(0), Catch::StartsWith("the side \"2.39"));
  REQUIRE_THAT(wrong.feedback.at(1), Catch::Contains("off by 10%"));
  // Alone, such a k is part (c)'s own answer k, the key's closed form read for it (and said):
  // no "unit vectors" line, no "3-vector".
  for (const auto& [name, typed] :
       std::vector<std::pair<std::string, std::string>>{{"kc2", "1 - k^2"}, {"k2", "k²"}}) {
    INFO(typed);
    const auto v = top.check(name, typed);
    REQUIRE(v.correct);
    REQUIRE_THAT(v.feedback.back(), Catch::StartsWith("read with k as the key's answer"));
  }
  REQUIRE_FALSE(top.check("kc2", "1 + k^2").correct);
  // Where a vector is asked for, i, j and k are still unit vectors, and a sum along them that
  // does not read is said so.
  REQUIRE(top.check("dw_dt0", "-0.5 i + j - 0.015 k").correct);
  REQUIRE_THROWS_WITH(top.check("dw_dt0", "-0.5 i + j^2 - 0.015 k"),
                      Catch::Contains("cannot read the components along unit vectors"));
}

TEST_CASE(
    "a formula in names the problem lacks beside '=' labels the value, and is said unjudged") {
  // The racket flips each half period: "T/2 = 1.91 s", T the student's own name for the period
  // (the steps' T is the energy: as that, the side has no time's dimension, and the line says
  // what T is here).
  const Fixture racket("tennis-racket");
  const std::string energy_label =
      "the side \"T/2\" of your '=' is taken as a label, not judged: T is energy here, the key's "
      "answer to part (c)";
  const auto right = racket.check("flip_interval", "T/2 = 1.91 s");
  REQUIRE(right.correct);
  REQUIRE(right.feedback == std::vector<std::string>{energy_label});
  // The value is still judged, and its mistake named before the note.
  const auto wrong = racket.check("flip_interval", "T/2 = 2.5 s");
  REQUIRE_FALSE(wrong.correct);
  REQUIRE(wrong.feedback.size() == 2);
  REQUIRE_THAT(wrong.feedback[0], Catch::Contains("off by 31%"));
  REQUIRE_THAT(wrong.feedback[1], Catch::Contains("taken as a label"));
  // After the value, the same: the value judged first, the label said unjudged.
  const auto after = racket.check("flip_interval", "1.91 s = T/2");
  REQUIRE(after.correct);
  REQUIRE(after.feedback == std::vector<std::string>{energy_label});
  // A name that is no symbol and none of the key's stays "no symbol".
  REQUIRE(racket.check("flip_interval", "P/2 = 1.91 s").feedback ==
          std::vector<std::string>{"the side \"P/2\" of your '=' is taken as a label, not judged: "
                                   "P is no symbol here"});
  const auto wrong_after = racket.check("flip_interval", "2.5 s = T/2");
  REQUIRE_FALSE(wrong_after.correct);
  REQUIRE_THAT(wrong_after.feedback[0], Catch::Equals("the side \"2.5 s\" of your '='"));
  // A label of one name after the value, as before it, is no formula to note.
  const auto named = racket.check("flip_interval", "1.91 s = t_flip");
  REQUIRE(named.correct);
  REQUIRE(named.feedback.empty());
  // Neither side readable: the first side's error, naming the name.
  REQUIRE_THROWS_WITH(racket.check("flip_interval", "T/2 = τ/2"),
                      Catch::Contains("undefined symbol"));
  // A left side in the problem's symbols is judged as before: a wrong formula is wrong.
  REQUIRE_FALSE(racket.check("flip_interval", "m a = 1.91 s").correct);
}

TEST_CASE("vectors added, each with its factor, read as their sum: ω from the Euler rates") {
  // ω = φ̇ ẑ + θ̇ ê_N + ψ̇ ê₃, each axis written in the space basis, as the lecture builds it.
  const Fixture euler("euler-angles");
  for (const char* same :
       {"φ̇ (0, 0, 1) + θ̇ (−sin φ, cos φ, 0) + ψ̇ (sin θ cos φ, sin θ sin φ, cos θ)",
        "φ̇ [0,0,1] + θ̇ [−sin φ, cos φ, 0] + ψ̇ [sinθ cosφ, sinθ sinφ, cosθ]",
        "φ̇ ẑ + θ̇ (−sin φ, cos φ, 0) + ψ̇ (sin θ cos φ, sin θ sin φ, cos θ)",
        "ψ̇ (sin θ cos φ, sin θ sin φ, cos θ) - θ̇ (sin φ, −cos φ, 0) + (0, 0, φ̇)",
        // The same in LaTeX, the hat a unit vector and the brackets a tuple or a pmatrix
        // (whose entries' signs are no terms of the sum).
        "\\dot\\phi \\hat z + \\dot\\theta (-\\sin\\phi, \\cos\\phi, 0) + \\dot\\psi "
        "(\\cos\\phi \\sin\\theta, \\sin\\phi \\sin\\theta, \\cos\\theta)",
        "\\dot{\\phi}\\,\\hat{\\mathbf{z}} - \\dot\\theta \\begin{pmatrix} \\sin\\phi \\\\ "
        "-\\cos\\phi \\\\ 0 \\end{pmatrix} + \\dot\\psi \\begin{pmatrix} \\cos\\phi "
        "\\sin\\theta \\\\ \\sin\\phi \\sin\\theta \\\\ \\cos\\theta \\end{pmatrix}"}) {
    INFO(same);
    REQUIRE(euler.check("omega_space", same).correct);
  }
  REQUIRE_FALSE(euler
                    .check("omega_space",
                           "\\dot\\phi \\hat z + \\dot\\theta (\\sin\\phi, "
                           "-\\cos\\phi, 0) + \\dot\\psi (\\cos\\phi "
                           "\\sin\\theta, \\sin\\phi \\sin\\theta, "
                           "\\cos\\theta)")
                    .correct);
  // Nor in LaTeX do vectors of two bases add.
  REQUIRE_THROWS_WITH(
      euler.check("omega_space",
                  "\\dot\\phi \\hat z + \\dot\\theta (0, 1, 0) + \\dot\\psi \\hat e_3"),
      Catch::Contains("ẑ, ê₃ mix bases"));
  // The line of nodes' sign turned: a wrong sum is judged wrong, entry by entry.
  const auto wrong = euler.check(
      "omega_space", "φ̇ (0, 0, 1) + θ̇ (sin φ, −cos φ, 0) + ψ̇ (sin θ cos φ, sin θ sin φ, cos θ)");
  REQUIRE_FALSE(wrong.correct);
  REQUIRE_THAT(wrong.feedback.at(0), Catch::StartsWith("entry x is off by"));
  // The box's centre, edge by edge; vectors of two sizes do not add.
  const Fixture box("box-corner");
  REQUIRE(box.check("center_of_mass", "(a, 0, 0)/2 + (0, b, 0)/2 + (0, 0, c)/2").correct);
  REQUIRE_THROWS_AS(box.check("center_of_mass", "(a, 0, 0)/2 + (0, b)/2"), InputError);
  // A number added to a vector is no sum of vectors.
  REQUIRE_THROWS_AS(box.check("center_of_mass", "(a, b, c)/2 + 1"), InputError);
}

TEST_CASE("a symbol after a number is a unit where that reads, else a factor, and it is said") {
  // The cone's centre of mass, −3h/4 along z, h the height (and hours).
  const Fixture cone("solid-cone");
  REQUIRE(cone.check("center_of_mass", "-0.75*h ẑ").correct);
  REQUIRE(cone.check("center_of_mass", "-0.75*h*k̂").correct);
  REQUIRE_FALSE(cone.check("center_of_mass", "2*h k̂").correct);  // judged, not hours
  REQUIRE(cone.check("center_of_mass", "-0.225 m k̂").correct);   // a unit after a space
  // After a space h reads as hours, which no length is: the height it must be, and the line
  // says how it was read. Judged so, right or wrong.
  const auto height = cone.check("center_of_mass", "-0.75 h k̂");
  REQUIRE(height.correct);
  REQUIRE(height.feedback ==
          std::vector<std::string>{"read as -0.75*h k̂, h the problem's symbol for the height: "
                                   "after a number alone it would be the unit"});
  REQUIRE(cone.check("center_of_mass", "(0, 0, -3/4 h)").correct);
  REQUIRE(cone.check("center_of_mass", "-0.75h ẑ").correct);  // glued, as "3h" is three hours
  // In LaTeX, after a fraction or a thin space.
  REQUIRE(cone.check("center_of_mass", "-\\frac{3}{4} h \\hat{z}").correct);
  REQUIRE(cone.check("center_of_mass", "-0.75\\,h\\,\\hat{z}").correct);
  // And after a tie, LaTeX's unbreakable space; judged, right or wrong.
  const auto tied = cone.check("center_of_mass", "-0.75~h~\\hat{z}");
  REQUIRE(tied.correct);
  // The line shows LaTeX's spaces as spaces.
  REQUIRE(tied.feedback.front() ==
          "read as -0.75*h \\hat{z}, h the problem's symbol for the "
          "height: after a number alone it would be the unit");
  REQUIRE(cone.check("center_of_mass", "-\\frac{3}{4}~h~\\hat{z}").correct);
  REQUIRE_FALSE(cone.check("center_of_mass", "-0.5~h~\\hat{z}").correct);
  REQUIRE(cone.check("center_of_mass", "r_cm = -(3/4) h ẑ").correct);
  const auto reversed = cone.check("center_of_mass", "(0, 0, 0.75 h)");
  REQUIRE_FALSE(reversed.correct);
  REQUIRE_THAT(reversed.feedback.at(0), Catch::StartsWith("read as (0, 0, 0.75*h), h the"));
  REQUIRE(reversed.feedback.at(1) == "the sign is reversed");
  // Where a unit's reading has the answer's dimension it stands: box-corner's a is a length,
  // and "0.5 m" half a metre (not half of a mass).
  const Fixture box("box-corner");
  REQUIRE(box.check("center_of_mass", "(0.5 m, 1 m, 1.5 m)").correct);
  // Where neither reading has it, the wrong dimension is said, with the symbol's line: the
  // plate's I0 is kg m², 0.00072 m neither a length nor a mass (the number is right in kg m²).
  const Fixture plate("flying-plate");
  const auto neither = plate.check("I0", "0.00072 m");
  REQUIRE_FALSE(neither.correct);
  REQUIRE(neither.feedback ==
          std::vector<std::string>{"you gave m (length); the answer is in kg m² (mass × length²)",
                                   "m is also the problem's symbol for the mass: after a number "
                                   "it reads as the unit; for the product, write the '*' "
                                   "(number*m)",
                                   "in kg m² the number would be right"});
  // A unit that is no symbol of the problem gets the dimension alone, and here that the number
  // is right in the key's unit.
  REQUIRE(cone.check("center_of_mass", "-0.225 s k̂").feedback ==
          std::vector<std::string>{"you gave s (time); the answer is in m (length)",
                                   "in m the numbers would be right"});
}

TEST_CASE("a name the statement defines is named with its definition, to be written in") {
  // The Earth's statement: "equatorial moment $A = C(1 - H)$"; A is no symbol of the problem.
  const Fixture earth("earth-free-precession");
  REQUIRE_THROWS_WITH(earth.check("Omega_body_rate", "(C − A)/A ω"),
                      Catch::Contains("A is no symbol here; the problem defines A = C(1 - H): "
                                      "write it in the problem's symbols"));
  // Written in, it reads and is judged.
  REQUIRE(earth.check("Omega_body_rate", "(C − C(1 − H))/(C(1 − H)) ω cos α").correct);
  // A name no math of the statement defines gets no such line.
  REQUIRE_THROWS_WITH(earth.check("Omega_body_rate", "B ω"), !Catch::Contains("defines"));
  // Nor a case the text names: "at $t = 0$" defines no t.
  const Fixture plate("flying-plate");
  REQUIRE_THROWS_WITH(plate.check("I0", "m R² t/4"),
                      Catch::Contains("undefined symbol 't'") && !Catch::Contains("defines"));
}

TEST_CASE("a rate in Lagrange's notation, a prime after the angle, is the problem's rate") {
  const Fixture euler("euler-angles");
  for (const char* rates :
       {"(I1/2)(θ'² + φ'² sin²θ) + (I3/2)(ψ' + φ' cos θ)²",
        "(I1/2)(θ′² + φ′² sin²θ) + (I3/2)(ψ′ + φ′ cos θ)²",
        "I1/2*(theta'^2 + phi'^2*sin(theta)^2) + I3/2*(psi' + phi'*cos(theta))^2"}) {
    INFO(rates);
    REQUIRE(euler.check("kinetic_energy", rates).correct);
  }
  REQUIRE_FALSE(
      euler.check("kinetic_energy", "(I1/2)(θ'² + φ'² sin²θ) + (I3/2)(ψ' + θ' cos θ)²").correct);
  // A prime that names no rate keeps its meaning: the heavy top's E′, minutes of arc, a
  // transpose; a rate the problem has at t = 0 only is refused naming that one, as "psidot" is.
  const Fixture top("heavy-top");
  REQUIRE(top.check("energy_prime", "E′ = M g l cos θ₀").correct);
  const double theta_max = top.answer("theta_max").value.data.at(0) * 180 / kPi;
  const double minutes = (theta_max - std::floor(theta_max)) * 60;
  REQUIRE(
      top.check("theta_max", fmt::format("{}°{:.3f}′", std::floor(theta_max), minutes)).correct);
  REQUIRE(
      top.check("theta_max", fmt::format("{}°{}′{:.1f}″", std::floor(theta_max),
                                         std::floor(minutes), (minutes - std::floor(minutes)) * 60))
          .correct);
  REQUIRE_THROWS_WITH(top.check("p_phi", "M R² ψ' cos θ₀ / 2"),
                      Catch::Contains("the problem's is ψ̇₀ (psidot0)"));
  REQUIRE(euler.check("omega_primed", "[-φ' sin θ, θ', φ' cos θ + ψ']'").correct);
}

TEST_CASE("a parameter's name but for its 0 is named with the parameter, not read as it") {
  // The heavy top gives the rates at t = 0 only: ψ̇ is ψ̇₀ there and nowhere else, so the name
  // is refused, and the line names the symbol with its description.
  const Fixture top("heavy-top");
  REQUIRE_THROWS_WITH(top.check("p_phi", "M R² ψ̇ cos θ₀ / 2"),
                      Catch::Contains("psidot is no symbol here; the problem's is ψ̇₀ (psidot0), "
                                      "the initial spin rate about the axle"));
  // θ without its 0 is θ₀, not the answers θ_min and θ_max it begins.
  REQUIRE_THROWS_WITH(top.check("p_phi", "M R^2 psidot0 cos(theta)/2"),
                      Catch::Contains("the problem's is θ₀ (theta0)") &&
                          !Catch::Contains("theta_min"));
  // The other way: the Euler angles' θ itself, typed with a 0; a description's math as text.
  const Fixture euler("euler-angles");
  REQUIRE_THROWS_WITH(euler.check("omega_space", "[theta_0, 0, 0]"),
                      Catch::Contains("theta_0 is no symbol here; the problem's is θ (theta), "
                                      "the second angle, about e₂'"));
  // A name that is no parameter with or without a 0 gets no such line.
  REQUIRE_THROWS_WITH(top.check("p_phi", "M R^2 chi cos(theta0)/2"),
                      !Catch::Contains("the problem's is"));
}

TEST_CASE(
    "an earlier answer's named entries read as its forms: the Ω's of each axis, Euler's c's") {
  const Fixture top("asymmetric-top");
  // The rate about e₁ in the lecture's Ω₂, Ω₃ of the spin about e₁ (Omega_axis1, just before).
  const std::string axis1 =
      "read with Ω₂ = (I1 - I3)·√(w1² + w2² + w3²)/I2, Ω₃ = (I1 - I2)·√(w1² + w2² + w3²)/I3, "
      "entries of the key's answer Omega_axis1 (part b)";
  for (const char* same : {"√(Ω₂ Ω₃)", "sqrt(Omega2*Omega3)", "sqrt(Omega_2 Omega_3)",
                           "\\sqrt{\\Omega_2 \\Omega_3}"}) {
    INFO(same);
    const auto v = top.check("rate_axis1", same);
    REQUIRE(v.correct);
    REQUIRE(v.feedback == std::vector<std::string>{axis1 + ": right as far as your Ω₂, Ω₃ are"});
  }
  // Each axis's own: Ω₂ about e₃ is the negative of Ω₂ about e₁, and the rate about e₃ reads
  // the pair just before it.
  const auto axis3 = top.check("rate_axis3", "√(Ω₁Ω₂)");
  REQUIRE(axis3.correct);
  REQUIRE_THAT(axis3.feedback.at(0), Catch::EndsWith("entries of the key's answer Omega_axis3 "
                                                     "(part b): right as far as your Ω₁, Ω₂ are"));
  REQUIRE(top.check("rate_axis2", "√(−Ω₃Ω₁)").correct);
  // About the unstable axis Ω₃ Ω₁ < 0: its root is refused as not real, with the growth hint, as
  // the same root written in the symbols is.
  for (const char* imaginary :
       {"√(Ω₃Ω₁)", "sqrt((I1-I2)*(I3-I2)/(I1*I3)) * sqrt(w1^2+w2^2+w3^2)"}) {
    INFO(imaginary);
    REQUIRE_THROWS_WITH(top.check("rate_axis2", imaginary),
                        Catch::Contains("not real (answers here are real; an imaginary frequency "
                                        "iλ is a growth e^(λt), and its rate is λ)"));
  }
  // Wrong, read so: the line without its "right as far as".
  const auto half = top.check("rate_axis1", "√(Ω₂ Ω₃)/2");
  REQUIRE_FALSE(half.correct);
  REQUIRE(half.feedback.back() == axis1);
  // Euler's equations' coefficients in dω/dt at t = 0, run together as the equations write them.
  const auto rates = top.check("dw_dt0", "(c₁ω₂ω₃, c₂ω₃ω₁, c₃ω₁ω₂)");
  REQUIRE(rates.correct);
  REQUIRE(rates.feedback ==
          std::vector<std::string>{
              "read with c₁ = (I2 - I3)/I1, c₂ = (I3 - I1)/I2, c₃ = (I1 - I2)/I3, entries of the "
              "key's answer euler_coefficients (part a): right as far as your c₁, c₂, c₃ are"});
  // An answer's own entries are no working, and a later answer's none to read.
  REQUIRE_THROWS_AS(top.check("Omega_axis1", "(Ω₂, Ω₃)"), InputError);
  REQUIRE_THROWS_AS(top.check("euler_coefficients", "(Ω₂/w1, 1, 1)"), InputError);
  // Forms longer than a line are named, not written out (the tennis racket's).
  const Fixture racket("tennis-racket");
  const auto flip = racket.check("rate_axis2", "√(−Ω₃ Ω₁)");
  REQUIRE(flip.correct);
  REQUIRE(flip.feedback == std::vector<std::string>{"read with Ω₃, Ω₁, entries of the key's "
                                                    "answer Omega_axis2 (part b): right as far as "
                                                    "your Ω₃, Ω₁ are"});
}

TEST_CASE("a 2-vector for a 3-vector whose z is zero in the key's form is (x, y, 0), said") {
  // The planar molecule's centre of mass lies in its plane z = 0.
  const Fixture molecule("three-atom-molecule");
  const std::string note = "read with z = 0: the key's z is zero";
  for (const char* same : {"(0.0131, 0.1529) m", "[0.0131, 0.1529]",
                           "((m1 d1 + m2 d2 cos α)/(M+m1+m2), m2 d2 sin α/(M+m1+m2))"}) {
    INFO(same);
    const auto v = molecule.check("center_of_mass", same);
    REQUIRE(v.correct);
    REQUIRE(v.feedback.back() == note);
  }
  const auto off = molecule.check("center_of_mass", "(0.0131, 0.15) m");
  REQUIRE_FALSE(off.correct);
  REQUIRE(off.feedback == std::vector<std::string>{"entry y is off by 1.87%", note});
  // Not where another entry is the zero one: "(0, -0.225)" for the cone's centre on its axis
  // reads two ways, and the shape is refused as before.
  const Fixture cone("solid-cone");
  REQUIRE_THROWS_WITH(cone.check("center_of_mass", "(0, -0.225) m"),
                      Catch::Contains("wants a 3-vector [..], not a 2-vector"));
}

TEST_CASE("a name the steps write for an earlier answer reads as it: θ_L for the angle of L") {
  // The steps write tan θ_L = (I1/I3) tan α; the space cone's half angle is θ_L − α for a prolate
  // body (rect-solid), α − θ_L for an oblate one (the plate).
  const Fixture solid("rect-solid");
  const std::string note =
      "read with θ_L as angle_L_e3 = atan2(2·sin(α),cos(α)), the key's "
      "answer to part (c)";
  for (const char* same :
       {"θ_L − α", "theta_L - alpha", "\\theta_L - \\alpha", "\\theta_{L} - \\alpha"}) {
    INFO(same);
    const auto v = solid.check("space_cone_half_angle", same);
    REQUIRE(v.correct);
    REQUIRE(v.feedback == std::vector<std::string>{note + ": right as far as your θ_L is"});
  }
  const auto reversed = solid.check("space_cone_half_angle", "α − θ_L");
  REQUIRE_FALSE(reversed.correct);
  REQUIRE(reversed.feedback.back() == note);
  const Fixture plate("flying-plate");
  REQUIRE(plate.check("space_cone_half_angle", "α − θ_L").correct);
  // As a label it names that answer, and the answer itself is no working.
  REQUIRE(solid.check("angle_L_e3", "θ_L = 28.19°").correct);
  REQUIRE(solid.check("space_cone_half_angle", "θ_L = 28.19°").feedback ==
          std::vector<std::string>{"this is angle_L_e3 (part c), not space_cone_half_angle"});
  REQUIRE_THROWS_AS(solid.check("angle_L_e3", "θ_L"), InputError);
  // Before an '=' and the value, the formula is a side, judged, though after a number the name
  // was first taken for a unit: right, both sides are; wrong, that side is said.
  const std::string max_angle =
      fmt::format("{:.4g}°", plate.answer("max_angle").value.data[0] * 180 / M_PI);
  const auto twice = plate.check("max_angle", "2θ_L = " + max_angle);
  REQUIRE(twice.correct);
  REQUIRE_THAT(twice.feedback.back(), Catch::StartsWith("read with θ_L as angle_L_e3"));
  const auto thrice = plate.check("max_angle", "3θ_L = " + max_angle);
  REQUIRE_FALSE(thrice.correct);
  REQUIRE(thrice.feedback.front() == "the side \"3θ_L\" of your '='");
}

TEST_CASE("the heavy top's E, as its steps write the energy, reads as it; E′ labels a line") {
  // The steps: "E = T + M g l cos θ"; part (b) asks for the level E′ = E − ½ I₃ ω₃².
  const Fixture top("heavy-top");
  const std::string e_note =
      "read with E as energy = M·R²·ψ̇0²/4 + M·l·g·cos(θ0), the key's "
      "answer to part (a): right as far as your E is";
  for (const char* same : {"E − ½ I₃ ω₃²", "E - p_psi^2/(2 I3)", "E′ = E − ½I₃ω₃² = 0.3398 J"}) {
    INFO(same);
    const auto v = top.check("energy_prime", same);
    REQUIRE(v.correct);
    REQUIRE(v.feedback.back() == e_note);
  }
  // A label with a prime, typed or Unicode, before a key's line: the line is judged.
  for (const char* line : {"E′ = M g l cos θ₀ = 0.3398 J", "V′ = M g l cos θ₀ = 0.3398 J",
                           "E' = M g l cos θ₀ = 0.34 J"}) {
    INFO(line);
    REQUIRE(top.check("energy_prime", line).correct);
  }
  REQUIRE_FALSE(top.check("energy_prime", "E′ = M g l = 0.3924 J").correct);
  // E for the energy itself is no working.
  REQUIRE_THROWS_AS(top.check("energy", "E"), InputError);
}

TEST_CASE("the asymmetric top reads λ, T, L and I₁, I₂, I₃ as its steps write them") {
  // The steps write the period 4 K(k)/λ, k² in T, L² and the moments: so may a student.
  const Fixture racket("tennis-racket");
  const auto flip = racket.check("flip_interval", "2K(k)/λ");
  REQUIRE(flip.correct);
  // λ's form is some 150 characters here: named, not written out.
  REQUIRE(flip.feedback.front() ==
          "read with λ (the rate of sn's argument, sn(λt, k)), as the key's steps write it: right "
          "as far as your λ is");
  // Read so, the period for half of it is the period, and said so.
  const auto whole = racket.check("flip_interval", "4 K(k)/λ");
  REQUIRE_FALSE(whole.correct);
  REQUIRE(whole.feedback.front() == "this is period (part c), not flip_interval");
  for (const char* k2 : {"(I₂ − I₁)(2T I₃ − L²)/((I₃ − I₂)(L² − 2T I₁))",
                         "(I2 - I1)*(2*T*I3 - L^2)/((I3 - I2)*(L^2 - 2*T*I1))"}) {
    INFO(k2);
    const auto v = racket.check("k2", k2);
    REQUIRE(v.correct);
    REQUIRE_THAT(v.feedback, Catch::VectorContains(std::string(
                                 "read with T as energy, the key's answer to part (c): right as "
                                 "far as your T is")));
    REQUIRE_THAT(v.feedback.back(),
                 Catch::StartsWith("read with I1 = m·(b² + c²)/12 (the principal moment about "
                                   "e₁), I2 = m·(a² + c²)/12"));
  }
  // A wrong one is judged wrong: k² upside down.
  REQUIRE_FALSE(racket.check("k2", "(I3 - I2)*(L^2 - 2*T*I1)/((I2 - I1)*(2*T*I3 - L^2))").correct);
  // T for the period, as some books write it: here T is the energy, and the line says so.
  const auto energy_for_time = racket.check("flip_interval", "T/2");
  REQUIRE(energy_for_time.wrong_dimension);
  REQUIRE(energy_for_time.feedback.back() == "read with T as energy, the key's answer to part (c)");
  // The energy is no working for itself.
  REQUIRE_THROWS_AS(racket.check("energy", "T"), InputError);
  // Where the moments are the problem's own symbols (the asymmetric top's I1, I2, I3), they stay
  // them, and λ is the same rate in them.
  const Fixture asymmetric("asymmetric-top");
  const auto period = asymmetric.check("period", "4K(k)/λ");
  REQUIRE(period.correct);
  REQUIRE_THAT(period.feedback.front(),
               Catch::StartsWith("read with λ = √(") && !Catch::Contains("principal moment"));
}

TEST_CASE("the heavy top reads I₁, I₃ and ω₃ as its steps write them, and says so") {
  // The steps write p_ψ = I₃ ω₃, ω₃ ≥ 2 √(M g l I₁)/I₃: a student writes the answers so too. The
  // names read as the key's exact forms, and the line says which, as for an earlier answer.
  const Fixture top("heavy-top");
  const std::string i1 = "I1 = M·(4·l² + R²)/4 (the moment about a transverse axis through the "
                         "pivot)",
                    i3 = "I3 = M·R²/2 (the moment about the axle)",
                    w3 = "ω3 = ψ̇0 (the spin about the axle)";
  const std::string one = "read with " + i3 +
                          ", as the key's steps write it: right as far as "
                          "your I3 is";
  const std::string spin = "read with " + i3 + ", " + w3 +
                           ", as the key's steps write them: right as far as your I3, ω3 are";
  for (const auto& [name, typed, note] : std::vector<std::array<std::string, 3>>{
           {"p_psi", "I₃ ψ̇₀", one},
           {"p_psi", "I_3 psidot0", one},
           {"p_psi", "I3 (ψ̇0)", one},
           // After a value, the reader takes a word for its unit: the name is read all the same.
           {"p_psi", "ψ̇₀ I₃", one},
           {"p_psi", "(ψ̇0) I_3", one},
           {"p_psi", "I₃ω₃", spin},
           {"p_psi", "I_3 w_3", spin},
           {"p_phi", "I3 ω3 cos θ0", spin},
           {"energy", "½ I₃ ψ̇₀² + M g l cos θ₀", one},
           {"omega3_min", "2√(MglI₁)/I₃",
            "read with " + i1 + ", " + i3 +
                ", as the key's steps write them: right as far as your I1, I3 are"},
           // In LaTeX, as the key's LaTeX steps write them.
           {"p_psi", "I_3\\omega_3", spin},
           {"p_phi", "I_{3} \\dot\\psi_0 \\cos\\theta_0", one},
           {"omega3_min", "\\frac{2\\sqrt{M g l I_1}}{I_3}",
            "read with " + i1 + ", " + i3 +
                ", as the key's steps write them: right as far as your I1, I3 are"}}) {
    INFO(name << ": " << typed);
    const auto v = top.check(name, typed);
    REQUIRE(v.correct);
    REQUIRE(v.feedback == std::vector<std::string>{note});
  }
  // Read so, a wrong answer is wrong: the transverse moment for the axial one, and the fast
  // top's approximation, which is said as such. The line says how the names were read, and not
  // that the answer is "right as far as" they are.
  const auto transverse = top.check("p_phi", "I1 ψ̇0 cos θ0");
  REQUIRE_FALSE(transverse.correct);
  REQUIRE(transverse.feedback.back() == "read with " + i1 + ", as the key's steps write it");
  const auto fast_top = top.check("phidot_slow", "M g l/(I3 ω3)");
  REQUIRE_FALSE(fast_top.correct);
  REQUIRE_THAT(fast_top.feedback.front(), Catch::StartsWith("this is the fast-top approximation"));
  REQUIRE(fast_top.feedback.back() ==
          "read with " + i3 + ", " + w3 + ", as the key's steps write them");
  // With an earlier answer's name too, each is said.
  const auto both = top.check("omega3", "p_ψ/I₃");
  REQUIRE(both.correct);
  REQUIRE(both.feedback.size() == 2);
  // In LaTeX alike: the answer's name and the steps' read together.
  const auto both_latex = top.check("omega3", "\\frac{p_\\psi}{I_3}");
  REQUIRE(both_latex.correct);
  REQUIRE(both_latex.feedback == both.feedback);
  // Not the answer's own name: ω₃ for ω₃ is no working.
  REQUIRE_THROWS_WITH(top.check("omega3", "ω₃"),
                      Catch::Contains("omega3 is the answer to part (c)"));
  REQUIRE_THROWS_WITH(top.check("omega3", "\\omega_3"),
                      Catch::Contains("omega3 is the answer to part (c)"));
  // A name that reads is not what the line blames where another does not: the line says what
  // may be written besides the problem's symbols, not "p_psi .. write it in the problem's
  // symbols"; in LaTeX, the name still refused, the problem's symbols listed.
  for (const std::string typed : {"Q + p_psi^2/(2 I3)", "p_ψ²/(2I₃) + Q"}) {
    INFO(typed);
    REQUIRE_THROWS_WITH(
        top.check("energy", typed),
        Catch::Contains("undefined symbol 'Q'") &&
            Catch::Contains("(the key's steps' I1, I3, omega3 (ω3) and its answers' "
                            "names up to part (a) read too)") &&
            !Catch::Contains("write it in"));
  }
  REQUIRE_THROWS_WITH(top.check("omega3", "\\frac{p_\\psi}{Q}"),
                      Catch::EndsWith("Q is not one of this problem's symbols (M, R, l, g, "
                                      "\\theta_0, \\dot\\theta_0, \\dot\\phi_0, "
                                      "\\dot\\psi_0) (the key's steps' I1, I3 and its answers' "
                                      "names up to part (c) read too)"));
  // Both an answer's name and a step's read, the text around them does not: said of the text as
  // typed, with how each name was read, not as the first name's refusal.
  // A name beside a number ("2 I3", "2I3") is its factor, its form put in too: the same words.
  for (const char* typed :
       {"p_psi^2/(2*I3) + (1,2)", "p_psi^2/(2 I3) + (1,2)", "p_psi^2/(2I3) + (1,2)"}) {
    INFO(typed);
    REQUIRE_THROWS_WITH(top.check("energy_prime", typed),
                        Catch::EndsWith("\", read with p_psi = M·R²·ψ̇0/2, the key's answer to "
                                        "part (a), read with " +
                                        i3 +
                                        ", as the key's steps write it: a ',' where one "
                                        "expression was expected (a vector is written [x, y, z])"));
  }
  REQUIRE_THROWS_WITH(top.check("energy_prime", "p_psi^2/(2*I3) + (1,2)"),
                      Catch::StartsWith("--answer: cannot read expression \"p_psi^2/(2*I3) + "
                                        "(1,2)\", read with"));
  // Where another name still keeps the answer from reading, that one is said.
  REQUIRE_THROWS_WITH(top.check("omega3_min", "2√(M g l I₁)/q"),
                      Catch::Contains("undefined symbol 'q'"));
  REQUIRE_THROWS_WITH(top.check("omega3_min", "\\frac{2\\sqrt{M g l I_1}}{q}"),
                      Catch::Contains("q is not one of this problem's symbols"));
  // A unit the names do not make read stays the unit's refusal, as typed, not the forms put in.
  REQUIRE_THROWS_WITH(top.check("p_psi", "ψ̇0 q"), Catch::Contains("cannot read the unit 'q'"));
  REQUIRE_THROWS_WITH(
      top.check("p_psi", "150 rad/s I3"),
      Catch::Contains("cannot read the unit 'rad/s I3'") && !Catch::Contains("M*R^2/2"));
  // The names read, a vector for a number is what is said, not that I₃ is no symbol.
  REQUIRE_THROWS_WITH(top.check("p_psi", "(I3, ω3)"),
                      Catch::Contains("not a 2-vector") && !Catch::Contains("no symbol here"));
  // A body whose key names no moments keeps the textbook name's line (the flying plate's I₀ is
  // an answer of its own).
  const Fixture plate("flying-plate");
  REQUIRE_THROWS_WITH(plate.check("Omega_body_rate", "(I3 - I1)/I1 ω cos α"),
                      Catch::Contains("I3, a principal moment of the body, is no symbol here"));
}

TEST_CASE("the Euler-angle top reads ω₁′, ω₂′, ω₃′, ω₃ and I₂ as its steps write them") {
  // The steps: L = (I₁ ω₁', I₁ ω₂', I₃ ω₃'), with I₁ = I₂, the components along the line-of-nodes
  // basis (e₃′ = e₃). A prime typed after a name is no part of it to the reader: these are found
  // before it reads, however the prime and the index are typed.
  const Fixture taylor("euler-angles"), phy("euler-angles-phy711");
  const std::string primes =
      "read with ω1′ = -α̇·sin(β) (ω's component along e₁′), ω2′ = β̇ (ω's component along "
      "e₂′), ω3′ = α̇·cos(β) + γ̇ (ω's component along e₃′ = e₃), as the key's steps write them: "
      "right as far as your ω1′, ω2′, ω3′ are";
  for (const char* typed :
       {"(I1 ω₁', I1 ω₂', I3 ω₃')", "(I₁ω₁′, I₁ω₂′, I₃ω₃′)", "(I1*w1', I1*w2', I3*w3')",
        "(I1 ω'₁, I1 ω'₂, I3 ω'₃)", "[I1 omega_1', I1 omega_2', I3 omega_3']"}) {
    INFO(typed);
    const auto v = phy.check("L_primed", typed);
    REQUIRE(v.correct);
    REQUIRE(v.feedback == std::vector<std::string>{primes});
  }
  // I₂ for I₁ and ω₃ for ω₃′, said on a line of their own.
  const auto moments = phy.check("L_primed", "(I₁ω₁′, I₂ω₂′, I₃ω₃)");
  REQUIRE(moments.correct);
  REQUIRE(moments.feedback.size() == 2);
  REQUIRE_THAT(moments.feedback[0],
               Catch::StartsWith("read with I2 = I1 (the moment about e₂, equal to I₁), ω3 = "
                                 "α̇·cos(β) + γ̇ (ω's component along e₃)"));
  REQUIRE_THAT(moments.feedback[1], Catch::StartsWith("read with ω1′ = -α̇·sin(β)") &&
                                        Catch::EndsWith("right as far as your ω1′, ω2′ are"));
  // In Taylor's angles, the energy as ½ ω · L in the primed basis.
  REQUIRE(taylor.check("kinetic_energy", "½(I₁ω₁′² + I₂ω₂′² + I₃ω₃′²)").correct);
  // Read so, a wrong one is wrong, and the line says how the names were read.
  const auto wrong = phy.check("L_primed", "(I1 ω₁', I1 ω₂', I1 ω₃')");
  REQUIRE_FALSE(wrong.correct);
  REQUIRE(wrong.feedback.back() == primes.substr(0, primes.find(": right")));
  // The answer's own entries are no working for it; the line names what the steps write.
  REQUIRE_THROWS_WITH(phy.check("omega_primed", "(ω₁′, ω₂′, ω₃′)"),
                      Catch::Contains("the key's steps write ω1′ for ω's component along e₁′"));
  REQUIRE_THROWS_WITH(phy.check("omega_primed", "(-α̇ sin β, β̇, ω₃)"),
                      Catch::Contains("undefined symbol 'omega3'"));
  // An unprimed ω₁ is no name of the steps': the line names the primed one.
  REQUIRE_THROWS_WITH(taylor.check("L_primed", "(I1 ω₁, I1 ω₂, I3 ω₃)"),
                      Catch::Contains("the key's steps write ω1′ for ω's component along e₁′"));
  // Two primes are no name of the steps'; where the rest then does not read, the line quotes the
  // text as typed, not the forms put in.
  REQUIRE_THROWS_WITH(
      phy.check("L_primed", "[I1 omega_1', I1 w'2, I3*w3'']"),
      Catch::Contains("cannot read expression \"I3*w3''\"") && !Catch::Contains("gammadot"));
  // A problem whose steps write no primed names keeps its refusal of a prime after a name.
  const Fixture top("heavy-top");
  REQUIRE_THROWS_AS(top.check("p_psi", "I3 ω₃′"), InputError);
}

TEST_CASE("a textbook formula's principal moment or ω component is named as such") {
  // (I3 - I1)/I1 ω3 is the general rate, before this body's moments are put in.
  const Fixture plate("flying-plate");
  REQUIRE_THROWS_WITH(plate.check("Omega_body_rate", "(I₃ - I₁)/I₁ ω cos α"),
                      Catch::Contains("I3, a principal moment of the body, is no symbol here"));
  REQUIRE_THROWS_WITH(plate.check("Omega_body_rate", "ω_3 (m R^2/2 - m R^2/4)/(m R^2/4)"),
                      Catch::Contains("omega_3, a component of ω along the body's axes"));
  REQUIRE_THROWS_WITH(plate.check("Omega_body_rate", "(I_3 - I_1)/I_1 ω cos α"),
                      Catch::Contains("I_3, a principal moment of the body"));
  const Fixture top("heavy-top");
  // Where such a name is the problem's own symbol, it reads (the asymmetric top's w1).
  const Fixture asym("asymmetric-top");
  REQUIRE(asym.check("energy", "(I₁ω₁² + I₂ω₂² + I₃ω₃²)/2").correct);
  REQUIRE_THROWS_WITH(top.check("p_psi", "I4 psidot0"), !Catch::Contains("principal moment"));
  REQUIRE_THROWS_WITH(plate.check("I0", "M R^2/4"), !Catch::Contains("principal moment"));
  // The undefined name is what is wrong, not the stars a bracket against a symbol needs, nor a
  // unit "+ omega1"; where the text runs I₃ and ω₁ together, the reader's name gets the hint
  // (here the steps write ω₁′, and ω₃, which reads).
  const Fixture euler("euler-angles");
  for (const char* text : {"½I₁(θ̇² + φ̇² sin²θ) + ½I₃ω₁²", "I1*(thetadot^2) + omega1"}) {
    INFO(text);
    REQUIRE_THROWS_WITH(
        euler.check("kinetic_energy", text),
        Catch::Contains("undefined symbol 'omega1'") &&
            Catch::Contains("omega1 is no symbol here; the key's steps write ω1′") &&
            !Catch::Contains("not a function") && !Catch::Contains("unit"));
  }
  REQUIRE(euler.check("kinetic_energy", "½I₁(θ̇² + φ̇² sin²θ) + ½I₃ω₃²").correct);
  REQUIRE(euler.check("kinetic_energy", "½I₁(θ̇² + φ̇² sin²θ) + ½I₃(ψ̇ + φ̇ cos θ)²").correct);
  REQUIRE_THROWS_WITH(plate.check("I0", "0.16 parsecs"),
                      Catch::Contains("cannot read the unit 'parsecs'"));
}

TEST_CASE("a unit after an expression in the symbols is a number's in it where only so it fits") {
  // "M R²/2 × 150 rad/s": the symbols are in SI (kg m²), the unit the 150's; the whole in rad/s
  // would be no momentum. Judged so, the number is named as the parameter's value the key
  // writes as its symbol, and the line says how the unit was read.
  const Fixture top("heavy-top");
  const std::string read_as =
      "read with rad/s as the unit of a number in it, not of the whole "
      "(with the problem's symbols in SI, the whole is then in kg m^2/s)";
  const auto spin = top.check("p_psi", "M R^2/2 × 150 rad/s");
  REQUIRE_FALSE(spin.correct);
  REQUIRE_FALSE(spin.wrong_dimension);
  REQUIRE(spin.feedback == std::vector<std::string>{
                               "it gives the key's value at the set values but not at others: 150 "
                               "is the value of ψ̇₀ (psidot0): write the symbol",
                               read_as});
  // Wrong at the set values too: why, as for a number, not that the symbols alone are no
  // momentum.
  const auto twice = top.check("p_psi", "M R² × 150 rad/s");
  REQUIRE_FALSE(twice.correct);
  REQUIRE_THAT(twice.feedback.front(), Catch::StartsWith("this is 2 times the answer"));
  REQUIRE(twice.feedback.back() == read_as);
  // A vector alike: each entry's dimension is the answer's with the unit on its numbers, and
  // none is said to be another.
  const Fixture plate("flying-plate");
  const auto spin_vector =
      plate.check("L0_body", "(m R^2/4 × sin α, 0, m R^2/2 × cos α) × 10 rad/s");
  REQUIRE_FALSE(spin_vector.correct);
  REQUIRE(spin_vector.feedback ==
          std::vector<std::string>{"it gives the key's value at the set values but not at "
                                   "others: 10 is the value of ω (omega): write the symbol",
                                   read_as});
  // Where the unit does not make the answer's dimension with the symbols, it is the whole's.
  const auto mass = top.check("p_psi", "M × 150 rad/s");
  REQUIRE(mass.wrong_dimension);
  REQUIRE_THAT(mass.feedback.front(), Catch::StartsWith("you gave rad/s (1 / time)"));
  // An expression in SI with its unit written after it stays right.
  REQUIRE(top.check("p_psi", "M R^2 psidot0/2 kg m^2/s").correct);
  // A unit inside, with more after it, is refused, with what to write; in LaTeX named as typed
  // (\mathrm{rad/s}, not the letters "rads").
  const std::string inside =
      " is a unit: an expression in the problem's symbols is in SI, its "
      "numbers without units; write the symbol whose value a number is, or "
      "one unit after the whole)";
  REQUIRE_THROWS_WITH(
      top.check("p_phi", "M R²/2 × 150 rad/s × cos θ₀"),
      Catch::Contains("undefined symbol 'rad'") && Catch::EndsWith("(rad" + inside));
  REQUIRE_THROWS_WITH(
      top.check("p_phi", "\\frac{M R^2}{2} \\cdot 150\\,\\mathrm{rad/s} \\cdot \\cos\\theta_0"),
      Catch::StartsWith("--answer: rad/s is not one of this problem's symbols") &&
          Catch::EndsWith("(rad/s" + inside));
}

TEST_CASE("a number worked out with its units reads as the number it works out to") {
  // Euler's rate from its period, as a student works it on paper: each unit its SI factor.
  const Fixture earth("earth-free-precession");  // 2.395e-07 rad/s
  for (const auto& [typed, line] : std::vector<std::pair<std::string, std::string>>{
           {"2π/(303.6 d)", "2π/(303.6 day) = 2.395e-07 rad/s"},
           {"2π rad / 303.6 days", "2π rad / (303.6 days) = 2.395e-07 rad/s"},
           {"1 rev / 304.46 sidereal days", "1 rev / (304.46 sidereal days) = 2.395e-07 rad/s"},
           {"2π rad/(303.6 × 86400 s)", "2π rad/(303.6 · 86400 s) = 2.395e-07 rad/s"},
           {"Ω_body = 2π/(303.6 days)", "2π/(303.6 days) = 2.395e-07 rad/s"},
           // In LaTeX, units upright; an upright d the day where d is no symbol. The line writes
           // what was read as it would be written, not as \frac is set in text ("((2*π)/(..))").
           {"\\frac{2\\pi\\,\\mathrm{rad}}{303.6\\,\\mathrm{days}}",
            "(2π rad)/(303.6 days) = 2.395e-07 rad/s"},
           {"\\frac{2\\pi}{303.6\\,\\mathrm{d}}", "2π/(303.6 day) = 2.395e-07 rad/s"}}) {
    INFO(typed);
    const auto v = earth.check("Omega_body_rate", typed);
    REQUIRE(v.correct);
    REQUIRE(v.feedback.back() == "read with its units worked out: " + line);
  }
  // Juxtaposed after a '/', a product is all of the denominator; a bracket says otherwise, and
  // "(2π rad/303.6) days" is a duration.
  REQUIRE(earth.check("Omega_body_rate", "(2π rad/303.6) days").wrong_dimension);
  // A wrong sign is said as for a number.
  const auto sign = earth.check("Omega_body_rate", "-2π/(303.6 d)");
  REQUIRE_FALSE(sign.correct);
  REQUIRE_THAT(sign.feedback.front(), Catch::StartsWith("the size is right but not the sign"));
  // The period from the rate: 2π over a rate in rad/s is seconds.
  REQUIRE(earth.check("precession_period_body", "2π/(2.395e-7 rad/s)").correct);
  // A moment times a spin, in grams and centimetres: p_ψ = ½ M R² ψ̇₀ = 0.09375 kg m²/s.
  const Fixture top("heavy-top");
  for (const char* typed : {"0.5 kg × (0.05 m)² / 2 × 150 rad/s", "(0.5 kg)(5 cm)²/2 × 150/s",
                            "0.5 kg * (50 mm)^2 / 2 * 150 s^-1"}) {
    INFO(typed);
    REQUIRE(top.check("p_psi", typed).correct);
  }
  REQUIRE_FALSE(top.check("p_psi", "0.5 kg × (5 cm)² × 150/s").correct);  // twice it
  // In LaTeX, an upright unit with factors after it, which the LaTeX reader takes for the
  // value's own only at the end.
  for (const char* typed :
       {"0.5 \\cdot 0.5\\,\\mathrm{kg} \\cdot (0.05\\,\\mathrm{m})^2 \\cdot 150\\,\\mathrm{rad/s}",
        "\\tfrac12\\,0.5\\,\\mathrm{kg}\\,(0.05\\,\\mathrm{m})^2\\,150\\,\\mathrm{rad/s}",
        "\\frac{0.5\\,\\mathrm{kg}\\,(0.05\\,\\mathrm{m})^2}{2} \\times 150\\,\\mathrm{s^{-1}}"}) {
    INFO(typed);
    const auto v = top.check("p_psi", typed);
    REQUIRE(v.correct);
    REQUIRE_THAT(v.feedback.back(), Catch::EndsWith("= 0.09375 kg m²/s"));
  }
  // The line in the key's notation (·, ²), without the brackets \frac is set in as text.
  REQUIRE(
      top.check("p_psi",
                "\\tfrac12\\,0.5\\,\\mathrm{kg}\\,(0.05\\,\\mathrm{m})^2\\,150\\,\\mathrm{rad/s}")
          .feedback.back() ==
      "read with its units worked out: (1/2)·0.5·kg·(0.05 m)²·150 rad/s "
      "= 0.09375 kg m²/s");
  // A unit word alone is a unit too: 1/day is 48.3 times Euler's rate.
  const auto per_day = earth.check("Omega_body_rate", "\\frac{1}{\\mathrm{day}}");
  REQUIRE_FALSE(per_day.correct);
  REQUIRE(per_day.feedback.back() == "read with its units worked out: 1/day = 1.157e-05 rad/s");
  // Where another name keeps it from being worked out, that name is refused, not a unit read
  // for a symbol, with the names the key reads besides the problem's symbols; in LaTeX with the
  // symbols listed as LaTeX draws them, a quotient set upright ("\mathrm{rad/s}") with more after
  // it read as its units; in plain text in the reader's words, quoting the answer as typed.
  const std::string read_too =
      "(the key's steps' I1, I3, omega3 (ω3) and its answers' names up "
      "to part (a) read too)";
  for (const char* typed :
       {"0.5\\,\\mathrm{kg} \\cdot (0.05\\,\\mathrm{m})^2 \\cdot Q", "0.5\\,\\mathrm{kg} \\cdot Q",
        "0.5\\,\\mathrm{kg} \\cdot 150\\,\\mathrm{rad/s} \\cdot Q"}) {
    INFO(typed);
    REQUIRE_THROWS_WITH(top.check("p_psi", typed),
                        "--answer: Q is not one of this problem's symbols (M, R, l, g, \\theta_0, "
                        "\\dot\\theta_0, \\dot\\phi_0, \\dot\\psi_0) " +
                            read_too);
  }
  for (const char* typed : {"0.5 kg × Q", "0.5 kg (0.05 m)^2 150 rad/s Q"}) {
    INFO(typed);
    REQUIRE_THROWS_WITH(
        top.check("p_psi", typed),
        "--answer: cannot read expression \"" + std::string(typed) +
            "\": undefined symbol 'Q'; the symbols here are M, R, g, l, phidot0, pi "
            "(π), psidot0, theta0, thetadot0 " +
            read_too);
  }
  // Units run together ("kgm", as "kg m") are no name beside units: the unit reader's refusal
  // stands, with the units written apart to copy, whether the powers have their '^' or not.
  for (const char* typed : {"0.09375 kgm^2/s", "0.09375 kgm²/s", "0.09375 kgm2/s"}) {
    INFO(typed);
    REQUIRE_THROWS_WITH(top.check("p_psi", typed),
                        Catch::StartsWith("--answer: cannot read the unit 'kgm") &&
                            Catch::Contains("unknown unit 'kgm' ('kg m', with spaces?)"));
  }
  // Against the number too ("0.094kgm^2/s", "5Nms"), the units are written apart to copy; a
  // unit vector's letter against a number ("9.13i") is no unit, and gets no such line.
  for (const auto& [typed, apart] :
       std::vector<std::pair<std::string, std::string>>{{"0.094kgm^2/s", "'0.094 kg m^2/s'"},
                                                        {"0.094kgm2/s", "'0.094 kg m2/s'"},
                                                        {"5Nms", "'5 N m s'"}}) {
    INFO(typed);
    REQUIRE_THROWS_WITH(
        top.check("p_psi", typed),
        Catch::Contains("(a number and its units are written apart: " + apart + ")"));
  }
  // Among units worked out, as after a number: not "unknown function 'kgm'".
  REQUIRE_THROWS_WITH(
      top.check("p_psi", "0.5 kgm (0.05 m) 150 rad/s"),
      Catch::StartsWith("--answer: cannot read the unit 'kgm': unknown unit 'kgm' ('kg m', "
                        "with spaces?)"));
  REQUIRE_THROWS_WITH(Fixture("tennis-racket").check("rate_axis2", "9.13i"),
                      Catch::Contains("unit vector î") && !Catch::Contains("put a space"));
  REQUIRE_THROWS_WITH(top.check("p_psi", "0.16parsecs"), Catch::Contains("put a space"));
  // Where every name is a unit, what keeps it from reading is said of the units as typed, not
  // that a unit is no function: a number after a power needs its '*', as it does after R².
  REQUIRE_THROWS_WITH(top.check("p_psi", "0.5 kg (0.05 m)² 150 rad/s"),
                      "--answer: cannot read \"0.5 kg (0.05 m)² 150 rad/s\": products need '*' "
                      "(0.5*kg*(0.05*m)^2*150*rad/s, not 0.5 kg (0.05 m)^2 150 rad/s)");
  // The answer quoted as typed, whole, not the reader's reading of it cut short.
  REQUIRE_THROWS_WITH(top.check("p_psi", "0.5 kg (0.05 m)^2 (150 rad/s"),
                      "--answer: cannot read expression \"0.5 kg (0.05 m)^2 (150 rad/s\": a '(' "
                      "is not closed");
  // With the quotient set upright first, its units are read as such before the factors after.
  REQUIRE(top.check("p_psi",
                    "0.5 \\cdot 0.5\\,\\mathrm{kg} \\cdot 150\\,\\mathrm{rad/s} \\cdot "
                    "(0.05\\,\\mathrm{m})^2")
              .correct);
  // "1/2 kg" is half a kilogram where only that reading has the answer's dimension (1/(2 kg)
  // has not); a rate in rad/s is written in the key's unit.
  const auto half = top.check("p_psi", "1/2 × 1/2 kg × (5 cm)² × 150 rad/s");
  REQUIRE(half.correct);
  REQUIRE(half.feedback.back() ==
          "read with its units worked out: 1/2 · 1/2 kg · (5 cm)² · 150 "
          "rad/s = 0.09375 kg m²/s");
  // After a unit the juxtaposed denominator stays whole, whatever the dimension: a rate given
  // for Euler's period is a rate.
  REQUIRE(earth.check("precession_period_body", "2π rad / 303.6 days").wrong_dimension);
  // Unlike quantities added are refused, one line naming the text.
  REQUIRE_THROWS_WITH(earth.check("Omega_body_rate", "2π/(303.6 d) + 1 s"),
                      Catch::Contains("\"2π/(303.6 day) + 1 s\" does not work out to one unit"));
  REQUIRE_THROWS_WITH(earth.check("Omega_body_rate", "exp(1 m)/1 s"),
                      Catch::Contains("a function of one"));
  // A sum's terms each of one unit: which, and a pure number among them said for what it most
  // often is, a unit left off; the text quoted in the key's notation, as the line is.
  REQUIRE_THROWS_WITH(earth.check("Omega_body_rate", "2π/(303.6 d) + 1 s"),
                      Catch::EndsWith("it adds unlike quantities: rad/s and s"));
  REQUIRE_THROWS_WITH(
      top.check("energy", "0.5 kg × (0.05 m)² × (150 rad/s)²/4 + 0.5 × 9.81 × 0.08 × cos 30°"),
      "--answer: \"0.5 kg · (0.05 m)² · (150 rad/s)²/4 + 0.5 · 9.81 · 0.08 · ...\" does not work "
      "out to one unit: it adds unlike quantities: J and a pure number (a number without its "
      "unit?)");
  // One term far outweighing the other is still a sum of unlike quantities.
  REQUIRE_THROWS_WITH(earth.check("precession_period_body", "1e12 m + 1 s"),
                      Catch::Contains("does not work out to one unit"));
  // A symbol of the problem that names a unit (the heavy top's g, the flying plate's mass m) is
  // that unit after a number, beside a unit that is no symbol, only where the text reads no
  // other way or only that reading has the answer's dimension; the line says so.
  const auto grams = top.check("p_psi", "0.5 g × (5 cm)² / 2 × 150/s");
  REQUIRE_FALSE(grams.correct);
  CHECK_THAT(grams.feedback.front(), Catch::StartsWith("this is 1/1000 of the answer"));
  CHECK(grams.feedback.back() ==
        "read with its units worked out: 0.5 g · (5 cm)² / 2 · 150/s = 9.375e-05 kg m²/s (g "
        "after a number as the unit g, not the problem's symbol g)");
  const Fixture plate("flying-plate");
  const std::string metres = " (m after a number as the unit m, not the problem's symbol m)";
  for (const auto& [typed, line] : std::vector<std::pair<std::string, std::string>>{
           {"(0.2 kg)(0.12 m)²/4", "(0.2 kg)(0.12 m)²/4 = 0.00072 kg m²"},
           {"0.2kg*(0.12m)^2/4", "0.2 kg·(0.12 m)²/4 = 0.00072 kg m²"},
           {"1/4 * 0.2kg * 0.12m * 0.12m", "1/4 · 0.2 kg · 0.12 m · 0.12 m = 0.00072 kg m²"}}) {
    INFO(typed);
    const auto v = plate.check("I0", typed);
    REQUIRE(v.correct);
    CHECK(v.feedback ==
          std::vector<std::string>{"read with its units worked out: " + line + metres});
  }
  // Where that reading has another dimension and the symbols' none, it is judged so.
  const auto linear = plate.check("I0", "(0.2 kg)(0.12 m)/4");
  REQUIRE(linear.wrong_dimension);
  CHECK(linear.feedback.back() ==
        "read with its units worked out: (0.2 kg)(0.12 m)/4 = 0.006 kg m" + metres);
  // A symbol and no other unit is two masses or two metres: refused as before.
  REQUIRE_THROWS_WITH(plate.check("I0", "2m"), Catch::Contains("one of the problem's symbols"));
  REQUIRE_THROWS_AS(plate.check("t_max", "0.16m"), InputError);
  // A unit glued to its number reads as spaced apart: "0.5kg", "5cm".
  const auto glued = top.check("p_psi", "0.5kg*(5cm)^2/2*150/s");
  REQUIRE(glued.correct);
  CHECK(glued.feedback.back() ==
        "read with its units worked out: 0.5 kg·(5 cm)²/2·150/s = 0.09375 kg m²/s");
  // Degrees in a function's argument are radians, as elsewhere; an angle in radians there is a
  // pure number.
  const auto cosine = earth.check("Omega_body_rate", "2π/(303.6 d) × cos 1°");
  REQUIRE(cosine.correct);
  // The line writes the degrees as typed, not as the radians read: "cos(1°)".
  REQUIRE(cosine.feedback.back() ==
          "read with its units worked out: 2π/(303.6 day) · cos(1°) = 2.395e-07 rad/s");
  REQUIRE(earth.check("Omega_body_rate", "cos((1°)) × 2π/(303.6 d)").feedback.back() ==
          "read with its units worked out: cos(1°) · 2π/(303.6 day) = 2.395e-07 rad/s");
  REQUIRE(earth.check("Omega_body_rate", "1 rev / 304.46 sidereal days / cos(0.1 rad)").correct);
  // A vector entry by entry: each entry that does not read as typed is worked out, in the key's
  // unit; the others stay as typed.
  const Fixture euler("euler-angles");  // ω in the primed basis: (-1, 0.5, 11.73) rad/s
  const auto omega =
      euler.check("omega_primed", "(−2 rad/s × sin 30°, 0.5 rad/s, 2 rad/s × cos 30° + 10 rad/s)");
  REQUIRE(omega.correct);
  REQUIRE(omega.feedback.back() ==
          "read with its units worked out, entry 1: -2 rad/s · sin(30°) = -1 rad/s; entry 3: "
          "2 rad/s · cos(30°) + 10 rad/s = 11.73 rad/s");
  const auto zero = euler.check("omega_primed", "(−2 rad/s × sin 30°, 0, 2 rad/s × cos 30°)");
  REQUIRE_FALSE(zero.correct);
  REQUIRE_THROWS_WITH(euler.check("omega_primed", "(−2 rad/s × sin 30°, 0.5 rad/s, 1 kg)"),
                      Catch::Contains("different things") || Catch::Contains("one unit"));
  // A long text is quoted a line's worth.
  std::string seconds = "1 s";
  for (int i = 0; i < 300; ++i) seconds += " + 1 s";
  const auto many = earth.check("precession_period_body", seconds);
  REQUIRE_FALSE(many.correct);
  REQUIRE_THAT(many.feedback.back(), Catch::EndsWith("... = 301 s"));
  REQUIRE(many.feedback.back().size() < 120);
}

TEST_CASE("a duration told in parts, 303 days 15 h, reads as their sum") {
  const Fixture earth("earth-free-precession");  // Euler's period, 303.62 days
  const double days = earth.answer("precession_period_body").value.data[0] / 86400;
  const int whole = static_cast<int>(days);
  const double hours = (days - whole) * 24;
  for (const std::string& same :
       {fmt::format("{} days {:.0f} h", whole, hours),
        fmt::format("{} day {:.0f} hours {:.0f} min", whole, std::floor(hours),
                    (hours - std::floor(hours)) * 60)}) {
    INFO(same);
    REQUIRE(earth.check("precession_period_body", same).correct);
  }
  // The SI's d for the day, where the problem has no symbol d (the Earth's: C, H, ω, α).
  REQUIRE(
      earth.check("precession_period_body", fmt::format("{} d {:.0f} h", whole, hours)).correct);
  // A part off by a day is judged as such, not dropped.
  REQUIRE_FALSE(
      earth.check("precession_period_body", fmt::format("{} days {:.0f} h", whole + 30, hours))
          .correct);
  // Parts out of order, or of two dimensions, are no duration.
  REQUIRE_THROWS_AS(earth.check("precession_period_body", fmt::format("15 h {} days", whole)),
                    InputError);
  REQUIRE_THROWS_AS(earth.check("precession_period_body", fmt::format("{} days 15 kg", whole)),
                    InputError);
}

TEST_CASE("a day written d reads where d is no symbol of the problem, and only there") {
  const Fixture earth("earth-free-precession");  // Euler's period, 303.62 days; no symbol d
  const double days = earth.answer("precession_period_body").value.data[0] / 86400;
  // Four significant digits, within the judge's reading of a value so given.
  const std::string four = fmt::format("{:.4g}", days);
  for (const std::string& same :
       {four + " d", four + "d", fmt::format("{:.3e} d", days), "(" + four + ") d",
        four + "\\,\\mathrm{d}", four + "\\ \\text{d}", "\\SI{" + four + "}{d}"}) {
    INFO(same);
    REQUIRE(earth.check("precession_period_body", same).correct);
  }
  // Read as days, not dropped: a value off by a tenth is judged wrong, a time in seconds as
  // days is far off, and d is refused as a rate's unit (no number is right before it).
  REQUIRE_FALSE(earth.check("precession_period_body", fmt::format("{:.4g} d", days * 1.1)).correct);
  REQUIRE_FALSE(
      earth.check("precession_period_body", fmt::format("{:.4g} d", days * 86400)).correct);
  REQUIRE_THROWS_AS(earth.check("Omega_body_rate", "0.0207 rad/d"), InputError);
  // Where a problem's length is d (the symmetric molecule's bond), "0.068 d" is that length:
  // right at the set d = 1 m, not where d varies (a day would be a time, no length at all).
  const Fixture molecule("three-atom-molecule-symmetric");
  const double x_over_d = molecule.answer("center_of_mass").value.data[0];  // d = 1 m
  const auto bond = molecule.check("center_of_mass", fmt::format("({:.10g} d, 0, 0)", x_over_d));
  REQUIRE_FALSE(bond.correct);
  REQUIRE_THAT(bond.feedback.back(), Catch::Contains("the key's value at the set values"));
  REQUIRE_THROWS_WITH(parse_unit("d", "u"), Catch::Contains("'d' is not read as days"));
  // In turns of the spin, as the key's note counts it: sidereal days.
  const double sidereal = earth.answer("precession_period_body").value.data[0] / 86164.0905;
  REQUIRE(
      earth.check("precession_period_body", fmt::format("{:.5g} sidereal days", sidereal)).correct);
  REQUIRE_FALSE(
      earth.check("precession_period_body", fmt::format("{:.5g} sidereal days", sidereal * 0.99))
          .correct);
}

TEST_CASE("a remark in words in brackets after an answer is no part of it") {
  const Fixture plate("flying-plate");
  const std::string i0 = fmt::format("{:.6g}", plate.answer("I0").value.data[0]);  // kg m^2
  for (const std::string& same :
       std::vector<std::string>{i0 + " kg m² (about the centre)", "m R^2/4 (thin disc)",
                                i0 + " (Euler's moment, approx)"}) {
    INFO(same);
    REQUIRE(plate.check("I0", same).correct);
  }
  REQUIRE_FALSE(plate.check("I0", "m R^2/2 (thin disc)").correct);
  // Brackets of symbols, units or Greek letters' names are mathematics, read as before: a
  // product, a unit, or an error that names the unknown symbol.
  REQUIRE_FALSE(plate.check("I0", "m R^2/4 (m R)").correct);
  REQUIRE(plate.check("I0", i0 + " (kg m^2)").correct);
  REQUIRE_THROWS_WITH(plate.check("I0", "0.5 (I theta)"), Catch::Contains("undefined symbol"));
}

TEST_CASE("one word on the motion in brackets after an answer is said to be unjudged") {
  const std::string unjudged = "is taken as a remark, not judged (the value is)";
  int judged = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.value.shape != wobble::Value::Shape::scalar || a.unit.empty()) continue;
        const std::string value = fmt::format("{:.6g} {}", a.value.data[0], a.unit);
        for (const std::string word : {"(unstable)", "(Stable)", "(approx)"}) {
          // A rate about a principal axis has its stability weighed (the next case).
          if (a.stability && word != "(approx)") continue;
          INFO(p.id << " " << a.name << ": " << value << " " << word);
          const auto v = f.check(a.name, value + " " + word);
          REQUIRE(v.correct);
          REQUIRE(v.feedback.back() == "your bracket \"" + word + "\" " + unjudged);
          ++judged;
        }
      }
    }
  }
  REQUIRE(judged > 100);
  // The asymmetric top's intermediate axis: the value judged, whatever the word claims.
  const Fixture top("asymmetric-top");
  const double growth = top.answer("rate_axis2").value.data[0];
  REQUIRE_FALSE(top.check("rate_axis2", fmt::format("{:.4g} 1/s (stable)", 2 * growth)).correct);
  // A word of no such list stays what it is: an unknown name; so does one glued on.
  REQUIRE_THROWS_WITH(top.check("rate_axis2", fmt::format("{:.4g} 1/s (unstabel)", growth)),
                      Catch::Contains("undefined symbol 'unstabel'"));
  REQUIRE_THROWS_WITH(top.check("rate_axis2", fmt::format("{:.4g} 1/s, unstabel", growth)),
                      Catch::Contains("unstabel"));
  REQUIRE_THROWS_WITH(top.check("rate_axis2", fmt::format("{:.4g}unstable", growth)),
                      Catch::Contains("undefined symbol 'unstable'"));
  // Unjudged words last after a comma are said so too, without a bracket.
  REQUIRE(top.check("rate_axis2", fmt::format("{:.6g} 1/s, approx", growth)).feedback.back() ==
          "your word \"approx\" " + unjudged);
}

namespace {
// `a`'s key number with "(word)" after it, or the word last after a comma, a semicolon, a dash
// or a space, and twice that number: the word said right or wrong with `why`; a right number
// with a wrong word is wrong, a wrong number wrong whatever the word.
void check_word_weighed(const Fixture& f, const wobble::Answer& a, const std::string& word,
                        bool right, const std::string& why) {
  const std::string bracket = "(" + word + ")", plain = "your word \"" + word + "\"";
  for (const auto& [after, said] : std::vector<std::pair<std::string, std::string>>{
           {" " + bracket, "your bracket \"" + bracket + "\""},
           {", " + word, plain},
           {"; " + word, plain},
           {" — " + word, plain},
           {" " + word, plain}}) {
    INFO(after);
    const auto v = f.check(a.name, fmt::format("{:.6g} {}{}", a.value.data[0], a.unit, after));
    CHECK(v.correct == right);
    CHECK(v.line ==
          (right ? "correct: " + a.name
                 : "incorrect: " + a.name + " (the number is right, the word after it is not)"));
    CHECK(v.feedback.back() == said + " is " + (right ? "right: " : "wrong: ") + why);
    const auto off =
        f.check(a.name, fmt::format("{:.6g} {}{}", 2 * a.value.data[0], a.unit, after));
    CHECK_FALSE(off.correct);
    CHECK(off.feedback.back() == v.feedback.back());
  }
}
}  // namespace

TEST_CASE("a word on a rate's stability after it is weighed against the key's, every such rate") {
  int weighed = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (!a.stability) continue;
        const bool stable = a.stability->stable;
        // The solver's verdict against the pair of the lecture's Ω about the same axis, an answer
        // of its own: stable exactly where their product is positive.
        const Answer& pair = f.answer("Omega_axis" + a.name.substr(a.name.size() - 1));
        REQUIRE((pair.value.data.at(0) * pair.value.data.at(1) > 0) == stable);
        REQUIRE_THAT(a.stability->why, Catch::Contains(stable ? "is stable (" : "is unstable ("));
        const std::string value = fmt::format("{:.6g} {}", a.value.data[0], a.unit);
        for (const auto& [word, says_stable] :
             std::vector<std::pair<std::string, bool>>{{"stable", true},
                                                       {"Oscillating", true},
                                                       {"oscillatory", true},
                                                       {"unstable", false},
                                                       {"growing", false},
                                                       {"exponential", false}}) {
          INFO(p.id << " " << a.name << ": " << value << " (" << word << ")");
          check_word_weighed(f, a, word, says_stable == stable, a.stability->why);
          ++weighed;
        }
      }
    }
  }
  REQUIRE(weighed == 2 * 3 * 6);  // two problems ask, three axes each, six words
}

TEST_CASE("a word on a precession's sense after its rate is weighed against the key's sign") {
  int weighed = 0, against = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.sign != SignConvention::sense_of_precession ||
            a.value.shape != wobble::Value::Shape::scalar || a.value.data[0] == 0.0) {
          continue;
        }
        const bool with_spin = a.value.data[0] > 0;
        against += with_spin ? 0 : 1;
        // As the key's note states it.
        REQUIRE_THAT(a.notes.at(0), Catch::Contains(with_spin ? "with the spin (oblate body)"
                                                              : "against the spin (prolate body)"));
        const std::string value = fmt::format("{:.6g} {}", a.value.data[0], a.unit);
        for (const auto& [word, says_with_spin] : std::vector<std::pair<std::string, bool>>{
                 {"prograde", true}, {"Oblate", true}, {"retrograde", false}, {"prolate", false}}) {
          INFO(p.id << " " << a.name << ": " << value << " (" << word << ")");
          check_word_weighed(
              f, a, word, says_with_spin == with_spin,
              a.name + (with_spin
                            ? " is along +e₃, with the spin: the body is oblate (I₃ > I₁)"
                            : " is along −e₃, against the spin: the body is prolate (I₃ < I₁)"));
          ++weighed;
        }
      }
    }
  }
  REQUIRE(weighed >= 4 * 4);  // four words on each signed rate of the catalog's free tops
  REQUIRE(against >= 1);      // a prolate body among them: both senses weighed
}

TEST_CASE("a rotation matrix as a product of turns about the axes, multiplied out") {
  // The key derives R = Rz(φ) Ry(θ) Rz(ψ); a student may answer with that product. Its entries,
  // multiplied out here from the turns' own matrices, are judged against the key's R, which the
  // solver builds another way: two derivations that must agree.
  const Fixture euler("euler-angles");  // φ, θ, ψ = 40°, 30°, 70°
  for (const char* same :
       {"Rz(φ) Ry(θ) Rz(ψ)", "R_z(phi)*R_y(theta)*R_z(psi)", "Rz(φ)·Ry(θ)·Rz(ψ)",
        "Rz(40°) Ry(30°) Rz(70 deg)", "R_z(\\phi) \\cdot R_y(\\theta) \\cdot R_z(\\psi)"}) {
    INFO(same);
    REQUIRE(euler.check("R_zyz", same).correct);
  }
  // The PHY 711 matrix is its transpose, or the inverse turns in reverse order.
  // Each turn transposed or inverted is the turn back, as the key's step writes PHY 711's R.
  for (const char* same :
       {"(Rz(φ) Ry(θ) Rz(ψ))ᵀ", "Rz(-ψ) Ry(-θ) Rz(-φ)", "Rz(ψ)ᵀ Ry(θ)ᵀ Rz(φ)ᵀ",
        "R_z(\\psi)^T R_y(\\theta)^T R_z(\\phi)^T",
        "R_z(\\psi)^{T} R_y(\\theta)^\\top R_z(\\phi)^{\\top}", "Rz(ψ)⁻¹ Ry(θ)^-1 Rz(φ)^{-1}",
        "Rz(ψ)' Ry(θ)' Rz(φ)'",
        // Marks mixed, or one alone: a mark after one factor is that factor's,
        // not the whole product's.
        "Rz(ψ)^T Ry(θ)^{-1} Rz(φ)′", "Rz(ψ)^{-1} Ry(θ)^T Rz(φ)^{-1}", "Rz(-ψ) Ry(θ)ᵀ Rz(-φ)",
        // The whole of Taylor's product inverted or transposed, by a mark or by a program's call.
        "(Rz(φ) Ry(θ) Rz(ψ))⁻¹", "(R_z(\\phi) R_y(\\theta) R_z(\\psi))^{-1}",
        "transpose(Rz(φ) Ry(θ) Rz(ψ))", "inv(Rz(φ)*Ry(θ)*Rz(ψ))",
        "np.linalg.inv(Rz(φ) Ry(θ) Rz(ψ))", "(Rz(φ) Ry(θ) Rz(ψ)).T", "Inverse[Rz(φ) Ry(θ) Rz(ψ)]",
        "Transpose[Rz(φ) Ry(θ) Rz(ψ)]"}) {
    INFO(same);
    REQUIRE(euler.check("R_phy711", same).correct);
  }
  // Inverted, the reversed product is another matrix; a call on part of a product is no turn.
  REQUIRE_FALSE(euler.check("R_phy711", "inv(Rz(ψ) Ry(θ) Rz(φ))").correct);
  REQUIRE_THROWS_WITH(euler.check("R_phy711", "inv(Rz(φ) Ry(θ)) Rz(ψ)"),
                      Catch::Contains("unknown function 'inv'"));
  // Transposed in the same order is another matrix.
  REQUIRE_FALSE(euler.check("R_phy711", "Rz(φ)ᵀ Ry(θ)ᵀ Rz(ψ)ᵀ").correct);
  // Order and axes matter: the turns reversed, x for y, and a degree off are wrong.
  for (const char* wrong : {"Rz(ψ) Ry(θ) Rz(φ)", "Rz(φ) Rx(θ) Rz(ψ)", "Rz(41°) Ry(30°) Rz(70°)"}) {
    INFO(wrong);
    REQUIRE_FALSE(euler.check("R_zyz", wrong).correct);
  }
  REQUIRE_THROWS_WITH(euler.check("R_zyz", "Rz(φ) Ry(θ) Rz(ψ) Rx(φ) Ry(θ)"),
                      Catch::Contains("5 turns in a product; at most 4"));
}

TEST_CASE(
    "a vector's entry in degrees may be arithmetic on its angle, as a one-number answer may") {
  const Fixture euler("euler-angles");  // Goldstein's z-x-z angles: (130°, 30°, −20°)
  for (const char* typed :
       {"(2*65°, 30°, -20°)", "(2·65°, 30°, −20°)", "(130°, 60°/2, -20°)", "(130°, 30°, 10° - 30°)",
        "(130°, 30°, 340° − 360°)", "[2*65 deg, 30 deg, -20 deg]"}) {
    INFO(typed);
    REQUIRE(euler.check("angles_zxz", typed).line == "correct: angles_zxz");
  }
  // Worked, not dropped: an entry a degree off is judged so.
  REQUIRE(euler.check("angles_zxz", "(2*65°, 30°, 10° - 31°)").feedback ==
          std::vector<std::string>{"ψ is off by 5%"});
  REQUIRE(euler.check("angles_zxz", "(2*66°, 30°, -20°)").feedback ==
          std::vector<std::string>{"φ is off by 1.54%"});
  // A bare number beside them still needs its unit.
  REQUIRE_THROWS_WITH(euler.check("angles_zxz", "(2*65°, 0.5236, -20°)"),
                      Catch::Contains("the entry \"0.5236\" has no unit where another has deg"));
}

TEST_CASE("Euler angles are the same up to whole turns, and named as the question names them") {
  // Goldstein's z-x-z angles here: (130°, 30°, −20°), φ and ψ in (−180°, 180°].
  const Fixture euler("euler-angles");
  for (const auto& [typed, moved] : std::vector<std::pair<std::string, std::string>>{
           {"(130°, 30°, 340°)", "ψ differs"},
           {"(2.269, 0.5236, 5.934)", "ψ differs"},
           {"(490°, 30°, 340°)", "φ and ψ differ"},
           {"[pi/2 + phi, theta, psi + 3 pi/2]", "ψ differs"},
           {"[pi/2 + phi - 2pi, theta + 2 pi, psi + 3 pi/2]", "φ, θ and ψ differ"}}) {
    INFO(typed);
    const auto v = euler.check("angles_zxz", typed);
    REQUIRE(v.correct);
    REQUIRE_THAT(
        v.line, Catch::EndsWith("(" + moved + " from the key's by whole turns: the same " +
                                (moved.find(" and ") == std::string::npos ? "angle)" : "angles)")));
  }
  REQUIRE(euler.check("angles_zxz", "(130°, 30°, -20°)").line == "correct: angles_zxz");
  // Half a turn is another angle; a wrong entry is named, one turn off judged from the key's
  // range (0.5° off, not "-17 times its right value").
  REQUIRE_FALSE(euler.check("angles_zxz", "(φ − 90°, θ, ψ + 90°)").correct);
  REQUIRE_FALSE(euler.check("angles_zxz", "(130°, 30°, 160°)").correct);
  const auto off = euler.check("angles_zxz", "(130°, 30°, 340.5°)");
  REQUIRE_FALSE(off.correct);
  REQUIRE(off.feedback == std::vector<std::string>{"ψ is off by 2.5%"});
  REQUIRE(euler.check("angles_zxz", "(130°, 35°, -20°)").feedback ==
          std::vector<std::string>{"θ is off by 16.7%"});
  // PHY 711 names its angles α, β, γ; degrees for radians is still said as such.
  const Fixture phy("euler-angles-phy711");
  REQUIRE(phy.check("angles_phy711", "(40°, 30°, 60°)").feedback ==
          std::vector<std::string>{"γ is off by 14.3%"});
  REQUIRE_THAT(euler.check("angles_zxz", "(130, 30, -20)").feedback.at(0),
               Catch::StartsWith("this is the angle in degrees"));
  // Reading back: the same, in any range.
  REQUIRE(euler.check("angles_back_zyz", "(400°, 30°, -290°)").correct);
  // Significant figures are of the number typed: 5.93 is 340° (5.934 rad) to three; a relative
  // tolerance is of the angle, 5.94 rad being 1.7% off the key's -0.349 rad.
  check::Options three;
  three.sigfigs = 3;
  REQUIRE(euler.check("angles_zxz", "(2.27, 0.524, 5.93)", three).correct);
  REQUIRE_FALSE(euler.check("angles_zxz", "(2.27, 0.524, 5.94)", three).correct);
  // A right entry a turn off is no part of what is wrong with the others.
  REQUIRE(euler.check("angles_zxz", "(2.27, 0.600, 5.93)", three).feedback ==
          std::vector<std::string>{"θ is off by 14.6%"});
  REQUIRE_FALSE(euler.check("angles_zxz", "(2.269, 0.5236, 5.94)").correct);
}

TEST_CASE("Euler angles on the other branch, the middle one negative, are told so") {
  // Over the catalog's vectors of angles (all proper Euler angles): (φ + π, −θ, ψ + π) is the
  // key's rotation, and wrong in its convention (θ in [0, π]); the line names the angles as the
  // question does. θ's sign alone turned is another rotation, and told as a wrong sign.
  int told = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (!check::angles_up_to_turns(a)) continue;
        const auto& k = a.value.data;
        const std::string middle = check::entry_name(a, 1);
        for (const double turns : {0.0, 1.0}) {
          const std::string typed = fmt::format("({:.9g}, {:.9g}, {:.9g})", k[0] + M_PI, -k[1],
                                                k[2] + M_PI - 2 * M_PI * turns);
          INFO(p.id << " " << a.name << ": " << typed);
          const check::Verdict v = f.check(a.name, typed);
          REQUIRE_FALSE(v.correct);
          REQUIRE(v.feedback.size() == 1);
          CHECK_THAT(
              v.feedback[0],
              Catch::StartsWith("these angles turn the body as the key's do, on the other "
                                "branch, with " +
                                middle + " negative: " + middle + " = arccos R₃₃") &&
                  Catch::EndsWith(check::entry_name(a, 0) + " and " + check::entry_name(a, 2) +
                                  " are each half a turn from yours"));
          ++told;
        }
        const std::string sign_only = fmt::format("({:.9g}, {:.9g}, {:.9g})", k[0], -k[1], k[2]);
        INFO(sign_only);
        CHECK(f.check(a.name, sign_only).feedback ==
              std::vector<std::string>{middle + " has the wrong sign"});
      }
    }
  }
  REQUIRE(told == 16);  // four vectors of angles in each of the two Euler-angle problems
  // An expression so, at the set values.
  const Fixture euler("euler-angles");
  for (const char* typed : {"[φ + π, −θ, ψ + π]", "[φ + 180°, −θ, ψ − 180°]"}) {
    INFO(typed);
    const check::Verdict v = euler.check("angles_back_zyz", typed);
    REQUIRE_FALSE(v.correct);
    REQUIRE(v.feedback.size() == 1);
    CHECK_THAT(v.feedback[0], Catch::StartsWith("these angles turn the body as the key's do"));
  }
}

TEST_CASE("degrees in an expression in the symbols are radians: φ + 90°") {
  // Goldstein's z-x-z angles are Taylor's with a quarter turn: (φ + π/2, θ, ψ − π/2).
  const Fixture euler("euler-angles");
  for (const char* same : {"(φ + 90°, θ, ψ − 90°)", "[phi + 90 deg, theta, psi - 90deg]",
                           "(\\phi + 90^\\circ, \\theta, \\psi - 90^\\circ)"}) {
    INFO(same);
    REQUIRE(euler.check("angles_zxz", same).correct);
  }
  REQUIRE_FALSE(euler.check("angles_zxz", "(φ + 91°, θ, ψ − 90°)").correct);
  REQUIRE_FALSE(euler.check("angles_zxz", "(φ − 90°, θ, ψ + 90°)").correct);
  // Without the mark a number is in radians: told so where it in degrees is the key's.
  for (const char* unmarked : {"φ+90, θ, ψ-90", "(φ + 90°, θ, ψ - 90)"}) {
    INFO(unmarked);
    const auto v = euler.check("angles_zxz", unmarked);
    REQUIRE_FALSE(v.correct);
    REQUIRE_THAT(v.feedback.at(0),
                 Catch::Equals("90 is in degrees: write 90° (a number without a unit is in "
                               "radians)"));
  }
  REQUIRE_THAT(euler.check("angles_zxz", "φ+100, θ, ψ-90").feedback.at(0),
               !Catch::Contains("in degrees"));
  // In a function's argument too, numbers only or with symbols: a calculator in radians.
  const Fixture top_u("heavy-top");    // u_p = cos θ₀, θ₀ = 30°
  const Fixture disc("flying-plate");  // α = 15°, ω = 10 rad/s
  for (const auto& [fixture, name, text, told] :
       std::vector<std::tuple<const Fixture*, std::string, std::string, std::string>>{
           {&top_u, "u_phidot_zero", "cos(30)", "30 is in degrees: write 30°"},
           {&disc, "angle_L_e3", "atan(tan(15)/2)", "15 is in degrees: write 15°"},
           {&disc, "Omega_space", "[10 sin(15), 0, 20 cos(15)]", "15 is in degrees: write 15°"},
           {&disc, "Omega_body_rate", "ω cos 15",
            "15 is the value of α (alpha) in degrees: write the symbol"}}) {
    INFO(text);
    const auto v = fixture->check(name, text);
    REQUIRE_FALSE(v.correct);
    REQUIRE_THAT(v.feedback.at(0), Catch::StartsWith(told));
  }
  // Without a function, a number in degrees is an angle in degrees, as before.
  REQUIRE_THAT(disc.check("angle_L_e3", "7.63").feedback.at(0),
               Catch::StartsWith("this is the angle in degrees"));
  // A number before a call reads as a product, as a calculator's result is written out.
  REQUIRE(disc.check("Omega_space", "[10 sin(0.2617993878), 0, 20 cos(0.2617993878)]").correct);
  REQUIRE_THAT(top_u.check("u_phidot_zero", "0.5 cos(0.5235987756)").feedback.at(0),
               Catch::Contains("a factor 2 is off"));
  const Fixture plate("flying-plate");
  REQUIRE(plate.check("angle_omega_e3", "α + 0°").correct);
  // In a function's argument too, without symbols: a calculator's cos(30°).
  const Fixture top("heavy-top");  // u_p = cos θ₀, θ₀ = 30°
  for (const char* same : {"cos(30°)", "cos 30°", "cos(30 deg)", "\\cos 30^\\circ"}) {
    INFO(same);
    REQUIRE(top.check("u_phidot_zero", same).correct);
  }
  REQUIRE_FALSE(top.check("u_phidot_zero", "cos(31°)").correct);
  REQUIRE(plate.check("angle_L_e3", "atan(tan(15°)/2)").correct);
  REQUIRE_FALSE(plate.check("angle_L_e3", "atan(tan(15°))").correct);
  // A call without its bracket on a number in degrees, after a factor: the argument is the
  // angle, and a division after it the call's ("tan 15°/2" is tan(15°)/2).
  for (const char* same : {"atan(0.5 tan 15°)", "arctan(tan 15°/2)", "atan(0.5 tan 15 deg)",
                           "θ_L = arctan(0.5 tan 15°) = 7.63°"}) {
    INFO(same);
    REQUIRE(plate.check("angle_L_e3", same).correct);
  }
  REQUIRE_FALSE(plate.check("angle_L_e3", "atan(2 tan 15°)").correct);
  // Arithmetic on angles in degrees, as the half angles are found: the space cone's α − θ_L.
  const double space_cone = plate.answer("space_cone_half_angle").value.data.at(0) * 180 / kPi;
  const double theta_l = plate.answer("angle_L_e3").value.data.at(0) * 180 / kPi;
  for (const std::string& same :
       {fmt::format("15° − {:.3f}°", theta_l), fmt::format("15 deg - {:.3f} deg", theta_l),
        fmt::format("15° − {:.3f}° = {:.3f}°", theta_l, space_cone)}) {
    INFO(same);
    REQUIRE(plate.check("space_cone_half_angle", same).correct);
  }
  REQUIRE_FALSE(
      plate.check("space_cone_half_angle", fmt::format("15° + {:.3f}°", theta_l)).correct);
  REQUIRE(plate.check("angle_omega_e3", "30°/2").correct);
  REQUIRE_FALSE(plate.check("angle_omega_e3", "30°/3").correct);
  // A vector of angles stays one, its entries parted by spaces or signs.
  REQUIRE(euler.check("angles_phy711", "[40 deg 30 deg 70 deg]").correct);
  // A vector of numbers in degrees keeps its units: no function, no symbol.
  REQUIRE(euler.check("angles_phy711", "(40°, 30°, 70°)").correct);
  // A number alone keeps its unit; a unit after the expression stays refused, and degrees
  // divided ("deg/s") are no number in radians.
  REQUIRE(plate.check("angle_omega_e3", "15°").correct);
  REQUIRE_THROWS_WITH(plate.check("angle_omega_e3", "α deg"),
                      Catch::Contains("in SI already; drop the unit 'deg'"));
  REQUIRE_THROWS_WITH(euler.check("omega_primed", "(-φ̇ sin θ, θ̇ + 0 deg/s, φ̇ cos θ + ψ̇)"),
                      !Catch::Contains("pi/180"));
}

TEST_CASE("an expression right at the set values only is told so, not named another answer") {
  // R is 0.12 m here: m 0.12²/4 is I0 at these values and no other.
  const Fixture plate("flying-plate");
  REQUIRE(plate.values.at("R") == 0.12);
  const auto number_for_symbol = plate.check("I0", "m 0.12^2/4");
  REQUIRE_FALSE(number_for_symbol.correct);
  REQUIRE_THAT(number_for_symbol.feedback.at(0),
               Catch::Equals("it gives the key's value at the set values but not at others: 0.12 "
                             "is the value of R: write the symbol"));
  // Degrees (in LaTeX too), two numbers, a value two parameters share, and no number at all.
  REQUIRE_THAT(plate.check("Omega_body_rate", "\\omega\\cos 15^\\circ").feedback.at(0),
               Catch::EndsWith("15° is the value of α (alpha): write the symbol"));
  // 0.5 is both I₃ and θ̇ here: the one that makes the key's expression is named.
  const Fixture phy711("euler-angles-phy711");
  REQUIRE_THAT(phy711.check("L_primed", "[-α̇ I₁ sin β, β̇ I₁, 0.5 (α̇ cos β + γ̇)]").feedback.at(0),
               Catch::EndsWith("0.5 is the value of I₃ (I3): write the symbol"));
  // A symbol of the same value in another's place: θ̇ is 0.5 rad/s and I₃ 0.5 kg m² here. The
  // θ̇ of entry y is right; the one of entry z is named.
  const Fixture euler_angles("euler-angles");
  const auto swapped = euler_angles.check("L_primed", "[-φ̇ I₁ sin θ, θ̇ I₁, θ̇ (φ̇ cos θ + ψ̇)]");
  REQUIRE_FALSE(swapped.correct);
  REQUIRE_THAT(swapped.feedback.at(0),
               Catch::EndsWith("θ̇ (thetadot) where the key has I₃ (I3)? (the same value here, "
                               "not the same quantity)"));
  // Rounded: right at the set values only to a number's tolerance.
  REQUIRE_THAT(plate.check("Omega_body_rate", "ω cos(0.2618)").feedback.at(0),
               Catch::StartsWith("it gives the key's value at the set values only as a number "
                                 "rounded would") &&
                   Catch::EndsWith("0.2618 is the value of α (alpha), rounded: write the symbol"));
  // Within a number's tolerance but no number to blame: half of the top's energy, the small
  // I₁ term left out (0.5% of it), is no "off by 0.5%".
  const Fixture euler_top("euler-angles");
  REQUIRE_THAT(euler_top.check("kinetic_energy", "½I₃(ψ̇ + φ̇ cos θ)²").feedback.at(0),
               Catch::Contains("a small term left out"));
  // An answer far below 1 in SI is held to the same relative digits: the Earth's wobble rate is
  // 2.4e-7 rad/s and L's angle 1e-6 rad, where an absolute 1e-9 passed forms 0.07% and 0.01%
  // off as the key's (1.2 H for H, a factor 1.0001), and said of Hω, 0.3% off, that it gives
  // the key's value at the set values.
  const Fixture earth("earth-free-precession");
  for (const auto& [name, close] : std::vector<std::pair<std::string, std::string>>{
           {"angle_L_e3", "α(1 - 1.2H)"},
           {"angle_L_e3", "α(1 - H - 0.0001)"},
           {"Omega_body_rate", "Hω"},
           {"Omega_body_rate", "1.0001 Hω cos α/(1 - H)"}}) {
    INFO(name << ": " << close);
    const auto v = earth.check(name, close);
    REQUIRE_FALSE(v.correct);
    REQUIRE_THAT(v.feedback.at(0), Catch::Contains("a small term left out"));
  }
  // The small-angle form of the exact atan2 is the key's to 1e-12 at every point: right.
  REQUIRE(earth.check("angle_L_e3", "α(1 - H)").correct);
  REQUIRE(earth.check("Omega_body_rate", "(C - C(1 - H))/(C(1 - H)) ω cos α").correct);
  // Where no parameter has the number's value (m/0.1 is 2 here), no symbol is named.
  REQUIRE_THAT(
      plate.check("I0", "m R^2/4 * (m/0.1)/2").feedback.at(0),
      Catch::EndsWith("a number, or a symbol of the same value, where the key has a symbol?"));
  // One value for every place a number stands: a and m are both 0.3 in the racket, and a is
  // the one whose symbol makes the key's coefficients.
  const Fixture racket("tennis-racket");
  REQUIRE_THAT(racket
                   .check("euler_coefficients",
                          "[-(b + c)(b - c)/(b² + c²), (0.3 + c)(0.3 - c)/(0.3² + c²), "
                          "-(0.3 + b)(0.3 - b)/(0.3² + b²)]")
                   .feedback.at(0),
               Catch::EndsWith("0.3 is the value of a: write the symbol"));
  const Fixture top("heavy-top");
  REQUIRE_THAT(top.check("p_psi", "M*0.05^2*150/2").feedback.at(0),
               Catch::EndsWith("0.05 is the value of R, 150 is the value of ψ̇₀ (psidot0): write "
                               "the symbols"));
  // angles_back_zyz is (φ, θ, ψ) too: a value equal to this answer's is no taking of another.
  const Fixture euler("euler-angles");
  const auto thirty = euler.check("angles_phy711", "(φ, 30°, ψ)");
  REQUIRE_FALSE(thirty.correct);
  REQUIRE_THAT(thirty.feedback.at(0), !Catch::Contains("angles_back_zyz"));
  REQUIRE_THAT(plate.check("I0", "m R^2/8").feedback.at(0), Catch::Contains("factor 2 is off"));
}

TEST_CASE("every closed form with a parameter's value for its symbol is told which symbol") {
  // Each parameter a closed form names, replaced by its value as the key prints it: right at
  // the set values only, and the message names the parameter.
  int told = 0;
  for_each_closed_form([&](const Fixture& f, const Answer& a) {
    for (const auto& parameter : f.key.parameters) {
      const std::string number = format_number(parameter.value);
      // A single digit is taken for a coefficient, not a value (symbol_values.hpp).
      if (parameter.value == 0.0 || number.size() == 1) continue;
      const std::string text = with_symbol_replaced(a.symbolic, parameter.name, number);
      if (text == a.symbolic) continue;
      INFO(f.key.problem << " " << a.name << ": " << text);
      const check::Verdict v = f.check(a.name, text);
      if (v.correct) continue;  // no dependence on it (a ratio where it cancels)
      REQUIRE_FALSE(v.feedback.empty());
      // The value to 10 digits: right at the set values to the expression's 1e-9 (then
      // wrong at others), or within a number's tolerance only.
      REQUIRE_THAT(v.feedback[0],
                   (Catch::StartsWith("it gives the key's value at the set values but not at "
                                      "others: ") ||
                    Catch::StartsWith("it gives the key's value at the set values only as a "
                                      "number rounded would")) &&
                       Catch::Contains(number + " is the value of ") &&
                       Catch::Contains(parameter.name));
      ++told;
    }
  });
  REQUIRE(told > 250);
}

TEST_CASE("every closed form with a symbol for another of the same value is told which") {
  // Each parameter a closed form names, replaced by another whose set value is the same (θ̇ and
  // I₃ both 0.5, the racket's a and m both 0.3): right at the set values only, and the message
  // names both.
  int told = 0;
  for_each_closed_form([&](const Fixture& f, const Answer& a) {
    for (const auto& was : f.key.parameters) {
      for (const auto& put : f.key.parameters) {
        if (put.name == was.name || was.value == 0.0 || put.value != was.value) continue;
        const std::string text = with_symbol_replaced(a.symbolic, was.name, put.name);
        if (text == a.symbolic) continue;
        INFO(f.key.problem << " " << a.name << ": " << text);
        const check::Verdict v = f.check(a.name, text);
        if (v.correct) continue;  // no dependence on it (a ratio where it cancels)
        REQUIRE_FALSE(v.feedback.empty());
        REQUIRE_THAT(v.feedback[0], Catch::StartsWith("it gives the key's value at the set "
                                                      "values but not at others: "));
        // The judge tries up to 32 choices of which places to change: each place of a
        // symbol that shares its value kept or changed (the box's a and M, both 1, in
        // every entry of its tensor are more).
        std::size_t choices = 1;
        for (const auto& q : f.key.parameters) {
          std::size_t partners = 0;
          for (const auto& r : f.key.parameters)
            partners += r.name != q.name && r.value == q.value && q.value != 0.0;
          for (std::size_t places = occurrences(text, q.name); places-- > 0;)
            choices = std::min<std::size_t>(choices * (partners + 1), 1000);
        }
        if (choices > 32) continue;
        REQUIRE_THAT(v.feedback[0], Catch::Contains(" where the key has ") &&
                                        Catch::Contains(was.name) && Catch::Contains(put.name));
        ++told;
      }
    }
  });
  REQUIRE(told > 20);
}

TEST_CASE("equal components told once, I₁ = I₂ = .., and a symbol glued to a number over one") {
  const Fixture cone("solid-cone");  // about the centre of mass: I₁ = I₂ = 3M(4R² + h²)/80
  const auto& moments = cone.answer("principal_moments_cm").value.data;  // ascending
  REQUIRE(moments.at(1) == moments.at(2));
  const std::string pair = fmt::format("{:.6g}", moments.at(1));
  const std::string axis = fmt::format("{:.6g}", moments.at(0));
  for (const std::string& same :
       {std::string("I₁ = I₂ = 3M(4R² + h²)/80, I₃ = 3M R²/10"),
        "I1 = I2 = " + pair + " kg m², I3 = " + axis + " kg m²", "I_3 = " + axis + ", I_1 = I_2 = " + pair}) {
    INFO(same);
    REQUIRE(cone.check("principal_moments_cm", same).correct);
  }
  REQUIRE_FALSE(cone.check("principal_moments_cm", "I₁ = I₂ = " + axis + ", I₃ = " + pair).correct);
  REQUIRE_FALSE(cone.check("principal_moments_cm", "I1 = I2 = I3 = " + pair).correct);
  // A closed form between the labels is no label: a key's line, refused as more than two sides.
  REQUIRE_THROWS_WITH(cone.check("principal_moments_cm", "I₁ = I₂ = 3M R²/10 = " + axis),
                      Catch::Contains("sides of '='"));
  // The centre of mass at -3h/4 along the axis, h the height glued to its factor: no unit (hours)
  // is divided by a number, so h is the symbol.
  REQUIRE(cone.check("center_of_mass", "(0, 0, -3h/4)").correct);
  REQUIRE_FALSE(cone.check("center_of_mass", "(0, 0, 3h/4)").correct);
}

TEST_CASE("axes listed as the rows of an eigenvector matrix are said to be its rows") {
  // Taylor 10.35: the axes are x and (y ± z)/√2, the columns of the key's matrix; numpy's
  // eigh(I)[1] prints that matrix, and its rows listed one by one are no axes.
  const Fixture taylor("taylor-10-35");
  for (const char* rows :
       {"(0, 0, 1), (0.7071, 0.7071, 0), (-0.7071, 0.7071, 0)", "ẑ, (x̂ + ŷ)/√2, (ŷ − x̂)/√2"}) {
    INFO(rows);
    const auto v = taylor.check("principal_axes", rows);
    REQUIRE_FALSE(v.correct);
    REQUIRE_THAT(v.feedback.at(0), Catch::StartsWith("these are the rows of the axes' matrix"));
  }
  // Listed as the columns, they are the axes; as a matrix, either way reads.
  REQUIRE(taylor.check("principal_axes", "(0, 1, -1)/√2, (0, 1, 1)/√2, (1, 0, 0)").correct);
  REQUIRE(taylor.check("principal_axes", "[[0, 0, 1], [0.7071, 0.7071, 0], [-0.7071, 0.7071, 0]]")
              .correct);
  // Vectors that are no axes either way get no such line.
  const auto wrong = taylor.check("principal_axes", "(1, 1, 0), (1, -1, 0), (0, 0, 1)");
  REQUIRE_FALSE(wrong.correct);
  REQUIRE_THAT(wrong.feedback.at(0), !Catch::Contains("rows of the axes' matrix"));
}

TEST_CASE("principal axes listed one by one are the axes, with a factor or along unit vectors") {
  // The four masses' axes: (1, 1, 0)/√2, (1, −1, 0)/√2, (0, 0, 1). Their matrix's rows, (1, 0,
  // 1), (1, 0, −1), (0, 1, 0), are no axes: a listed vector is never read across.
  const Fixture masses("four-masses");
  for (const char* same :
       {"(1,1,0)/√2, (1,-1,0)/√2, (0,0,1)", "1/√2 (1, 1, 0), 1/√2 (1, −1, 0), (0, 0, 1)",
        "x̂ + ŷ, x̂ − ŷ, ẑ", "[x̂ + ŷ, x̂ − ŷ, ẑ]", "{x̂ + ŷ, x̂ − ŷ, ẑ}", "(x̂ + ŷ)/√2, (x̂ − ŷ)/√2, ẑ",
        "e1 = (1, 1, 0)/√2, e2 = (1, -1, 0)/√2, e3 = (0, 0, 1)",
        "\\frac{1}{\\sqrt{2}}(1,1,0), \\frac{1}{\\sqrt{2}}(1,-1,0), (0,0,1)",
        // A root of a digit without brackets, as TeX and a keyboard allow.
        "\\frac1{\\sqrt2}(1,1,0), \\frac{1}{\\sqrt 2}(1,-1,0), (0,0,1)",
        "e1=(i+j)/sqrt2, e2=(i-j)/sqrt2, e3=k",
        "[1/sqrt2, 1/sqrt2, 0], [sqrt2/2, -sqrt(2)/2, 0], [0, 0, 1]",
        "[1, 1, 0], [1, -1, 0], [0, 0, 1]"}) {
    INFO(same);
    REQUIRE(masses.check("principal_axes", same).correct);
  }
  for (const char* across :
       {"(1,0,1)/√2, (1,0,-1)/√2, (0,1,0)", "x̂ + ẑ, x̂ − ẑ, ŷ", "[1, 0, 1], [1, 0, -1], [0, 1, 0]",
        "e1 = (1, 0, 1), e2 = (1, 0, -1), e3 = (0, 1, 0)",
        "e1 = (1, 0, 1)/√2, e2 = (1, 0, -1)/√2, e3 = (0, 1, 0)"}) {
    INFO(across);
    const auto v = masses.check("principal_axes", across);
    REQUIRE_FALSE(v.correct);
    // The rows of the axes' matrix: said first, then each vector that is no axis.
    REQUIRE_THAT(v.feedback.at(0), Catch::StartsWith("these are the rows of the axes' matrix"));
    REQUIRE_THAT(v.feedback.at(1),
                 Catch::Contains("(1, 0, 1)") || Catch::Contains("(0.7071, 0, 0.7071)"));
  }
  // A matrix in one bracket, as the key prints its axes' matrix, may hold them either way.
  REQUIRE(masses.check("principal_axes", "[[1, 0, 1], [1, 0, -1], [0, 1, 0]]").correct);
  REQUIRE(masses.check("principal_axes", "[[1, 1, 0], [1, -1, 0], [0, 0, 1]]").correct);
  // A minus as a PDF sets it between unit vectors, and a list whose factors run together: read
  // as products; with one in the wrong case, the message names the symbols, not a unit "Ma^2".
  const Fixture plate("flying-plate");
  REQUIRE_FALSE(plate.check("L0_body", "0.001863 x̂ − 0.01391 ẑ").correct);
  REQUIRE(masses.check("principal_moments", "5/2 ma², 3ma², 7/2 ma²").correct);
  REQUIRE_THROWS_WITH(masses.check("principal_moments", "5/2 Ma², 3Ma², 7/2 Ma²"),
                      Catch::Contains("undefined symbol 'Ma' (names are case-sensitive: m*a?)"));
}

TEST_CASE("an answer's name as the statement or LaTeX writes it finds the answer") {
  const Fixture plate("flying-plate");
  using wobble::check::name_in_key;
  for (const char* i0 : {"I0", "I₀", "I_0", "I_{0}"}) REQUIRE(name_in_key(plate.key, i0) == "I0");
  REQUIRE(name_in_key(plate.key, "L_{0,\\mathrm{body}}") == "L0_body");
  REQUIRE(name_in_key(plate.key, "Ω_body_rate") == "Omega_body_rate");
  // A part's id stays itself, and a word that is neither is returned for the lookup to refuse.
  REQUIRE(name_in_key(plate.key, "a") == "a");
  REQUIRE(name_in_key(plate.key, "ψ_L") == "ψ_L");
  // A name the steps write for an answer finds it: tan θ_L = (I1/I3) tan α, the angle of L.
  REQUIRE(name_in_key(plate.key, "θ_L") == "angle_L_e3");
  REQUIRE(name_in_key(plate.key, "\\theta_{L}") == "angle_L_e3");
  REQUIRE(name_in_key(plate.key, "") == "");
  // The centre of mass as its step writes it, r_cm = Σ m r / Σ m, in every problem that asks it.
  for (const char* id :
       {"box-corner", "solid-cone", "three-atom-molecule", "three-atom-molecule-symmetric"}) {
    INFO(id);
    const Fixture body(id);
    for (const char* r_cm : {"r_cm", "r_{cm}", "r_{\\mathrm{cm}}"})
      REQUIRE(name_in_key(body.key, r_cm) == "center_of_mass");
  }
  // A prime makes another name: the heavy top's level E′ (as the question writes it) is not its
  // energy E (as the steps do), however the prime is typed.
  const Fixture top("heavy-top");
  REQUIRE(name_in_key(top.key, "E") == "energy");
  for (const char* level : {"E'", "E′", "E’"})
    REQUIRE(name_in_key(top.key, level) == "energy_prime");
  // The Lagrangian's value at t = 0 as the question asks it, L(0) or L₀; L alone names nothing
  // (in an expression it is more likely the pivot's l in the wrong case).
  for (const char* at_start : {"L(0)", "L₀", "L_0"})
    REQUIRE(name_in_key(top.key, at_start) == "lagrangian0");
  REQUIRE(name_in_key(top.key, "L") == "L");
  REQUIRE(name_in_key(plate.key, "θ_L'") == "θ_L'");
  // The asymmetric top's k′² = 1 − k² (kc2, as its note writes it) is not k² (k2).
  const Fixture asymmetric("asymmetric-top");
  for (const char* kc2 : {"k'^2", "k′²", "k’^2"})
    REQUIRE(name_in_key(asymmetric.key, kc2) == "kc2");
  for (const char* k2 : {"k^2", "k²"}) REQUIRE(name_in_key(asymmetric.key, k2) == "k2");
}

TEST_CASE("a label the steps write for the centre of mass names it") {
  const Fixture box("box-corner");
  REQUIRE(box.check("center_of_mass", "r_cm = (0.5, 1, 1.5) m").correct);
  REQUIRE_FALSE(box.check("center_of_mass", "r_cm = (1, 2, 3) m").correct);
  // A label no symbol could be, dω/dt as the question writes dw_dt0, is that answer's own:
  // nothing said of it.
  const Fixture top("asymmetric-top");
  const auto& d = top.answer("dw_dt0").value.data;
  const std::string rates = fmt::format("({:.6g}, {:.6g}, {:.6g}) rad/s²", d[0], d[1], d[2]);
  for (const std::string label : {"dω/dt", "ω̇(0)", "dw/dt"}) {
    INFO(label);
    const auto v = top.check("dw_dt0", label + " = " + rates);
    REQUIRE(v.correct);
    REQUIRE(v.feedback.empty());
  }
}

TEST_CASE("a refusal shown where no option was typed names an entry counted from 1") {
  using wobble::check::without_option;
  REQUIRE(without_option("--answer: empty") == "empty");
  REQUIRE(without_option("--answer[0]: cannot read expression \"ma\"") ==
          "entry 1: cannot read expression \"ma\"");
  REQUIRE(without_option("--answer[2][1]: a ',' where") == "entry (3, 2): a ',' where");
  // Anything else stays as it is.
  for (const char* other : {"--answer[x]: no", "--answer[0] no colon", "--answer[]: no",
                            "--set: R=0", "--answer[1][2][3]: three"})
    REQUIRE(without_option(other) == other);
}

TEST_CASE("an answer with a '±' is two answers: which is right is said, in every spelling") {
  const Fixture racket("tennis-racket");
  // The growth rate about the unstable axis: the roots of Ω² = −rate², written ±.
  const std::string rate = fmt::format("{:.6g}", racket.answer("rate_axis2").value.data.at(0));
  for (const std::string sign : {"±", "+/-", "+/−", "+-", "\\pm "}) {
    INFO(sign);
    REQUIRE_THROWS_WITH(racket.check("rate_axis2", "λ = " + sign + rate + " 1/s"),
                        Catch::Contains("'±' gives two answers; type one: with '+' it is right; "
                                        "with '−', the sign is reversed"));
  }
  REQUIRE_THROWS_WITH(racket.check("rate_axis2", "∓" + rate + " 1/s"),
                      Catch::Contains("type one: with '−' it is right"));
  REQUIRE_THROWS_WITH(racket.check("rate_axis2", "±" + rate + "/2 1/s"),
                      Catch::Contains("type one: neither is right (with '+', this is 1/2 of the answer"));
  // A value with its uncertainty, both ends within the tolerance: right either way.
  const auto within = racket.check("rate_axis2", rate + " ± 0.001 1/s");
  REQUIRE(within.correct);
  REQUIRE_THAT(within.line, Catch::EndsWith("(with either sign of its '±')"));
  REQUIRE_FALSE(racket.check("rate_axis2", "-" + rate + " 1/s").correct);

  // The heavy top's precession rates, the roots of I1 cos θ φ̇² − I3 ω3 φ̇ + M g l = 0 by the
  // quadratic formula (I1 about the pivot, I3 = M R²/2, ω3 = ψ̇0): a derivation apart from the
  // key's. The sign that is not asked for gives the other rate.
  const Fixture top("heavy-top");
  const std::string i1 = "M*(R^2/4 + l^2)", i3w3 = "(M*R^2/2*psidot0)";
  const std::string roots =
      fmt::format("({0} ± sqrt({0}^2 - 4*{1}*cos(theta0)*M*g*l))/(2*{1}*cos(theta0))", i3w3, i1);
  REQUIRE_THROWS_WITH(top.check("phidot_slow", roots),
                      Catch::Contains("with '−' it is right; with '+', this is phidot_fast"));
  REQUIRE_THROWS_WITH(top.check("phidot_fast", roots),
                      Catch::Contains("with '+' it is right; with '−', this is phidot_slow"));
  std::string slow = roots;
  slow.replace(slow.find("±"), std::string("±").size(), "-");
  REQUIRE(top.check("phidot_slow", slow).correct);
}

TEST_CASE("an imaginary number where a real one is wanted is said to be read as a unit vector") {
  const Fixture racket("tennis-racket");
  const double rate = racket.answer("rate_axis2").value.data.at(0);
  const std::string growth = "an imaginary frequency iλ is a growth e^(λt), and its rate is λ";
  REQUIRE_THROWS_WITH(
      racket.check("rate_axis2", fmt::format("{:.6g}i rad/s", rate)),
      Catch::Contains("the i reads as the unit vector î along x") && Catch::Contains(growth));
  REQUIRE_THROWS_WITH(racket.check("rate_axis2", fmt::format("{:.6g}j", rate)),  // Python's
                      Catch::Contains("the j reads as the unit vector ĵ along y"));
  REQUIRE_THROWS_WITH(racket.check("rate_axis2", fmt::format("sqrt(-{:.6g}) 1/s", rate * rate)),
                      Catch::Contains("not real (answers here are real; " + growth));
  // An energy is no rate: the line says only that answers are real.
  REQUIRE_THROWS_WITH(racket.check("energy", "0.16i J"),
                      Catch::Contains("answers here are real)") && !Catch::Contains(growth));
  // NumPy's real roots, 4.995+0.j, have no imaginary unit to name: the list is the mistake.
  REQUIRE_THROWS_WITH(
      racket.check("rate_axis2", fmt::format("array([{0:.6g}+0.j, -{0:.6g}+0.j])", rate)),
      Catch::Contains("not a 2-vector") && !Catch::Contains("unit vector"));
  // An i inside a name (pi, sin) is no imaginary unit.
  REQUIRE(racket.check("rate_axis2", fmt::format("{:.6g}*pi/pi*sin(pi/2) 1/s", rate)).correct);
}

TEST_CASE("labels before a ':', a unit after labelled components, a row of numbers with its unit") {
  const Fixture box("box-corner");
  const auto& centre = box.answer("center_of_mass").value.data;  // (a/2, b/2, c/2) in m
  const auto at = [&](std::size_t k, double scale) {
    return fmt::format("{:.6g}", centre.at(k) * scale);
  };
  const std::string x = at(0, 1), y = at(1, 1), z = at(2, 1);
  for (const std::string& right :
       {"centre of mass: (" + x + ", " + y + ", " + z + ") m",
        "r_cm: [" + x + ", " + y + ", " + z + "]", "x: " + x + ", y: " + y + ", z: " + z,
        "x: " + x + " m, y: " + y + " m, z: " + z + " m",
        "x = " + x + ", y = " + y + ", z = " + z + " m",
        "x = " + at(0, 100) + ", y = " + at(1, 100) + ", z = " + at(2, 100) + " cm",
        "(" + x + " " + y + " " + z + ")", "(" + x + " " + y + " " + z + ") m",
        x + " " + y + " " + z + " m", at(0, 100) + " " + at(1, 100) + " " + at(2, 100) + " cm"}) {
    INFO(right);
    REQUIRE(box.check("center_of_mass", right).correct);
  }
  // The unit after the last value as typed, with its superscript: the principal moments' kg m².
  const auto& moments_kg_m2 = box.answer("principal_moments_corner").value.data;
  for (const char* unit : {"kg m²", "kg·m²", "kg m^2", "Kg m²", "kgs m^2"}) {
    const std::string labelled =
        fmt::format("I₁ = {:.6g}, I₂ = {:.6g}, I₃ = {:.6g} {}", moments_kg_m2.at(0),
                    moments_kg_m2.at(1), moments_kg_m2.at(2), unit);
    INFO(labelled);
    REQUIRE(box.check("principal_moments_corner", labelled).correct);
  }
  // The unit after the last value is the whole vector's: in mm the values are 1000 times off.
  const auto mm = box.check("center_of_mass", "x = " + x + ", y = " + y + ", z = " + z + " mm");
  REQUIRE_FALSE(mm.correct);
  REQUIRE_THAT(mm.feedback.at(0), Catch::Contains("1/1000"));
  // A unit on some values but not all is still refused, as in a bracket.
  REQUIRE_THROWS_WITH(
      box.check("center_of_mass", "x = " + x + " m, y = " + y + ", z = " + z + " m"),
      Catch::Contains("has no unit where another has m"));
  // A label is words, a letter first: a formula before a ':' is no label.
  REQUIRE_THROWS_AS(box.check("center_of_mass", "a/2: (" + x + ", " + y + ", " + z + ")"),
                    InputError);
  const auto& moments = box.answer("principal_moments_corner").value.data;
  const std::string moments_text =
      fmt::format("{:.6g}, {:.6g}, {:.6g}", moments.at(0), moments.at(1), moments.at(2));
  REQUIRE(box.check("principal_moments_corner", "eigenvalues: " + moments_text).correct);
  REQUIRE(box.check("principal_moments_corner",
                    fmt::format("λ₁: {:.6g}, λ₂: {:.6g}, λ₃: {:.6g}", moments.at(0), moments.at(1),
                                moments.at(2)))
              .correct);
  REQUIRE_FALSE(box.check("principal_moments_corner", "eigenvalues: 1, 2, 3").correct);
}

TEST_CASE("unit vectors spelt in ASCII as plain text writes them") {
  const Fixture plate("flying-plate");
  const auto& omega = plate.answer("Omega_space").value.data;  // (ω sin α, 0, 2ω cos α)
  REQUIRE(omega.at(1) == 0.0);
  const std::string x = fmt::format("{:.6g}", omega.at(0)), z = fmt::format("{:.6g}", omega.at(2));
  for (const auto& [ex, ez] :
       {std::pair{"x^", "z^"}, std::pair{"ihat", "khat"}, std::pair{"i-hat", "k-hat"},
        std::pair{"x_hat", "z_hat"}, std::pair{"e_x", "e_z"}, std::pair{"xhat", "zhat"}}) {
    const std::string text = x + " " + ex + " + " + z + " " + ez + " rad/s";
    INFO(text);
    REQUIRE(plate.check("Omega_space", text).correct);
  }
  REQUIRE(plate.check("Omega_space", "ω(sin α x^ + 2 cos α z^)").correct);
  REQUIRE_FALSE(plate.check("Omega_space", z + " x^ + " + x + " z^").correct);
  // A caret before a number is a power: z^2 is no unit vector (and z no symbol here).
  REQUIRE_THROWS_AS(plate.check("Omega_space", x + " x^ + " + z + " z^2"), InputError);
}

TEST_CASE("the cosine of an angle asked for, as u = cos θ is found first, is read as its angle") {
  const Fixture top("heavy-top");
  const double theta_max = top.answer("theta_max").value.data.at(0);
  const std::string u = fmt::format("{:.6g}", std::cos(theta_max));
  for (const std::string& left :
       {std::string("cos θ_max"), std::string("cos(theta_max)"), std::string("cosθmax")}) {
    INFO(left);
    const auto v = top.check("theta_max", left + " = " + u);
    REQUIRE(v.correct);
    REQUIRE(v.feedback == std::vector<std::string>{"read as theta_max = acos(" + u +
                                                   "): your '=' gives cos theta_max"});
  }
  REQUIRE(top.check("theta_max", fmt::format("sin θ_max = {:.6g}", std::sin(theta_max))).correct);
  const auto wrong =
      top.check("theta_max", fmt::format("cos θ_max = {:.6g}", std::cos(theta_max) * 0.8));
  REQUIRE_FALSE(wrong.correct);
  REQUIRE_THAT(wrong.feedback.back(), Catch::StartsWith("read as theta_max = acos("));
  // The cosine of another answer's name is no such reading: its side is a label.
  const auto other = top.check("theta_max", "cos θ_min = " + u);
  REQUIRE(other.correct == false);
  REQUIRE_THAT(other.feedback.back(), Catch::Contains("taken as a label"));
}

TEST_CASE("a name squared before the value gives the square of the answer, read as its root") {
  const Fixture racket("tennis-racket");
  const double rate = racket.answer("rate_axis2").value.data.at(0);  // 1/s
  const std::string square = fmt::format("{:.6g}", rate * rate);
  // A label of the student's own, or the answer's name; the unit's powers halved.
  for (const std::string& written :
       {"λ² = " + square, "lambda^2 = " + square + " s^-2", "Ω² = " + square + " rad²/s²",
        "rate_axis2^2 = " + square + " 1/s^2"}) {
    INFO(written);
    const auto v = racket.check("rate_axis2", written);
    REQUIRE(v.correct);
    REQUIRE_THAT(v.feedback.back(), Catch::StartsWith("read as rate_axis2 = √(" + square));
  }
  const auto wrong = racket.check("rate_axis2", fmt::format("λ² = {:.6g}", rate * rate * 1.1));
  REQUIRE_FALSE(wrong.correct);
  REQUIRE_THAT(wrong.feedback.back(), Catch::StartsWith("read as rate_axis2 = √("));
  // A negative square is an imaginary rate, and is told so.
  REQUIRE_THROWS_WITH(racket.check("rate_axis2", "λ² = -" + square),
                      Catch::Contains("an imaginary frequency iλ is a growth"));
  // A symbol of the problem squared is an expression, judged as one (ω here is the spin).
  REQUIRE_FALSE(racket.check("rate_axis2", "ω² = " + square).correct);
  // An answer with a sign: the root with the sign that makes it right, said.
  const Fixture solid("rect-solid");
  const double body = solid.answer("Omega_body_rate").value.data.at(0);
  REQUIRE(body < 0);
  const auto negative =
      solid.check("Omega_body_rate", fmt::format("Ω_b² = {:.8g} rad²/s²", body * body));
  REQUIRE(negative.correct);
  REQUIRE_THAT(negative.feedback.back(), Catch::StartsWith("read as Omega_body_rate = −√("));
  // "k² = .." names the key's k2: the answer k2 is k², and k is its root.
  const Fixture top("asymmetric-top");
  const std::string k2 = fmt::format("{:.8g}", top.answer("k2").value.data.at(0));
  REQUIRE(top.check("k2", "k² = " + k2).correct);
  REQUIRE(top.check("k2", "k² = " + k2).feedback.empty());
  REQUIRE(top.check("k", "k² = " + k2).correct);
}

TEST_CASE("a square given in its root's unit is wrong, and says which unit the square is in") {
  const Fixture racket("tennis-racket");
  const Answer& rate = racket.answer("rate_axis2");
  REQUIRE(rate.unit == "1/s");
  const double square = rate.value.data.at(0) * rate.value.data.at(0);
  const auto v = racket.check("rate_axis2", fmt::format("λ² = {:.6g} 1/s", square));
  REQUIRE_FALSE(v.correct);
  REQUIRE(v.line == "incorrect: the square of rate_axis2 has the wrong dimension");
  REQUIRE(v.feedback ==
          std::vector<std::string>{"you gave λ² in 1/s (1 / time); the square of rate_axis2 is "
                                   "in (1/s)² (1 / time²)",
                                   "in (1/s)² the number would be right"});
  // A wrong number as well: only the unit is named.
  const auto both = racket.check("rate_axis2", fmt::format("λ² = {:.6g} 1/s", square * 1.1));
  REQUIRE_FALSE(both.correct);
  REQUIRE(both.feedback.size() == 1);
  // Any unit no square has, and an answer with a sign: its negative root is found too.
  const Fixture solid("rect-solid");
  const double body = solid.answer("Omega_body_rate").value.data.at(0);
  REQUIRE(body < 0);
  const auto negative =
      solid.check("Omega_body_rate", fmt::format("Ω_b² = {:.8g} kg", body * body));
  REQUIRE_FALSE(negative.correct);
  REQUIRE_THAT(negative.feedback.front(), Catch::StartsWith("you gave Ω_b² in kg (mass); "));
  REQUIRE(negative.feedback.back() ==
          "in (" + solid.answer("Omega_body_rate").unit + ")² the number would be right");
}

TEST_CASE("Euler's equations written out are read as their coefficients, as the key prints them") {
  // The key's own step, over every problem that asks for the coefficients: pasted back, right.
  int pasted = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.name != "euler_coefficients") continue;
        for (const auto& step : part.steps) {
          // As the key holds it (JSON), "dw1/dt = -0.5 w2 w3, .." and the general "I1 dw1/dt =
          // (I2 − I3) w2 w3, ..", with its full stop; the terminal's dω₁/dt .. ω₂ ω₃ is pasted
          // in cli_tests.
          const auto colon = step.text.find(": ");
          if (colon == std::string::npos || step.text.find("dw1/dt = ") == std::string::npos ||
              step.text.find(" w2 w3") == std::string::npos)
            continue;
          const std::string equations = step.text.substr(colon + 2);
          INFO(p.id << ": " << equations);
          const auto v = f.check(a.name, equations);
          if (equations.starts_with("I1 ") && !f.table.contains("I1")) {
            // The racket's moments are no symbols: read as the steps' names for its moments.
            REQUIRE(v.correct);
            REQUIRE_THAT(v.feedback.front(), Catch::StartsWith("read with I1 = "));
            continue;
          }
          REQUIRE(v.correct);
          REQUIRE_THAT(
              v.feedback.back(),
              Catch::StartsWith("read as the coefficients of Euler's equations: (c₁, c₂, c₃) = ["));
          ++pasted;
          // The LaTeX key's source of the same step, where it has one.
          if (step.latex.empty()) continue;
          INFO(step.latex);
          REQUIRE(f.check(a.name, step.latex).correct);
          ++pasted;
        }
      }
    }
  }
  REQUIRE(pasted >= 4);  // the asymmetric top's two forms (and LaTeX), the racket's numbers
  const Fixture racket("tennis-racket");
  const auto& c = racket.answer("euler_coefficients").value.data;
  const auto n = [&](std::size_t i, double scale = 1.0) {
    return fmt::format("{:.6g}", c.at(i) * scale);
  };
  // In any order, spelt as hands and keyboards write the derivative, the products run together.
  for (const std::string& written :
       {"dw1/dt = " + n(0) + " w2 w3; dw2/dt = " + n(1) + " w3 w1; dw3/dt = " + n(2) + " w1 w2",
        "ω̇₂ = " + n(1) + " ω₃ω₁, ω̇₁ = " + n(0) + " ω₂ ω₃, ω̇₃ = " + n(2) + " ω₁·ω₂",
        "omega1' = " + n(0) + "*omega_2*omega_3\nomega2' = " + n(1) +
            "*omega_3*omega_1\nomega3' = " + n(2) + "*omega_1*omega_2",
        // LaTeX, as a student types it and as a LaTeX key sets the derivative.
        "\\dot\\omega_1 = " + n(0) + "\\,\\omega_2\\omega_3, \\dot\\omega_2 = " + n(1) +
            "\\,\\omega_3\\omega_1, \\dot\\omega_3 = " + n(2) + "\\,\\omega_1\\omega_2",
        "$\\frac{d\\omega_{1}}{dt} = " + n(0) +
            "\\omega_{2}\\omega_{3},\\quad "
            "\\mathrm{d}\\omega_{2}/\\mathrm{d}t = " +
            n(1) +
            "\\omega_{3}\\omega_{1},\\quad "
            "\\dot{\\omega}_{3} = " +
            n(2) + "\\omega_{1}\\omega_{2}$",
        // As a PDF of the LaTeX key copies its step: spaces before '/', ',' and the full stop.
        "dω1 /dt = " + n(0) + " ω2 ω3 , dω2 /dt = " + n(1) + " ω3 ω1 , dω3 /dt = " + n(2) +
            " ω1 ω2 .",
        std::string("dω₁/dt = (c² − b²)/(b² + c²) ω₂ ω₃, dω₂/dt = (a² − c²)/(a² + c²) ω₃ ω₁, "
                    "dω₃/dt = (b² − a²)/(a² + b²) ω₁ ω₂")}) {
    INFO(written);
    REQUIRE(racket.check("euler_coefficients", written).correct);
  }
  // A wrong coefficient is judged wrong, the reading said.
  const auto wrong =
      racket.check("euler_coefficients", "dω₁/dt = " + n(0) + " ω₂ ω₃, dω₂/dt = " + n(1, 2.0) +
                                             " ω₃ ω₁, dω₃/dt = " + n(2) + " ω₁ ω₂");
  REQUIRE_FALSE(wrong.correct);
  REQUIRE_THAT(
      wrong.feedback.back(),
      Catch::StartsWith("read as the coefficients of Euler's equations: (c₁, c₂, c₃) = ["));
  // The wrong components on a right side are a wrong equation, whatever its coefficient: each
  // such equation is named, with the form it should have.
  const auto pair =
      racket.check("euler_coefficients", "dω₁/dt = " + n(0) + " ω₁ ω₃, dω₂/dt = " + n(1) +
                                             " ω₃ ω₁, dω₃/dt = " + n(2) + " ω₃²");
  REQUIRE_FALSE(pair.correct);
  REQUIRE(pair.line ==
          "incorrect: euler_coefficients: in Euler's equations each dωᵢ/dt is a coefficient times "
          "the other two components");
  REQUIRE(pair.feedback == std::vector<std::string>{"dω₁/dt = c₁ ω₂ ω₃, and yours has ω₁ ω₃",
                                                    "dω₃/dt = c₃ ω₁ ω₂, and yours has ω₃²"});
  // A sum beside the components multiplies only its last term: a − b ω₂ ω₃ is no coefficient
  // times ω₂ ω₃, and is not read as one.
  REQUIRE_THROWS_AS(racket.check("euler_coefficients", "dω₁/dt = 1 - 2 ω₂ ω₃, dω₂/dt = " + n(1) +
                                                           " ω₃ ω₁, dω₃/dt = " + n(2) + " ω₁ ω₂"),
                    InputError);
  REQUIRE(racket
              .check("euler_coefficients", "dω₁/dt = (" + n(0, 2.0) + " + " + n(0, -1.0) +
                                               ") ω₂ ω₃, dω₂/dt = " + n(1) +
                                               " ω₃ ω₁, dω₃/dt = " + n(2) + " ω₁ ω₂")
              .correct);
  // Fewer than three, or one twice: no vector of coefficients, and the line says which.
  REQUIRE_THROWS_WITH(racket.check("euler_coefficients",
                                   "dω₁/dt = " + n(0) + " ω₂ ω₃, dω₂/dt = " + n(1) + " ω₃ ω₁"),
                      Catch::Contains("Euler's equations: give one for each component") &&
                          Catch::EndsWith("(dω₃/dt missing)"));
  REQUIRE_THROWS_WITH(racket.check("euler_coefficients", "dω₂/dt = " + n(1) + " ω₃ ω₁"),
                      Catch::EndsWith("(dω₁/dt missing, dω₃/dt missing)"));
  REQUIRE_THROWS_WITH(
      racket.check("euler_coefficients", "dω₁/dt = " + n(0) + " ω₂ ω₃, dω₁/dt = " + n(1) +
                                             " ω₃ ω₂, dω₃/dt = " + n(2) + " ω₁ ω₂"),
      Catch::EndsWith("(dω₁/dt twice, dω₂/dt missing)"));
  // A wrong coefficient is named as the equations name it, c₁ to c₃.
  const auto swapped =
      racket.check("euler_coefficients", "dω₁/dt = " + n(2) + " ω₂ ω₃, dω₂/dt = " + n(1) +
                                             " ω₃ ω₁, dω₃/dt = " + n(0) + " ω₁ ω₂");
  REQUIRE_FALSE(swapped.correct);
  REQUIRE(swapped.feedback.at(0) == "the right entries in another order: c₁ and c₃ are swapped");
  // The same equations for dω/dt at t = 0 (values, not coefficients) are read so, and wrong.
  const auto rates = racket.check("dw_dt0", "dω₁/dt = " + n(0) + " ω₂ ω₃, dω₂/dt = " + n(1) +
                                                " ω₃ ω₁, dω₃/dt = " + n(2) + " ω₁ ω₂");
  REQUIRE_FALSE(rates.correct);
}

TEST_CASE("Euler's equations with the moments written, I₁ ω̇₁ = (I₂ − I₃) ω₂ ω₃, read as theirs") {
  const Fixture top("asymmetric-top");  // I = (2, 3, 4) kg m²: c = (-1/2, 2/3, -1/4)
  // The moment on the left, as the lecture writes them, or dividing the right side; numbers too.
  for (const std::string written :
       {"I₁ω̇₁ = (I₂ − I₃)ω₂ω₃, I₂ω̇₂ = (I₃ − I₁)ω₃ω₁, I₃ω̇₃ = (I₁ − I₂)ω₁ω₂",
        "I_1 dω₁/dt = (I_2 - I_3) ω₂ ω₃; I_2 dω₂/dt = (I_3 - I_1) ω₃ ω₁; I_3 dω₃/dt = (I_1 - I_2) "
        "ω₁ ω₂",
        "ω̇₁ = (I₂ − I₃)ω₂ω₃/I₁, ω̇₂ = (I₃ − I₁) ω₃ ω₁ / I₂, ω̇₃ = (I₁ − I₂)/I₃ ω₁ω₂",
        "2 dω₁/dt = -ω₂ω₃, 3 dω₂/dt = 2 ω₃ω₁, 4 dω₃/dt = -ω₁ω₂",
        "I_1\\dot\\omega_1 = (I_2 - I_3)\\,\\omega_2\\omega_3,\\ I_2\\dot\\omega_2 = (I_3 - "
        "I_1)\\,\\omega_3\\omega_1,\\ I_3\\dot\\omega_3 = (I_1 - I_2)\\,\\omega_1\\omega_2"}) {
    INFO(written);
    const auto v = top.check("euler_coefficients", written);
    REQUIRE(v.correct);
    REQUIRE_THAT(v.feedback.back(),
                 Catch::StartsWith("read as the coefficients of Euler's equations"));
  }
  // The moments' difference turned in the first equation: c₁ has the wrong sign, said so.
  const auto turned = top.check("euler_coefficients",
                                "I₁ω̇₁ = (I₃ − I₂)ω₂ω₃, I₂ω̇₂ = (I₃ − I₁)ω₃ω₁, I₃ω̇₃ = (I₁ − I₂)ω₁ω₂");
  REQUIRE_FALSE(turned.correct);
  REQUIRE(turned.feedback.at(0) == "c₁ has the wrong sign");
  // A component of ω on the left, or a derivative on the right, is no such equation, and is
  // refused as unreadable.
  for (const std::string other :
       {"ω₁ ω̇₁ = ω₂ω₃, ω̇₂ = ω₃ω₁, ω̇₃ = ω₁ω₂", "ω̇₁ = ω̇₂ ω₃, ω̇₂ = ω₃ω₁, ω̇₃ = ω₁ω₂"}) {
    INFO(other);
    REQUIRE_THROWS_AS(top.check("euler_coefficients", other), InputError);
  }
}

TEST_CASE(
    "Euler's equations and labelled entries in the moments the steps write read as the key's") {
  // The racket's moments are no symbols: its steps write I₁ dω₁/dt = (I₂ − I₃) ω₂ ω₃; pasted
  // back, or the coefficients labelled in them, they read with the key's moments, said so.
  const Fixture racket("tennis-racket");
  const std::string moments = "read with I1 = m·(b² + c²)/12 (the principal moment about e₁)";
  for (const std::string written :
       {"I₁ dω₁/dt = (I₂ − I₃) ω₂ ω₃, I₂ dω₂/dt = (I₃ − I₁) ω₃ ω₁, I₃ dω₃/dt = (I₁ − I₂) ω₁ ω₂",
        "c₁ = (I₂ − I₃)/I₁, c₂ = (I₃ − I₁)/I₂, c₃ = (I₁ − I₂)/I₃"}) {
    INFO(written);
    const auto v = racket.check("euler_coefficients", written);
    REQUIRE(v.correct);
    REQUIRE_THAT(v.feedback.front(), Catch::StartsWith(moments));
  }
  // Read so, a turned difference is still wrong, and the sign is said.
  const auto turned = racket.check(
      "euler_coefficients", "I₁ω̇₁ = (I₃ − I₂)ω₂ω₃, I₂ω̇₂ = (I₃ − I₁)ω₃ω₁, I₃ω̇₃ = (I₁ − I₂)ω₁ω₂");
  REQUIRE_FALSE(turned.correct);
  REQUIRE(turned.feedback.at(0) == "c₁ has the wrong sign");
}

TEST_CASE("a comparison at the top level is found once, its sides and its sense") {
  const auto q = check::inequality_of("ω₃ ≥ 118.8 rad/s");
  REQUIRE(q);
  CHECK(q->left == "ω₃");
  CHECK(q->right == "118.8 rad/s");
  CHECK(q->left_greater);
  const auto latex = check::inequality_of("\\theta \\le \\left(\\frac{\\pi}{4}\\right)");
  REQUIRE(latex);
  CHECK_FALSE(latex->left_greater);
  CHECK(latex->right == "\\left(\\frac{\\pi}{4}\\right)");  // \left is no \le
  CHECK(check::inequality_of("0.5 <= θ")->sign == "<=");
  // An angle-bracket vector, a chain, a comparison inside brackets, a side missing: none.
  for (const std::string none :
       {"<1, 2, 3>", "0 < θ < 1", "f(a > b)", "≥ 118.8", "\\left(1\\right)"}) {
    INFO(none);
    CHECK_FALSE(check::inequality_of(none));
  }
}

TEST_CASE("a least or greatest value given as its inequality is judged by its bound and sense") {
  const Fixture top("heavy-top");
  const std::string least = fmt::format("{:.6g} rad/s", top.answer("omega3_min").value.data[0]);
  const std::string most = fmt::format("{:.6g} rad", top.answer("theta_max").value.data[0]);
  // The bound on either side, in Unicode, ASCII or LaTeX, strict or not.
  for (const std::string& right :
       {"ω₃ ≥ " + least, "omega3 > " + least, least + " <= ω₃", "\\omega_3 \\geq " + least}) {
    INFO(right);
    const auto v = top.check("omega3_min", right);
    REQUIRE(v.correct);
    REQUIRE_THAT(v.feedback.back(), Catch::StartsWith("read as omega3_min = " + least));
  }
  REQUIRE(top.check("theta_max", "θ ≤ " + most).correct);
  REQUIRE(top.check("theta_min", "θ ≥ θ₀").correct);  // the start is the least tilt, exactly
  // The sense turned: wrong, and said whether the bound itself would be right.
  const auto turned = top.check("omega3_min", "ω₃ ≤ " + least);
  REQUIRE_FALSE(turned.correct);
  REQUIRE(turned.line == "incorrect: omega3_min: your inequality points the wrong way");
  REQUIRE(turned.feedback ==
          std::vector<std::string>{"omega3_min is a least value: ω₃ ≥ omega3_min",
                                   "the bound itself would be right"});
  REQUIRE(top.check("theta_max", "θ ≥ 1 rad").feedback.back() ==
          "and the bound itself is not right either");
  // A wrong bound in the right sense is judged as any wrong value is.
  const auto low = top.check("omega3_min", "ω₃ ≥ 100 rad/s");
  REQUIRE_FALSE(low.correct);
  REQUIRE_THAT(low.feedback.at(0), Catch::Contains("off by"));
  // No bound, no inequality: the first time the largest angle is reached is no greatest value.
  const Fixture plate("flying-plate");
  REQUIRE(plate.answer("max_angle").bound == AnswerBound::upper);
  REQUIRE(plate.answer("t_max").bound == AnswerBound::none);
  REQUIRE_THROWS_AS(plate.check("t_max", "t ≤ 0.1612 s"), InputError);
  REQUIRE(plate.check("max_angle", "∠(z, e₃) ≤ 15.26°").correct);
}

TEST_CASE("a value given in units of an expression is that expression times it") {
  const Fixture cube("four-masses");  // moments (5/2, 3, 7/2) m a², I = m a² [[3, -1/2, 0], ..]
  for (const char* same : {"λ = 2.5, 3, 3.5 (in units of ma²)", "2.5, 3, 3.5 in units of m a^2",
                           "(2.5, 3, 3.5) (In units of m*a^2)", "[2.5 3 3.5] in units of ma^2",
                           "λ = 2.5, 3, 3.5 (× ma²)", "2.5, 3, 3.5 (times m a^2)",
                           "2.5, 3, 3.5 (all × ma²)", "2.5, 3, 3.5 (in ma^2)"}) {
    INFO(same);
    const auto v = cube.check("principal_moments", same);
    REQUIRE(v.correct);
    REQUIRE_THAT(v.line, Catch::Contains("simplifies to the key's"));
  }
  REQUIRE(cube.check("I", "[[3, -0.5, 0], [-0.5, 3, 0], [0, 0, 3]] (in units of ma²)").correct);
  REQUIRE_FALSE(cube.check("principal_moments", "2.5, 3, 3.6 (in units of ma²)").correct);
  const Fixture top("heavy-top");  // E = 7.371 J
  REQUIRE(top.check("energy", "0.07371 (in units of 100 J)").correct);
  CHECK(check::in_units_of_written("x = 1, 2 (in units of m a^2)") == "x = (1, 2) m a^2");
  CHECK(check::in_units_of_written("2.5 (about the axis)") == "2.5 (about the axis)");
  // A value with its unit already: the words are a remark.
  CHECK(check::in_units_of_written("303.6 days (in units of days)") == "303.6 days");
  REQUIRE(top.check("energy", "7.371 J (in units of J)").correct);
  // "(in SI)": a bare number is read in the key's unit, which is SI; the words are a remark.
  REQUIRE(cube.check("principal_moments", "2.5, 3, 3.5 (in SI)").correct);
  REQUIRE_FALSE(cube.check("principal_moments", "2.5, 3, 3.6 (in SI units)").correct);
  REQUIRE(top.check("energy", "7.371 (in J)").correct);
  // Only in brackets is "times" or "×" the words of a unit: "2.5 × 10" stays a product.
  CHECK(check::in_units_of_written("2.5 times m a^2") == "2.5 times m a^2");
}

TEST_CASE("a range, as the nutation's limits are written, gives each bound its end") {
  const Fixture top("heavy-top");
  const auto degrees = [&](const std::string& name) {
    return fmt::format("{:.6g}°", top.answer(name).value.data[0] * 180 / kPi);
  };
  const std::string low = degrees("theta_min"), high = degrees("theta_max");
  for (const std::string& range :
       {low + " ≤ θ ≤ " + high, high + " ≥ θ ≥ " + low, low + " < theta < " + high,
        "θ₀ ≤ θ ≤ " + high, "\\theta_0 \\le \\theta \\le " + high,
        // An interval, closed or open.
        "θ ∈ [" + low + ", " + high + "]", "theta in (" + low + ", " + high + ")"}) {
    INFO(range);
    const auto most = top.check("theta_max", range);
    REQUIRE(most.correct);
    REQUIRE_THAT(most.feedback.back(), Catch::StartsWith("read as theta_max = " + high +
                                                         ", the upper end of your range") &&
                                           Catch::EndsWith("not judged here: it is theta_min's"));
    const auto least = top.check("theta_min", range);
    REQUIRE(least.correct);
    REQUIRE_THAT(least.feedback.back(), Catch::Contains("the lower end of your range"));
  }
  // An interval's unit after it is each end's.
  const std::string in_radians =
      fmt::format("θ ∈ [{:.6g}, {:.6g}] rad", top.answer("theta_min").value.data[0],
                  top.answer("theta_max").value.data[0]);
  const auto radians = top.check("theta_max", in_radians);
  REQUIRE(radians.correct);
  REQUIRE_THAT(radians.feedback.back(), Catch::Contains(" rad (its lower end) not judged here"));
  // Each end is judged for its own answer: a wrong upper end is wrong for theta_max only.
  const std::string too_high = low + " ≤ θ ≤ 50°";
  REQUIRE_FALSE(top.check("theta_max", too_high).correct);
  REQUIRE(top.check("theta_min", too_high).correct);
  // Without a name, part (b) takes a range for its first bound, theta_min.
  const check::Context ctx{top.key, top.table, top.values};
  REQUIRE(check::answer_meant(ctx, "b", low + " ≤ θ ≤ " + high, {}) == "theta_min");
  // An answer that is no bound takes no inequality or range, and is told so; an arrow is none.
  for (const char* compared : {"E < 8 J", "7 J < E < 8 J", "E ≤ 8 J"}) {
    INFO(compared);
    REQUIRE_THROWS_WITH(top.check("energy", compared),
                        Catch::Contains("energy is a value, not a bound"));
  }
  // "E -> 8 J", a Mathematica rule, is the equation E = 8 J: judged, and wrong.
  const auto rule = top.check("energy", "E -> 8 J");
  REQUIRE_FALSE(rule.correct);
  REQUIRE_THAT(rule.feedback.at(0), Catch::Contains("off by"));
  CHECK_FALSE(check::inequality_of("E -> 8"));
  // Two comparisons that point both ways are no range: a bound so written is told how a range
  // is written, in its own ends.
  REQUIRE_THROWS_WITH(top.check("theta_max", "30° ≤ θ ≥ 44.7°"),
                      Catch::Contains("the signs of your range point both ways") &&
                          Catch::Contains("30° ≤ θ ≤ 44.7°"));
  CHECK(check::range_both_ways("1 ≥ θ ≤ 2") == "1 ≥ θ ≥ 2");
  CHECK_FALSE(check::range_both_ways("1 ≤ θ ≤ 2"));
  REQUIRE_THROWS_WITH(top.check("energy", "E ∈ [7, 8] J"),
                      Catch::Contains("energy is a value, not a bound"));
  CHECK_FALSE(check::range_of("θ ∈ [1]"));
  CHECK_FALSE(check::range_of("θ ∈ [1, 2, 3]"));
  CHECK_FALSE(check::range_of("∈ [1, 2]"));
  CHECK_FALSE(check::range_of("1 ≤ θ ≥ 2"));
  CHECK_FALSE(check::range_of("1 ≤ θ ≤ 2 ≤ 3"));
  CHECK_FALSE(check::range_of("θ ≤ 2"));
}

TEST_CASE("every closed form one part in a million off is wrong, however small its value in SI") {
  // An expression is held to 1e-9 of the answer's size: the key's own form times (1 + 1e-6) is
  // no identity at any size, the Earth's 2.4e-7 rad/s as the top's 150 rad/s.
  int judged = 0;
  double smallest = 1.0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.symbolic.empty() || a.value.shape != Value::Shape::scalar) continue;
        if (a.value.data.at(0) == 0.0) continue;  // zero times anything is the key's zero
        const std::string off = "(" + a.symbolic + ")*(1 + 1/1000000)";
        INFO(p.id << " " << a.name << ": " << off);
        REQUIRE_FALSE(f.check(a.name, off).correct);
        REQUIRE(f.check(a.name, "(" + a.symbolic + ")*(1 + 0)").correct);
        smallest = std::min(smallest, std::abs(a.value.data.at(0)));
        ++judged;
      }
    }
  }
  REQUIRE(judged >= 60);
  REQUIRE(smallest < 1e-6);  // the Earth's rates are in the catalog
}

TEST_CASE("principal moments given as the diagonal tensor are read as its diagonal") {
  int judged = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.kind != AnswerKind::principal_moments) continue;
        const auto& m = a.value.data;  // ascending
        const std::string diagonal =
            fmt::format("diag({:.6g}, {:.6g}, {:.6g})", m.at(2), m.at(0), m.at(1));
        INFO(p.id << " " << a.name << ": " << diagonal);
        const auto v = f.check(a.name, diagonal);
        REQUIRE(v.correct);
        REQUIRE(v.feedback.back() ==
                "read as the moments on its diagonal (the tensor in its principal axes)");
        ++judged;
      }
    }
  }
  REQUIRE(judged >= 5);
  const Fixture cone("solid-cone");  // in the symbols too
  REQUIRE(cone.check("principal_moments_cm", "diag(3M(4R² + h²)/80, 3M(4R² + h²)/80, 3M R²/10)")
              .correct);
  // A matrix with something off its diagonal is refused, saying the moments are its eigenvalues.
  const Fixture box("box-corner");
  REQUIRE_THROWS_WITH(box.check("principal_moments_corner", box.answer("I_corner").symbolic),
                      Catch::Contains("the principal moments are this matrix's eigenvalues") &&
                          !Catch::Contains("decimal comma"));
}

TEST_CASE("a diagonal tensor given as its three diagonal entries is told how to write it") {
  int judged = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        const auto& m = a.value.data;
        if (a.value.shape != wobble::Value::Shape::matrix || m.size() != 9) continue;
        bool diagonal = true;
        for (std::size_t i = 0; i < 9; ++i) diagonal = diagonal && (i % 4 == 0 || m[i] == 0.0);
        const std::string entries = fmt::format("{:.6g}, {:.6g}, {:.6g}", m[0], m[4], m[8]);
        const std::string unit = a.unit.empty() ? "" : " " + a.unit;
        for (const std::string& typed :
             {entries, "(" + entries + ")" + unit, entries + unit, "[" + entries + "]"}) {
          INFO(p.id << " " << a.name << ": " << typed);
          std::string said;
          try {
            (void)f.check(a.name, typed);
          } catch (const wobble::InputError& e) {
            said = e.what();
          }
          REQUIRE_THAT(said, Catch::Contains("wants a 3x3 matrix"));
          const std::size_t from = said.find("write diag("), to = said.find("; three entries");
          if (!diagonal) {  // the tensor has products of inertia: its diagonal is not it
            REQUIRE(from == std::string::npos);
            continue;
          }
          REQUIRE(from != std::string::npos);
          REQUIRE(to != std::string::npos);
          // What it says to write is read back and judged right.
          const std::string suggested = said.substr(from + 6, to - from - 6);
          INFO(suggested);
          REQUIRE(f.check(a.name, suggested).correct);
          ++judged;
        }
      }
    }
  }
  REQUIRE(judged >= 8);  // the cone's two tensors at least, four ways each
  // A bracket around one entry only is no bracket around the diagonal: no line to write.
  const Fixture cone("solid-cone");
  REQUIRE_THROWS_WITH(cone.check("I_apex", "(0.111), 0.111, 0.006"),
                      Catch::Contains("wants a 3x3 matrix") && !Catch::Contains("diag("));
}

TEST_CASE(
    "an answer restated in a bracket after it is judged twice, the bracket a remark only "
    "where no value reads from it") {
  const Fixture top("heavy-top");
  const double least_rad_s = top.answer("omega3_min").value.data[0];
  const std::string least = fmt::format("{:.6g} rad/s", least_rad_s);
  // The same spin in turns per minute: rad/s x 60 / (2 pi).
  const std::string rpm = fmt::format("{:.4g} rpm", least_rad_s * 60 / (2 * M_PI));
  for (const std::string& right : {least + " (about " + rpm + ")", least + " (≈ " + rpm + ")",
                                   least + " (i.e. " + rpm + ")", least + " (= " + rpm + ")"}) {
    INFO(right);
    const auto v = top.check("omega3_min", right);
    REQUIRE(v.correct);
    REQUIRE(v.feedback.empty());
  }
  // The restatement wrong: wrong, and said to be the bracket's.
  const auto wrong = top.check("omega3_min", least + " (about 2000 rpm)");
  REQUIRE_FALSE(wrong.correct);
  REQUIRE(wrong.feedback.at(0) == "your bracket \"(about 2000 rpm)\" gives another value");
  // The answer wrong: wrong whatever the bracket says.
  REQUIRE_FALSE(top.check("omega3_min", "200 rad/s (about " + rpm + ")").correct);
  // A bracket that reads as no value is a remark, said not to be judged.
  const auto remark = top.check("omega3_min", least + " (about 1134 turns a minute)");
  REQUIRE(remark.correct);
  REQUIRE(remark.feedback.back() ==
          "your bracket \"(about 1134 turns a minute)\" is taken as a remark, not judged");
  // Two brackets: one is asked for, nothing judged.
  REQUIRE_THROWS_WITH(top.check("omega3_min", least + " (≈ " + rpm + ") (= 19 Hz)"),
                      "--answer: (≈ " + rpm +
                          ") and (= 19 Hz): the answer again in one bracket, "
                          "not two");
  // Words only stay a remark; a product stays a product.
  REQUIRE(top.check("omega3_min", least + " (about the vertical)").correct);
  REQUIRE_FALSE(wobble::check::restatement_of("2 (m R)").has_value());
  REQUIRE_FALSE(wobble::check::restatement_of("2 (about m R)").has_value());
}

TEST_CASE("a derivative on a right side of Euler's equations is named, not another symbol") {
  // The asymmetric top writes ω's components w1, w2, w3: the hint is about ω̇₂, the name the
  // reader could not read, not about the ω₃ beside it.
  const Fixture top("asymmetric-top");
  for (const std::string& typed :
       {std::string("ω̇₁ = ω̇₂ ω₃, ω̇₂ = ω₃ ω₁, ω̇₃ = ω₁ ω₂"),
        std::string("dw1/dt = w2dot w3, dw2/dt = w3 w1, dw3/dt = w1 w2")}) {
    INFO(typed);
    REQUIRE_THROWS_WITH(top.check("euler_coefficients", typed),
                        Catch::Contains("(dω₂/dt is no symbol here: in Euler's equations each "
                                        "right side is a coefficient times the other two "
                                        "components, dω₁/dt = c₁ ω₂ ω₃)") &&
                            !Catch::Contains("omega3"));
  }
}

TEST_CASE(
    "a power of ten whose superscript was lost is read as written, and said, over the catalog") {
  // "7.2 × 10−4" as a PDF copies 10⁻⁴, "7.2*10-4" as typed: 7.2 × (10 − 4) to the reader. The
  // verdict stays what was written, and says what the power would give: every scalar answer
  // below 1 (its value in SI, the key's unit), at 10 significant figures, right, and 5% off.
  std::size_t tried = 0;
  for (const auto& p : load_catalog()) {
    const Fixture f(p.id);
    for (const auto& part : f.key.parts) {
      for (const auto& a : part.answers) {
        if (a.value.shape != Value::Shape::scalar) continue;
        const double v = a.value.data[0];
        if (v == 0.0 || std::abs(v) >= 1.0) continue;
        const int exponent = static_cast<int>(std::floor(std::log10(std::abs(v))));
        const double mantissa = v / std::pow(10.0, exponent);
        for (const char* times : {" × ", "*", " x ", "·"}) {
          for (const char* minus : {"−", "-"}) {
            const std::string lost = fmt::format("10{}{}", minus, -exponent);
            const std::string typed = fmt::format("{:.10g}{}{} {}", mantissa, times, lost, a.unit);
            INFO(p.id << " " << a.name << ": " << typed);
            const auto said =
                fmt::format("\"{}\" reads as 10 − {} = {}, not 10", lost, -exponent, 10 + exponent);
            // The letter x reads as times only before a power ("x 10^-4"): refused, with how
            // the power is written.
            if (std::string_view(times) == " x ") {
              REQUIRE_THROWS_WITH(
                  f.check(a.name, typed),
                  Catch::Contains(said) &&
                      Catch::Contains(fmt::format(": write 10^-{}, as in \"", -exponent)));
              ++tried;
              continue;
            }
            const auto v_typed = f.check(a.name, typed);
            REQUIRE_FALSE(v_typed.correct);
            REQUIRE(v_typed.feedback.size() == 1);
            REQUIRE_THAT(v_typed.feedback[0],
                         Catch::StartsWith(said) &&
                             Catch::EndsWith(
                                 fmt::format("; written 10^-{}, your answer is right", -exponent)));
            // 5% off: the power said, how far off the number as written is after it.
            const auto wrong = f.check(
                a.name, fmt::format("{:.10g}{}{} {}", 1.05 * mantissa, times, lost, a.unit));
            REQUIRE_FALSE(wrong.correct);
            REQUIRE(wrong.feedback.size() >= 2);
            REQUIRE_THAT(wrong.feedback[0], Catch::EndsWith(fmt::format(
                                                "; a power of ten is written 10^-{}", -exponent)));
            ++tried;
          }
        }
      }
    }
  }
  REQUIRE(tried > 100);
}

TEST_CASE("a lost power of ten only after a number's times sign, whole and then an exponent") {
  using check::lost_powers_of_ten;
  const auto flying = lost_powers_of_ten("[1.86*10-3, 0, 1.39 × 10−2] kg m^2/s");
  REQUIRE(flying.has_value());
  CHECK(flying->as_powers == "[1.86*10^-3, 0, 1.39 × 10^-2] kg m^2/s");
  CHECK(flying->written == "10-3");
  CHECK(flying->exponent == "3");
  CHECK(lost_powers_of_ten("7.2 x 10–4")->as_powers == "7.2 x 10^-4");
  // Each reads as the difference it writes, or is no power of ten at all.
  for (const char* difference :
       {"7.2 × 10 − 4", "7.2*710-4", "7.2*1.10-4", "7.2*10-4.5", "7.2*10-4^2", "m*10-4", "10-4",
        "7.2*10-1234", "7.2e-4", "7.2*10^-4", "x*10-4"}) {
    INFO(difference);
    CHECK_FALSE(lost_powers_of_ten(difference).has_value());
  }
  // A refusal that the power would read names it, and how to write it.
  const Fixture plate("flying-plate");
  REQUIRE_THROWS_WITH(plate.check("I0", "7.2 x 10-4 kg m^2"),
                      "--answer: \"10-4\" reads as 10 − 4 = 6, not 10⁻⁴: write 10^-4, as in "
                      "\"7.2 x 10^-4 kg m^2\"");
}

TEST_CASE("a list in words: 'and' before its last item is a comma, in LaTeX's \\text{ and } too") {
  for (const auto& [typed, read] : std::vector<std::pair<std::string, std::string>>{
           {"0.569, 4.209 and 4.556 kg m^2", "0.569, 4.209, 4.556 kg m^2"},
           {"0.569, 4.209, and 4.556", "0.569, 4.209, 4.556"},
           {"x = 1 AND y = 2", "x = 1, y = 2"},
           {"(1 and 2)", "(1, 2)"},
           {"band and", "band and"},  // no word with a space after it
           {"a and", "a and"},
           {"sandy andes", "sandy andes"},
           // LaTeX's word in text, with its spacing; a bare "and" in LaTeX is a symbol's name.
           {"1 \\text{ and } 2", "1, 2"},
           {"x = 1,\\quad\\text{and}\\quad y = 2", "x = 1, y = 2"},
           {"1~\\mathrm{and}~2 \\text{ rad}", "1, 2 \\text{ rad}"},
           {"\\frac{1}{2} and 3", "\\frac{1}{2} and 3"}}) {
    INFO(typed);
    CHECK(wobble::check::and_as_comma(typed) == read);
  }
}
