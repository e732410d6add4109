// The heavy top's closed form against Lagrange's equations in the Euler angles, integrated by
// Boost.Odeint (a second derivation: no elliptic function, no quaternion), for cusps, waves,
// loops, a start between the limits, a wide slow swing, a hanging start and a sleeping top.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "core/exact_heavy_top.hpp"
#include "core/runge_kutta.hpp"
#include "heavy_top_lagrange.hpp"

using namespace wobble;
using Catch::Matchers::WithinAbs;

namespace {
using namespace wobble::testing;
using State = LagrangeState;
using Stepper = LagrangeStepper;
using Checker = LagrangeChecker;
constexpr double kLagrangeTol = 1e-14;

Quat euler_zyz(double phi, double theta, double psi) {
  return Quat(Eigen::AngleAxisd(phi, Vec3::UnitZ())) * Quat(Eigen::AngleAxisd(theta, Vec3::UnitY())) *
         Quat(Eigen::AngleAxisd(psi, Vec3::UnitZ()));
}

// m_B from the Euler angles and rates (z-y-z): w = (-phidot sin cos psi + thetadot sin psi,
// phidot sin sin psi + thetadot cos psi, phidot cos + psidot).
Vec3 momentum(const HeavyTop& top, double theta, double thetadot, double phidot, double psi,
              double psidot) {
  const double st = std::sin(theta);
  return Vec3(top.I1_kgm2 * (-phidot * st * std::cos(psi) + thetadot * std::sin(psi)),
              top.I1_kgm2 * (phidot * st * std::sin(psi) + thetadot * std::cos(psi)),
              top.I3_kgm2 * (phidot * std::cos(theta) + psidot));
}

double attitude_distance(const Quat& a, const Quat& b) {
  return (a.toRotationMatrix() - b.toRotationMatrix()).norm();
}
}  // namespace

TEST_CASE("exact heavy top: the closed form follows Lagrange's equations") {
  constexpr double kT = 1.5;
  for (const auto& s : kHeavyTopStarts) {
    INFO("theta0 " << s.theta << " thetadot0 " << s.thetadot << " phidot0 " << s.phidot);
    const Vec3 m0 = momentum(kTop, s.theta, s.thetadot, s.phidot, 0.0, s.psidot);
    const ExactHeavyTop exact(kTop, m0, euler_zyz(0.0, s.theta, 0.0));
    const HeavyTopConstants k = heavy_top_constants(kTop, s);
    const Lagrange sys{kTop, k.p_phi, k.p_psi};
    State x{s.theta, s.thetadot, 0.0, 0.0};
    Stepper stepper(Checker(kLagrangeTol, kLagrangeTol));
    double worst_q = 0, worst_m = 0, worst_u = 0, t = 0;
    std::size_t steps = 0;
    for (int i = 1; i <= 30; ++i) {
      const double t_next = kT * i / 30;
      steps += ode::integrate_adaptive(stepper, sys, x, t, t_next, 1e-5);
      t = t_next;
      const FreeBodyState e = exact.at(t);
      const double pd = sys.phidot(x[0]);
      const Vec3 m_ref = momentum(kTop, x[0], x[1], pd, x[3], k.p_psi / kTop.I3_kgm2 - pd * std::cos(x[0]));
      worst_q = std::max(worst_q, attitude_distance(e.q_BtoS, euler_zyz(x[2], x[0], x[3])));
      worst_m = std::max(worst_m, (e.m_B - m_ref).norm() / m0.norm());
      worst_u = std::max(worst_u, std::abs(exact.u_at(t) - std::cos(x[0])));
    }
    // The integration's own error: each step is controlled to kLagrangeTol and the errors add
    // up along the run (no contraction in a conservative flow): steps * tol per angle; three
    // angles' errors add, and a rotation by d is sqrt(2) d away as a matrix: below 5 steps tol.
    // (Measured: at most 0.15 of it.)
    const double bound = 5.0 * static_cast<double>(steps) * kLagrangeTol;
    INFO("steps " << steps << " worst q " << worst_q << " m " << worst_m << " u " << worst_u
                  << " bound " << bound);
    CHECK(worst_q <= bound);
    CHECK(worst_m <= bound);
    CHECK(worst_u <= bound);
    // The nutation stays between its limits and the period is that of u.
    const double P = exact.nutation_period_s();
    REQUIRE(std::isfinite(P));
    const double eps = std::numeric_limits<double>::epsilon();
    for (const double tt : {0.1, 0.37, 1.2}) {
      const double u = exact.u_at(tt);
      CHECK(u >= exact.nutation().u_min - 4 * eps);
      CHECK(u <= exact.nutation().u_max + 4 * eps);
      // One period later u is the same: the phase reduction by 2K agrees with the period.
      CHECK_THAT(exact.u_at(tt + P), WithinAbs(u, 64 * eps * (1.0 + tt / P)));
    }
  }
}

