// The heavy symmetric top's closed forms against an independent integration of Lagrange's
// equations (Boost.Odeint): the nutation limits, steady precession.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "core/heavy_top.hpp"
#include "heavy_top_lagrange.hpp"

using namespace wobble;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
using namespace wobble::testing;
using State = LagrangeState;
using Stepper = LagrangeStepper;
using Checker = LagrangeChecker;

// theta at every turning point (thetadot = 0) in [0, t_end]: found by bisection on the time,
// integrating again from the last sample each time.
std::vector<double> turning_thetas(const Lagrange& sys, State x, double t_end) {
  Stepper stepper(Checker(1e-14, 1e-14));
  std::vector<double> out;
  const double dt = 1e-3;
  for (double t = 0; t < t_end; t += dt) {
    State next = x;
    ode::integrate_adaptive(stepper, sys, next, t, t + dt, 1e-5);
    if (x[1] != 0.0 && (x[1] > 0) != (next[1] > 0)) {
      double lo = 0, hi = dt;
      State at = x;
      for (int i = 0; i < 40; ++i) {
        const double mid = 0.5 * (lo + hi);
        at = x;
        ode::integrate_adaptive(stepper, sys, at, 0.0, mid, 1e-5);
        ((at[1] > 0) == (x[1] > 0) ? lo : hi) = mid;
      }
      out.push_back(at[0]);
    }
    x = next;
  }
  return out;
}
}  // namespace

TEST_CASE("heavy top: nutation limits are the turning points of an integration") {
  for (const auto& s : kHeavyTopStarts) {
    const HeavyTopConstants k = heavy_top_constants(kTop, s);
    const Nutation n = nutation_limits(kTop, s);
    INFO("theta0 " << s.theta << " thetadot0 " << s.thetadot << " phidot0 " << s.phidot);
    REQUIRE(n.theta_min <= s.theta + 1e-15);
    REQUIRE(n.theta_max >= s.theta - 1e-15);
    const Lagrange sys{kTop, k.p_phi, k.p_psi};
    const auto thetas = turning_thetas(sys, {s.theta, s.thetadot, 0.0, 0.0}, 1.5);
    REQUIRE(thetas.size() >= 2);
    // Both runs are controlled to 1e-14 per step; over ~1500 steps the turning angles agree to
    // 1e-9 rad (measured: 6.3e-14). A turning angle is a minimum or a maximum.
    for (const double th : thetas) {
      const double nearest =
          std::abs(th - n.theta_min) < std::abs(th - n.theta_max) ? n.theta_min : n.theta_max;
      REQUIRE_THAT(th, WithinAbs(nearest, 1e-9));
    }
  }
}

TEST_CASE("heavy top: started at the steady precession rate, it precesses steadily") {
  const double theta = 0.7, w3 = 150;
  const auto rates = steady_precession(kTop, theta, w3);
  REQUIRE(rates.has_value());
  // Both roots satisfy I1 cos phidot^2 - I3 w3 phidot + M g l = 0 to rounding of its terms.
  const double Mgl = kTop.M_kg * kTop.g_m_s2 * kTop.l_m, c = std::cos(theta);
  for (const double r : {rates->slow, rates->fast}) {
    const double scale = kTop.I3_kgm2 * std::abs(w3 * r);
    REQUIRE_THAT(kTop.I1_kgm2 * c * r * r - kTop.I3_kgm2 * w3 * r + Mgl,
                 WithinAbs(0.0, 8 * std::numeric_limits<double>::epsilon() * scale));
  }
  for (const double phidot : {rates->slow, rates->fast}) {
    const HeavyTopStart s{theta, 0.0, phidot, w3 - phidot * c};
    const HeavyTopConstants k = heavy_top_constants(kTop, s);
    const Nutation n = nutation_limits(kTop, s);
    // A double root: the two limits coincide to about sqrt(eps) (a double root's condition).
    REQUIRE_THAT(n.theta_max - n.theta_min, WithinAbs(0.0, 1e-7));
    State x{theta, 0.0, 0.0, 0.0};
    Stepper stepper(Checker(1e-14, 1e-14));
    ode::integrate_adaptive(stepper, Lagrange{kTop, k.p_phi, k.p_psi}, x, 0.0, 0.5, 1e-5);
    REQUIRE_THAT(x[0], WithinAbs(theta, 1e-9));
    REQUIRE_THAT(x[2], WithinRel(phidot * 0.5, 1e-9));
  }
  // Too slow a spin: no steady precession above the horizontal; below it always one pair.
  const double w_min = 2 * std::sqrt(kTop.I1_kgm2 * Mgl * c) / kTop.I3_kgm2;
  REQUIRE_FALSE(steady_precession(kTop, theta, 0.999 * w_min).has_value());
  REQUIRE(steady_precession(kTop, theta, 1.001 * w_min).has_value());
  REQUIRE(steady_precession(kTop, 2.0, 1.0).has_value());
  // Horizontal (cos(pi/2) rounds to 6e-17): the fast precession runs away, the slow is M g l/p
  // up to the true correction I1 M g l cos / p^2 of that cosine (2e-15 here) and rounding.
  const auto flat = steady_precession(kTop, M_PI / 2, 10.0);
  REQUIRE(flat->fast > 1e12 * flat->slow);
  const double p = kTop.I3_kgm2 * 10.0;
  const double shift = kTop.I1_kgm2 * Mgl * std::abs(std::cos(M_PI / 2)) / (p * p);
  REQUIRE_THAT(flat->slow, WithinRel(Mgl / p, shift + 8 * std::numeric_limits<double>::epsilon()));
}

TEST_CASE("heavy top: a vertical start has no nutation limits, bad tops are refused") {
  REQUIRE_THROWS_AS(nutation_limits(kTop, {0.0, 0.0, 0.0, 100}), std::invalid_argument);
  HeavyTop bad = kTop;
  bad.l_m = -0.1;
  REQUIRE_THROWS_AS(heavy_top_constants(bad, {0.5, 0, 0, 10}), std::invalid_argument);
}
