// The exact torque-free solution (Jacobi elliptic functions, attitude by the third-kind
// integral) against independent integrations, near and far from the separatrix.
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "core/elliptic.hpp"
#include "core/exact_free_body.hpp"
#include "odeint_reference.hpp"

using namespace wobble;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();
const Quat kQ0(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
}  // namespace

TEST_CASE("Jacobi sn, cn, dn from k'^2 match Boost.Math at 50 digits, down to k'^2 = 1e-16") {
  using mp = boost::multiprecision::cpp_bin_float_50;
  for (const double kc2 : {0.9, 0.5, 1e-2, 1e-4, 1e-8, 1e-12, 1e-16}) {
    const double K = complete_K(kc2);
    const mp k = sqrt(mp(1) - mp(kc2));
    INFO("k'^2 = " << kc2);
    for (int i = -100; i <= 100; ++i) {
      for (const double u : {K * i / 100.0, std::nextafter(K, 0.0), K - 1e-10, K - 1e-6}) {
        const SnCnDn e = jacobi_sncndn(u, kc2);
        mp cn, dn;
        const mp sn = boost::math::jacobi_elliptic(k, mp(u), &cn, &dn);
        INFO("u = " << u);
        // sn and dn relative: Bulirsch's recurrence runs ~log2(log(1/k'^2)) + 3 <= 9 levels,
        // each adding a few eps; measured at most 19.5 eps (dn near K at k'^2 = 1e-16, where dn
        // ~ k' = 1e-8). 32 eps bounds it.
        REQUIRE_THAT(e.sn, WithinRel(static_cast<double>(sn), 32 * kEps));
        REQUIRE_THAT(e.dn, WithinRel(static_cast<double>(dn), 32 * kEps));
        // cn absolute: cn vanishes at K, and the phase u c carries one rounding of ~eps |u c|
        // with |u c| <= pi/2; measured at most 1.1e-16.
        REQUIRE_THAT(e.cn, WithinAbs(static_cast<double>(cn), 4 * kEps));
      }
    }
  }
}

TEST_CASE("exact solution agrees with an independent Fehlberg 7(8) run, both circulations") {
  struct Case {
    Vec3 I, m0;
  };
  // Circling the axis of largest moment, of least moment, a permuted body (moments not in
  // ascending order), the standard test body, and k'^2 = 2.7e-8 near the separatrix.
  const Case cases[] = {{Vec3(1, 2, 3), Vec3(0.2, 0.5, 1)},
                        {Vec3(1, 2, 3), Vec3(1, 0.5, 0.2)},
                        {Vec3(3, 1, 2), Vec3(0.3, -0.7, 0.5)},
                        {Vec3(2, 1, 2.0 / 3), Vec3(std::cos(1.1), 0, std::sin(1.1))},
                        {Vec3(1, 2, 3), Vec3(-0.3, 0.2, -1)},
                        {Vec3(1, 2, 3), Vec3(1e-4, 1, 1e-4)}};
  for (const auto& c : cases) {
    const ExactFreeMotion exact(c.I, c.m0, kQ0);
    REQUIRE(exact.kind() == ExactFreeMotion::Kind::elliptic);
    for (const double T : {0.7, 5.0, 20.0}) {
      const FreeBodyState ref = testing::odeint_free_body(c.I, c.m0, kQ0, T);
      const FreeBodyState ex = exact.at(T);
      INFO("I = " << c.I.transpose() << ", m0 = " << c.m0.transpose() << ", T = " << T);
      // The reference controls each step to 1e-14; over <= ~2000 steps its global error stays
      // below 1e-14 * steps * (growth), measured <= 2e-14 here; near the separatrix a 1-ulp
      // change of m0 already moves m(20) by ~1e-12 (numerics notes), so 1e-11 covers both
      // with the separatrix case and is still 1e-5 of the smallest component it must get.
      REQUIRE((ex.m_B - ref.m_B).norm() <= 1e-11 * c.m0.norm());
      REQUIRE(testing::attitude_distance(ex.q_BtoS, ref.q_BtoS) <= 1e-11);
    }
  }
}

TEST_CASE("exact solution on and next to the separatrix keeps the invariants to round-off") {
  const Vec3 I(1, 2, 3);
  for (const double s : {1e-8, 1e-12, 0.0}) {
    // m0 = (s, 1, s): k'^2 ~ s^2 (1e-16, 1e-24). s = 0: m0 = (1e-3, 1, 1e-3 sqrt 3) lies on the
    // separatrix (D = m3^2/3 - m1^2 = 0) up to the rounding of sqrt 3.
    const Vec3 m0 = s > 0 ? Vec3(s, 1, s) : Vec3(1e-3, 1, 1e-3 * std::sqrt(3.0));
    const ExactFreeMotion exact(I, m0, Quat::Identity());
    const double E0 = 0.5 * m0.cwiseQuotient(I).dot(m0);
    for (double t = 0; t <= 50; t += 0.5) {
      const FreeBodyState st = exact.at(t);
      INFO("s = " << s << ", t = " << t << ", m = " << st.m_B.transpose());
      REQUIRE(st.m_B.allFinite());
      // Each component comes from one elliptic function times an amplitude: a few eps each,
      // so |m|^2 and 2T to 16 eps.
      REQUIRE_THAT(st.m_B.norm(), WithinRel(m0.norm(), 16 * kEps));
      REQUIRE_THAT(0.5 * st.m_B.cwiseQuotient(I).dot(st.m_B), WithinRel(E0, 16 * kEps));
      // L in space is fixed: the attitude carries m to the same vector at every t.
      REQUIRE((st.q_BtoS * st.m_B - m0).norm() <= 64 * kEps * m0.norm());
    }
  }
}