TEST_CASE("exact heavy top: at t = 0 it is its start, a sleeping top spins in place") {
  const HeavyTopStart s{0.8, 0.3, -3, 150};
  const Vec3 m0 = momentum(kTop, s.theta, s.thetadot, s.phidot, 0.0, s.psidot);
  const Quat q0 = euler_zyz(0.4, s.theta, -1.0);
  const ExactHeavyTop exact(kTop, m0, q0);
  REQUIRE(exact.kind() == ExactHeavyTop::Kind::nutating);
  const FreeBodyState at0 = exact.at(0.0);
  const double eps = std::numeric_limits<double>::epsilon();
  CHECK(attitude_distance(at0.q_BtoS, q0) <= 8 * eps);
  CHECK((at0.m_B - m0).norm() <= 64 * eps * m0.norm());
  // Started at rest at a turning point, tilted in a way that leaves its rates a rounding away
  // from zero: the start is still reproduced to rounding, not to sqrt(eps) (the turning point
  // is a root known to eps; the velocity fixes the phase), also 2e-6 rad from hanging down.
  for (const double theta0 : {2.6, M_PI - 2e-6}) {
    const Quat tilted = euler_zyz(0.3, theta0, 1.1);
    const Vec3 spin(0, 0, kTop.I3_kgm2 * 20);
    const ExactHeavyTop rest(kTop, spin, tilted);
    const FreeBodyState s0 = rest.at(0.0);
    INFO("theta0 " << theta0);
    CHECK(attitude_distance(s0.q_BtoS, tilted) <= 8 * eps);
    CHECK((s0.m_B - spin).norm() <= 64 * eps * spin.norm());
  }
  // Sleeping: axis up, spin only; the state turns about the vertical at w3 and nothing else.
  const Vec3 spin(0, 0, kTop.I3_kgm2 * 200);
  const ExactHeavyTop sleeping(kTop, spin, Quat::Identity());
  REQUIRE(sleeping.kind() == ExactHeavyTop::Kind::sleeping);
  const FreeBodyState later = sleeping.at(0.3);
  CHECK(attitude_distance(later.q_BtoS, euler_zyz(0.0, 0.0, 200 * 0.3)) <= 64 * eps * 200 * 0.3);
  CHECK(later.m_B == spin);
  // Vertical and moving: theta is no coordinate there; refused, not guessed.
  REQUIRE_THROWS_AS(ExactHeavyTop(kTop, Vec3(1e-3, 0, 0.1), Quat::Identity()), std::invalid_argument);
}

TEST_CASE("exact heavy top: a top released at rest moves alike forward and backward in time") {
  // Released at rest, the axle is at its upper turning point u2 at t = 0 and u(t) = u(-t). The
  // phase starts at tau0 = K: with K to double-double the reduced phases at t and -t are each
  // other's negatives to double-double, and u at the two times agrees to its own rounding
  // (u1 + du sn^2, |u| <= 1, du <= 2: an eps or two each, 4 eps between them; measured 3 at
  // most). A tau0 rounded to double (F(am tau0) = K in double, off by up to eps K / 2) shifts
  // both phases by that, and u(t) - u(-t) by du (sn^2)' times twice it: measured 7 eps at 0.8
  // rad, 9 at 1e-4 and 12.5 at 1e-8 (K = 20) with it. Near hanging du is small and both agree.
  const double eps = std::numeric_limits<double>::epsilon();
  for (const double theta0 : {1e-8, 1e-4, 0.8, 2.6, M_PI - 2e-6}) {
    const Quat tilted = euler_zyz(0.3, theta0, 1.1);
    const Vec3 spin(0, 0, kTop.I3_kgm2 * 20);
    const ExactHeavyTop rest(kTop, spin, tilted);
    REQUIRE(rest.kind() == ExactHeavyTop::Kind::nutating);
    const double P = rest.nutation_period_s();
    double worst = 0.0;
    for (int i = 1; i <= 40; ++i) {
      const double t = P * i / 7.3;  // through five periods, at phases all round the swing
      worst = std::max(worst, std::abs(rest.u_at(t) - rest.u_at(-t)));
    }
    INFO("theta0 " << theta0 << ": |u(t) - u(-t)| <= " << worst / eps << " eps");
    CHECK(worst <= 4 * eps);
  }
}

