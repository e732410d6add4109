// The torque-free keys against an independent simulation: Euler's equations plus the attitude,
// integrated by Boost.Odeint's Dormand-Prince 5(4) at tight tolerance.
#include <array>
#include <boost/numeric/odeint.hpp>
#include <catch2/catch.hpp>
#include <cmath>

#include "core/inertia.hpp"
#include "solvers/catalog.hpp"
#include "problem/values.hpp"
#include "solvers/solve.hpp"

using namespace wobble;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
using State = std::array<double, 12>;  // w in the body (3), then R row-major (9), body -> space

const Answer& answer(const Key& key, const std::string& name) {
  for (const auto& part : key.parts) {
    for (const auto& a : part.answers) {
      if (a.name == name) return a;
    }
  }
  throw std::logic_error("no answer " + name);
}

struct Rigid {
  double I1, I3;
  void operator()(const State& x, State& dxdt, double) const {
    const double w1 = x[0], w2 = x[1], w3 = x[2];
    dxdt[0] = (I1 - I3) / I1 * w2 * w3;  // Euler's equations with I2 = I1
    dxdt[1] = (I3 - I1) / I1 * w3 * w1;
    dxdt[2] = 0.0;
    for (int r = 0; r < 3; ++r) {  // dR/dt = R [w]x
      const double a = x[3 + 3 * r], b = x[4 + 3 * r], c = x[5 + 3 * r];
      dxdt[3 + 3 * r] = b * w3 - c * w2;
      dxdt[4 + 3 * r] = c * w1 - a * w3;
      dxdt[5 + 3 * r] = a * w2 - b * w1;
    }
  }
};

Mat3 attitude(const State& x) {
  Mat3 R;
  for (int i = 0; i < 9; ++i) R(i / 3, i % 3) = x[static_cast<std::size_t>(3 + i)];
  return R;
}

void check(const std::string& id, const std::vector<std::string>& sets) {
  const Problem p = find_problem(id);
  const Key key = solve(p, parameter_values(p, sets));
  const double I1 = answer(key, "I").value.at(0, 0), I3 = answer(key, "I").value.at(2, 2);
  const auto& w0 = answer(key, "L0_body").value.data;  // L0 = (I1 w1, 0, I3 w3)
  const Vec3 L0(w0[0], w0[1], w0[2]);
  const double max_angle = answer(key, "max_angle").value.data[0];
  const double t_max = answer(key, "t_max").value.data[0];
  const double rate_body = answer(key, "Omega_body_rate").value.data[0];
  const double rate_space = answer(key, "Omega_space_rate").value.data[0];

  State x{L0.x() / I1, 0.0, L0.z() / I3, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const double w1_0 = x[0], w3 = x[2];
  // Tolerance of the integrator: 1e-12 per unit of time (abs and rel); the run lasts 1.5 t_max,
  // a few hundred steps, so the global error stays below 1e-9 in every component.
  constexpr double kTol = 1e-12, kGlobal = 1e-9;
  auto stepper = boost::numeric::odeint::make_dense_output(
      kTol, kTol, boost::numeric::odeint::runge_kutta_dopri5<State>());
  const int n = 6000;
  const double dt = 1.5 * t_max / n;
  std::vector<double> angle(n + 1);
  double worst_L = 0.0, worst_coplanar = 0.0, worst_body_rate = 0.0;
  // The turn of e3 about the fixed L, summed sample to sample (each step turns far below pi).
  const Vec3 n_L = L0.normalized();
  const auto across_L = [&](const Vec3& v) -> Vec3 { return v - v.dot(n_L) * n_L; };
  Vec3 previous = across_L(Vec3::UnitZ());
  double turned_about_L = 0.0;
  int k = 0;
  boost::numeric::odeint::integrate_const(
      stepper, Rigid{I1, I3}, x, 0.0, 1.5 * t_max, dt, [&](const State& s, double t) {
        const Mat3 R = attitude(s);
        const Vec3 w_body(s[0], s[1], s[2]);
        const Vec3 e3 = R.col(2);
        angle[static_cast<std::size_t>(k++)] = std::atan2(std::hypot(e3.x(), e3.y()), e3.z());
        const Vec3 now = across_L(e3);
        turned_about_L += std::atan2(previous.cross(now).dot(n_L), previous.dot(now));
        previous = now;
        const Vec3 L = R * Vec3(I1 * s[0], I1 * s[1], I3 * s[2]);
        worst_L = std::max(worst_L, (L - L0).norm() / L0.norm());
        worst_coplanar = std::max(
            worst_coplanar, std::abs((R * w_body).cross(L).dot(e3)) / (L0.norm() * w_body.norm()));
        // In the body, w1 + i w2 turns at Omega_body: w1 = w1(0) cos(Omega_b t), w2 = w1(0)
        // sin(...).
        worst_body_rate =
            std::max(worst_body_rate, std::hypot(s[0] - w1_0 * std::cos(rate_body * t),
                                                 s[1] - w1_0 * std::sin(rate_body * t)) /
                                          std::max(w1_0, 1e-300));
      });
  INFO(id << " with " << (sets.empty() ? "defaults" : sets.back()));
  REQUIRE(k == n + 1);
  // Conservation and geometry: at the level of the global error.
  CHECK(worst_L <= kGlobal);
  CHECK(worst_coplanar <= kGlobal);
  // The body precession grows phase error linearly: kGlobal relative over the run.
  CHECK(worst_body_rate <= kGlobal * (1 + std::abs(rate_body) * 1.5 * t_max));
  // The maximum: a parabola through the largest sample and its neighbours.
  std::size_t i = 1;
  for (std::size_t j = 1; j < angle.size() - 1; ++j) {
    if (angle[j] > angle[i]) i = j;
  }
  const double a = angle[i - 1], b = angle[i], c = angle[i + 1];
  const double curvature = (a - 2 * b + c) / (dt * dt);  // < 0
  const double shift = 0.5 * (a - c) / (a - 2 * b + c);  // in units of dt
  const double t_peak = (static_cast<double>(i) + shift) * dt;
  const double peak = b - 0.25 * (a - c) * shift;
  // The parabola's own error is ~ angle''' dt^3, far below kGlobal at 6000 samples; an angle
  // error kGlobal moves the vertex by about kGlobal / (|curvature| dt).
  CHECK_THAT(peak, WithinAbs(max_angle, 2 * kGlobal));
  CHECK_THAT(t_peak, WithinAbs(t_max, 4 * kGlobal / (std::abs(curvature) * dt) + 1e-3 * dt));
  // The space precession, measured: the turn of e3 about L over the run, divided by its time.
  // e3 circles L at the radius sin(theta_L); an attitude error kGlobal moves the measured turn
  // by kGlobal / sin(theta_L) at each end of the run.
  const double t_end = 1.5 * t_max;
  const double radius = across_L(Vec3::UnitZ()).norm();
  CHECK_THAT(turned_about_L / t_end, WithinAbs(rate_space, 2 * kGlobal / (radius * t_end)));
  (void)w3;
}
}  // namespace

TEST_CASE("torque-free keys agree with an Odeint simulation for several shapes and angles") {
  for (const std::string id : {"rect-solid", "flying-plate", "flying-square-plate"}) {
    for (const std::string alpha : {"5deg", "30deg", "60deg", "85deg"}) {
      check(id, {"omega=7.5", "alpha=" + alpha});
    }
  }
}