TEST_CASE("exact solution's flip period matches the simulated flips of the intermediate axis") {
  // The tennis racket: spin about the intermediate axis, perturbed. m2 changes sign every half
  // period; find the crossings in an independent integration and compare.
  const Vec3 I(1, 2, 3), m0(0.01, 2.0, 0.01);
  const ExactFreeMotion exact(I, m0, Quat::Identity());
  const double half = exact.period_s() / 2;
  std::vector<double> crossings;
  double t = 0, dt = 0.01, prev = m0.y();
  FreeBodyState s{m0, Quat::Identity()};
  while (t < 3.2 * half) {
    s = testing::odeint_free_body(I, s.m_B, s.q_BtoS, dt, 1e-13);
    t += dt;
    if ((prev > 0) != (s.m_B.y() > 0)) {
      // Linear interpolation: at a zero of sn the curvature vanishes (sn'' ~ sn), so the error
      // is O(dt^3 |m'''|) ~ 1e-6 * 2, far below the 1e-4 bound.
      crossings.push_back(t - dt * s.m_B.y() / (s.m_B.y() - prev));
    }
    prev = s.m_B.y();
  }
  REQUIRE(crossings.size() >= 3);
  for (std::size_t i = 1; i < crossings.size(); ++i) {
    REQUIRE_THAT(crossings[i] - crossings[i - 1], WithinRel(half, 1e-4));
  }
}

TEST_CASE(
    "symmetric closed form: exact kinds agree with the integrator and the nearly symmetric "
    "elliptic") {
  const Vec3 I(1, 1, 2.5), m0(0.4, -0.3, 1.2);
  const ExactFreeMotion closed(I, m0, kQ0);
  REQUIRE(closed.kind() == ExactFreeMotion::Kind::symmetric);
  // I2 = I1 (1 + 1e-10): the elliptic solution must approach the closed form; the difference
  // is of order 1e-10 * rate * t (a phase drift), <= 1e-8 here.
  const ExactFreeMotion near(Vec3(1, 1 + 1e-10, 2.5), m0, kQ0);
  REQUIRE(near.kind() == ExactFreeMotion::Kind::elliptic);
  for (const double T : {1.0, 10.0}) {
    const FreeBodyState ref = testing::odeint_free_body(I, m0, kQ0, T);
    const FreeBodyState c = closed.at(T), e = near.at(T);
    REQUIRE((c.m_B - ref.m_B).norm() <= 1e-12 * m0.norm());
    REQUIRE(testing::attitude_distance(c.q_BtoS, ref.q_BtoS) <= 1e-12);
    REQUIRE((e.m_B - c.m_B).norm() <= 1e-8 * m0.norm());
    REQUIRE(testing::attitude_distance(e.q_BtoS, c.q_BtoS) <= 1e-8);
  }
}

TEST_CASE("steady rotation about a principal axis and bad input") {
  const ExactFreeMotion steady(Vec3(1, 2, 3), Vec3(0, 2, 0), Quat::Identity());
  REQUIRE(steady.kind() == ExactFreeMotion::Kind::steady);
  const FreeBodyState s = steady.at(M_PI);  // w = 1 rad/s about y: half a turn
  REQUIRE((s.m_B - Vec3(0, 2, 0)).norm() == 0.0);
  REQUIRE((s.q_BtoS * Vec3::UnitX() - Vec3(-1, 0, 0)).norm() <= 4 * kEps);
  REQUIRE_THROWS_AS(ExactFreeMotion(Vec3(1, 2, 3), Vec3::Zero(), Quat::Identity()),
                    std::invalid_argument);
  REQUIRE_THROWS_AS(ExactFreeMotion(Vec3(1, -2, 3), Vec3::Ones(), Quat::Identity()),
                    std::invalid_argument);
}

TEST_CASE("momentum_at equals the momentum of at, for every kind of motion") {
  const ExactFreeMotion kinds[] = {ExactFreeMotion(Vec3(1, 2, 3), Vec3(0.2, 0.5, 1), kQ0),
                                   ExactFreeMotion(Vec3(1, 2, 3), Vec3(1, 0.5, 0.2), kQ0),
                                   ExactFreeMotion(Vec3(1, 1, 2.5), Vec3(0.4, -0.3, 1.2), kQ0),
                                   ExactFreeMotion(Vec3(1, 2, 3), Vec3(0, 2, 0), kQ0)};
  for (const auto& m : kinds) {
    for (const double t : {0.0, 0.3, 7.0, 123.4}) {
      REQUIRE((m.momentum_at(t) - m.at(t).m_B).norm() == 0.0);  // the same arithmetic
    }
  }
}