TEST_CASE("exact heavy top: through the poles and past them, against the integrated quaternion") {
  // Where the axle passes through the vertical (b = -a: hanging; b = a: upright; a pendulum
  // swinging in a plane, a = b = 0) theta turns back in the Euler angles while the motion goes
  // on, and where it passes near, phi turns by nearly pi within a moment: Lagrange's equations
  // are singular there, so the reference is the body's own equations, the momentum and the
  // attitude quaternion, integrated by Verner's 9(8) (core/runge_kutta), no Euler angle in it.
  struct Start {
    const char* what;
    double theta, thetadot, phidot, psidot;
  };
  const Start starts[] = {
      {"a pendulum swinging through hanging", 0.5, 2.0, 0.0, 0.0},
      {"a pendulum swinging over the top, through both poles", 0.5, 8.0, 0.0, 0.0},
      {"a pendulum released at rest near upright (it falls)", 0.3, 0.0, 0.0, 0.0},
      {"a pendulum started within a rounding of hanging", M_PI, 0.3, 0.0, 0.0},
      {"a top all but spinless, 1.6e-5 rad past hanging", M_PI / 6, 0.0, 0.0, 1e-3},
      {"a top all but spinless, 1.6e-4 rad past hanging", M_PI / 6, 0.0, 0.0, 1e-2},
      {"a top thrown over the top, 2.4e-6 rad past upright, 1.4e-5 past hanging", M_PI / 6, -11.5,
       0.0, 1e-3},
  };
  RigidBodyModel model;
  model.I_P = Vec3(kTop.I1_kgm2, kTop.I1_kgm2, kTop.I3_kgm2);
  model.gravity = true;
  model.mass_kg = kTop.M_kg;
  model.d_P_m = Vec3(0, 0, kTop.l_m);
  model.g_S = Vec3(0, 0, -kTop.g_m_s2);
  // The momentum's error is measured against the swing's: I1 times the pendulum rate.
  const double m_scale = std::sqrt(2 * kTop.M_kg * kTop.g_m_s2 * kTop.l_m * kTop.I1_kgm2);
  constexpr double kTol = 1e-14, kT = 3.0;
  for (const Start& s : starts) {
    INFO(s.what);
    const Vec3 m0 = momentum(kTop, s.theta, s.thetadot, s.phidot, 0.0, s.psidot);
    const Quat q0 = euler_zyz(0.0, s.theta, 0.0);
    const ExactHeavyTop exact(kTop, m0, q0);
    REQUIRE(exact.kind() == ExactHeavyTop::Kind::nutating);
    RungeKutta rk(model, RkMethod::vern9, kTol, m_scale);
    State7 y;
    y << m0, q0.w(), q0.x(), q0.y(), q0.z();
    double worst_q = 0, worst_m = 0, t = 0;
    for (int i = 1; i <= 60; ++i) {
      const double t_next = kT * i / 60;
      rk.advance(y, t, t_next);
      t = t_next;
      const FreeBodyState e = exact.at(t);
      const Quat q(y[3], y[4], y[5], y[6]);
      worst_q = std::max(worst_q, attitude_distance(e.q_BtoS, q));
      worst_m = std::max(worst_m, (e.m_B - y.head<3>()).norm() / m_scale);
    }
    // As above: each step's error is held to tol and they add up along the run.
    const double bound = 5.0 * static_cast<double>(rk.cost().steps) * kTol;
    INFO("steps " << rk.cost().steps << " worst q " << worst_q << " m " << worst_m << " bound "
                  << bound);
    CHECK(worst_q <= bound);
    CHECK(worst_m <= bound);
  }
}
