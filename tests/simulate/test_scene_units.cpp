// A scene's quantities with units of their own ("1500 ms", "1432 rpm", "30°", "8 cm"), read as
// exactly as the same value written in SI; a unit of the wrong dimension, or a word that is no
// unit, refused with the field named.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "core/input_error.hpp"
#include "problem/scene.hpp"
#include "simulate/scene_setup.hpp"

using namespace wobble;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinULP;

namespace {
// The heavy-top scene (parameters M, R, g, l, theta0, ...) with one field changed.
template <class Change>
SceneSetup heavy_top_with(const Change& change) {
  Scene scene = find_scene("heavy-top");
  change(scene);
  return setup_scene(scene, {});
}

template <class Change>
std::string refusal(const Change& change) {
  try {
    (void)heavy_top_with(change);
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("accepted");
  return "";
}
}  // namespace

TEST_CASE("a scene's time, rate, angle, length and acceleration read with units, rounded once") {
  // Each converted value is the double nearest the exact one, as the SI expression gives it:
  // the unit's factor multiplies the value symbolically before one rounding.
  CHECK(heavy_top_with([](Scene& s) { s.t_end = "1500 ms"; }).t_end == 1.5);
  CHECK(heavy_top_with([](Scene& s) { s.t_end = "0.5 min"; }).t_end == 30.0);
  CHECK(heavy_top_with([](Scene& s) { s.t_end = "2 [s]"; }).t_end == 2.0);
  CHECK(heavy_top_with([](Scene& s) { s.t_end = "2s"; }).t_end == 2.0);
  CHECK(heavy_top_with([](Scene& s) { s.t_end = "π/2"; }).t_end == std::numbers::pi / 2);
  CHECK(heavy_top_with([](Scene& s) { s.step = "1 ms"; }).step == 0.001);
  CHECK(heavy_top_with([](Scene& s) { s.gravity->g = "981 cm/s²"; }).model.g_S.z() == -9.81);
  CHECK(heavy_top_with([](Scene& s) {
          s.gravity->pivot = {"0", "0", "-8 mm"};
        }).turning_point_B.z() == -0.008);

  const auto spin = [](const std::string& text) {
    return heavy_top_with([&](Scene& s) { s.omega = {"0", "0", text}; }).m0_P;
  };
  // rpm counts revolutions: 1432 rpm = 1432 * 2 pi / 60 rad/s; 1/s is rad/s.
  CHECK(spin("1432 rpm") == spin("1432*2*pi/60"));
  CHECK(spin("150 1/s") == spin("150"));
  CHECK(spin("3 Hz") == spin("6*pi"));
  CHECK_THAT(spin("1432 rpm").z() / spin("1").z(), WithinULP(1432 * 2 * std::numbers::pi / 60, 1));

  const auto attitude = [](const std::string& theta) {
    return heavy_top_with([&](Scene& s) { s.orientation.euler = {"0", theta, "0"}; }).q0_BtoS;
  };
  for (const std::string degrees : {"30deg", "30°", "30 deg", "(90 - 60) deg", "1/12 rev"}) {
    INFO(degrees);
    CHECK(attitude(degrees).coeffs() == attitude("pi/6").coeffs());
  }
  CHECK(attitude("0.5235987755982988 rad").coeffs() == attitude("0.5235987755982988").coeffs());
}

TEST_CASE("a scene's parameter named like a unit stays the parameter in an expression") {
  // The heavy top's g is a parameter (9.81 m/s^2), and g is also the gram: "1*g" is the
  // parameter, "9.81 m/s^2" a value with a unit, "2 R" (R a parameter) a product without '*'.
  CHECK(heavy_top_with([](Scene& s) { s.gravity->g = "1*g"; }).model.g_S.z() == -9.81);
  CHECK_THAT(refusal([](Scene& s) { s.t_end = "2 R"; }), Contains("products need '*'"));
}

TEST_CASE("a scene's unit of the wrong dimension, or a word that is no unit, is refused") {
  CHECK_THAT(refusal([](Scene& s) { s.t_end = "2 m"; }),
             Contains("run.t_end: '2 m' is in m (length); it must be in s (time)"));
  CHECK_THAT(refusal([](Scene& s) {
               s.omega = {"0", "0", "3 m/s"};
             }),
             Contains("initial.omega[2]: '3 m/s' is in m/s"));
  CHECK_THAT(refusal([](Scene& s) {
               s.orientation.euler = {"0", "2 s", "0"};
             }),
             Contains("initial.euler[1]: '2 s' is in s (time); it must be an angle"));
  // Beyond a turn: degrees written as a bare number, which is radians.
  CHECK_THAT(refusal([](Scene& s) {
               s.orientation.euler = {"0", "30", "0"};
             }),
             Contains("initial.euler[1]: \"30\" is 30 rad, more than a turn; a bare number is in "
                      "radians: for degrees write \"30deg\""));
  CHECK_THAT(refusal([](Scene& s) {
               s.orientation.euler = {"0", "0", "-370 deg"};
             }),
             Contains("initial.euler[2]: \"-370 deg\" is -6.457718232 rad, more than a turn; "
                      "give the angle within one"));
  CHECK_NOTHROW(heavy_top_with([](Scene& s) { s.orientation.euler = {"2*pi", "1", "-2*pi"}; }));
  CHECK_THAT(refusal([](Scene& s) {
               s.gravity->pivot = {"0", "0", "5 kg"};
             }),
             Contains("effects.gravity.pivot[2]: '5 kg' is in kg (mass); it must be in m"));
  CHECK_THAT(refusal([](Scene& s) { s.t_end = "2 parsecs"; }),
             Contains("run.t_end: cannot read the unit 'parsecs'"));
  CHECK_THAT(refusal([](Scene& s) { s.t_end = "-2 s"; }), Contains("it must be finite and > 0"));
  // A quaternion's components are pure numbers: an angle unit is no quaternion component.
  CHECK_THAT(
      refusal([](Scene& s) {
        s.orientation.kind = OrientationSpec::Kind::quaternion;
        s.orientation.quaternion = {"1 deg", "0", "0", "0"};
      }),
      Contains("initial.quaternion[0]: '1 deg' is in deg (an angle); it must be a pure number"));
}

TEST_CASE("a scene's body reads units as the problems' bodies do") {
  // The heavy top's disc: M = 0.5 kg, R = 0.05 m, its centre l = 0.08 m up the axle.
  const SceneSetup si = heavy_top_with([](Scene& s) {
    auto& disc = s.model.body.shapes.at(0);
    disc.mass = "0.5";
    disc.sizes = {"0.05"};
    disc.center = {"0", "0", "0.08"};
  });
  const SceneSetup units = heavy_top_with([](Scene& s) {
    auto& disc = s.model.body.shapes.at(0);
    disc.mass = "500 g";
    disc.sizes = {"5 cm"};
    disc.center = {"0", "0", "80 mm"};
  });
  CHECK(units.mass_kg == si.mass_kg);
  CHECK(units.moments == si.moments);
  CHECK(units.model.d_P_m == si.model.d_P_m);
  CHECK(units.m0_P == si.m0_P);
  CHECK_THAT(refusal([](Scene& s) { s.model.body.shapes.at(0).sizes = {"5 kg"}; }),
             Contains("body.shapes[0].sizes[0]: '5 kg' is in kg (mass); it must be in m"));
}
