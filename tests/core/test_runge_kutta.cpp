// Runge-Kutta methods on the rigid body: measured orders, tolerance control, drift of the
// invariants, and the torques (gravity about a pivot, a constant torque in space).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "core/exact_free_body.hpp"
#include "core/runge_kutta.hpp"
#include "core/runge_kutta_tableaux.hpp"

using namespace wobble;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
const Vec3 kI(2.0, 1.0, 2.0 / 3.0);
const Vec3 kM0(std::cos(1.1), 0.0, std::sin(1.1));

RigidBodyModel free_model() {
  RigidBodyModel m;
  m.I_P = kI;
  return m;
}

double error_at(const RigidBodyModel& model, RkMethod method, double tol_or_h, bool fixed, double T,
                IntegrationCost* cost = nullptr) {
  RungeKutta rk(model, method, tol_or_h, 1.0, fixed);
  State7 y = pack(kM0, Quat::Identity());
  rk.advance(y, 0.0, T);
  if (cost) *cost = rk.cost();
  const FreeBodyState ex = ExactFreeMotion(kI, kM0, Quat::Identity()).at(T);
  return std::max((momentum_of(y) - ex.m_B).norm(),
                  (attitude_of(y).toRotationMatrix() - ex.q_BtoS.toRotationMatrix()).norm());
}
}  // namespace

TEST_CASE("each Runge-Kutta method converges at its order when the step halves (measured)") {
  const RigidBodyModel model = free_model();
  // Steps chosen in each method's asymptotic range and with errors >= 3e-14, well above the
  // exact solution's round-off (~1e-15): the observed order log2(e(h)/e(h/2)) is then the
  // method's up to higher-order terms, which the halvings below leave within 0.3.
  for (const auto& [method, h0] : {std::pair{RkMethod::rk4, 0.2}, std::pair{RkMethod::dopri5, 0.2},
                                   std::pair{RkMethod::rkf78, 0.5},
                                   std::pair{RkMethod::dop853, 0.6}}) {
    const double e1 = error_at(model, method, h0, true, 10.0),
                 e2 = error_at(model, method, h0 / 2, true, 10.0),
                 e3 = error_at(model, method, h0 / 4, true, 10.0);
    const double p = order_of(method);
    INFO(name_of(method) << ": errors " << e1 << ", " << e2 << ", " << e3);
    REQUIRE(e3 >= 3e-14);
    REQUIRE_THAT(std::log2(e1 / e2), WithinAbs(p, 0.3));
    REQUIRE_THAT(std::log2(e2 / e3), WithinAbs(p, 0.3));
  }
}

TEST_CASE("adaptive pairs meet their tolerance, and tighter costs more") {
  const RigidBodyModel model = free_model();
  for (const RkMethod method : {RkMethod::dopri5, RkMethod::rkf78, RkMethod::dop853}) {
    std::int64_t last_evals = 0;
    for (const double tol : {1e-6, 1e-9, 1e-12}) {
      IntegrationCost cost;
      const double e = error_at(model, method, tol, false, 10.0, &cost);
      INFO(name_of(method) << " tol " << tol << ": error " << e << ", " << cost.rhs_evals);
      // Per-step control to tol over ~20-300 steps of a non-expanding flow: the global error
      // stays within 100 tol (measured 0.03-2.3 tol).
      REQUIRE(e <= 100 * tol);
      REQUIRE(cost.rhs_evals > last_evals);
      last_evals = cost.rhs_evals;
    }
  }
}

TEST_CASE("dense output: states between the steps as accurate as at them, the steps unchanged") {
  const RigidBodyModel model = free_model();
  const ExactFreeMotion exact(kI, kM0, Quat::Identity());
  constexpr double kTol = 1e-10, kT = 10.0;
  const auto times_of = [&](std::size_t n) {
    std::vector<double> t(n);
    for (std::size_t i = 0; i < n; ++i) t[i] = kT * static_cast<double>(i + 1) / static_cast<double>(n);
    return t;
  };
  for (const RkMethod method : {RkMethod::dopri5, RkMethod::dop853}) {
    const auto run = [&](std::size_t n, double* worst) {
      RungeKutta rk(model, method, kTol, 1.0);
      State7 y = pack(kM0, Quat::Identity());
      const std::vector<double> times = times_of(n);
      rk.sample(y, 0.0, times, [&](std::size_t k, const State7& s) {
        const FreeBodyState ex = exact.at(times[k]);
        const double e = std::max((momentum_of(s) - ex.m_B).norm(),
                                  (attitude_of(s).toRotationMatrix() -
                                   ex.q_BtoS.toRotationMatrix()).norm());
        if (worst) *worst = std::max(*worst, e);
        // Unit quaternion as given, not only after attitude_of normalises it.
        REQUIRE_THAT(s.tail<4>().norm(), WithinAbs(1.0, 4 * std::numeric_limits<double>::epsilon()));
      });
      return std::pair{rk.cost(), y};
    };
    double worst = 0.0;
    const auto [few, y_few] = run(10, nullptr);
    const auto [many, y_many] = run(10000, &worst);
    RungeKutta plain(model, method, kTol, 1.0);
    State7 y_plain = pack(kM0, Quat::Identity());
    plain.advance(y_plain, 0.0, kT);
    INFO(name_of(method) << ": worst sample error " << worst << "; steps " << few.steps << " / "
                         << many.steps << ", evaluations " << few.rhs_evals << " / "
                         << many.rhs_evals);
    // The same bound as the step ends' (above): the interpolants' error is of the local
    // error's size (orders 4 and 7, one less than the steps').
    REQUIRE(worst <= 100 * kTol);
    REQUIRE(worst > 0.0);
    // The output times never shorten a step: the same steps, and the same end state as
    // advance() (bit for bit).
    REQUIRE(many.steps == few.steps);
    REQUIRE(few.steps == plain.cost().steps);
    REQUIRE(y_many == y_plain);
    REQUIRE(y_few == y_plain);
    // Dormand-Prince's interpolant costs no evaluation; DOP853's three per step with an output.
    const std::int64_t extra = method == RkMethod::dopri5 ? 0 : 3 * many.steps;
    REQUIRE(many.rhs_evals <= plain.cost().rhs_evals + extra);
  }
}

TEST_CASE("the tableaux: weights sum to one, error weights to zero, interpolants end at y_new") {
  namespace tab = rk_tableau;
  const double eps = std::numeric_limits<double>::epsilon();
  // Each sum has at most 16 terms of size up to ~500 (DOP853's D): rounding within
  // 16 * 500 eps of the exact sum.
  const double bound = 16 * 500 * eps;
  const auto sum = [](const auto& row) {
    double s = 0.0;
    for (const double c : row) s += c;
    return s;
  };
  REQUIRE_THAT(sum(tab::Dop853::B), WithinAbs(1.0, bound));
  REQUIRE_THAT(sum(tab::Dop853::E), WithinAbs(0.0, bound));
  REQUIRE_THAT(sum(tab::Dop853::E3), WithinAbs(0.0, bound));
  REQUIRE_THAT(sum(tab::Dopri5::B), WithinAbs(1.0, bound));
  // Shampine's interpolant at x = 1 is the step's own solution: sum_p P[j][p] = B[j].
  // It also has the end slopes, y'(0) = k_1 and y'(1) = k_7 (sum_p (p + 1) P[j][p] is 1 for the
  // last stage, 0 for the others): so it is the cubic Hermite interpolant plus x^2 (1-x)^2
  // times its x^4 coefficient, the nested form dense output evaluates.
  for (std::size_t j = 0; j < tab::Dopri5::S; ++j) {
    const auto& P = tab::Dopri5::P[j];
    REQUIRE_THAT(sum(P), WithinAbs(tab::Dopri5::B[j], bound));
    REQUIRE_THAT(P[0], WithinAbs(j == 0 ? 1.0 : 0.0, bound));
    REQUIRE_THAT(P[0] + 2 * P[1] + 3 * P[2] + 4 * P[3],
                 WithinAbs(j == tab::Dopri5::S - 1 ? 1.0 : 0.0, 4 * bound));
  }
  // Every row of A sums to its node c_i; the nodes lie in [0, 1] (DOP853's three extra stages
  // at 0.1, 0.2 and 7/9, Hairer's values).
  for (const auto& row : tab::Dop853::A) {
    REQUIRE(sum(row) >= -bound);
    REQUIRE(sum(row) <= 1.0 + bound);
  }
  REQUIRE_THAT(sum(tab::Dop853::kExtraA[0]), WithinAbs(0.1, bound));
  REQUIRE_THAT(sum(tab::Dop853::kExtraA[1]), WithinAbs(0.2, bound));
  REQUIRE_THAT(sum(tab::Dop853::kExtraA[2]), WithinAbs(7.0 / 9.0, bound));
}

TEST_CASE("output times out of order are refused") {
  RungeKutta rk(free_model(), RkMethod::dop853, 1e-8, 1.0);
  State7 y = pack(kM0, Quat::Identity());
  const std::vector<double> times{1.0, 0.5};
  REQUIRE_THROWS_AS(rk.sample(y, 0.0, times, [](std::size_t, const State7&) {}),
                    std::invalid_argument);
}

TEST_CASE("Runge-Kutta energy error drifts at most linearly in time (a bound)") {
  // Not structure-preserving: the energy error grows, roughly linearly for this periodic
  // motion. Bound: over 10x the time, at most 10x the error, with a factor 3 for the phase of
  // the oscillation at which each run ends.
  const RigidBodyModel model = free_model();
  const double E0 = model.kinetic(kM0);
  RungeKutta rk(model, RkMethod::dopri5, 1e-8, 1.0);
  State7 y = pack(kM0, Quat::Identity());
  double t = 0, worst100 = 0, worst1000 = 0;
  for (int k = 1; k <= 1000; ++k) {
    rk.advance(y, t, k * 1.0);
    t = k;
    const double e = std::abs(model.kinetic(momentum_of(y)) - E0);
    (k <= 100 ? worst100 : worst1000) = std::max(k <= 100 ? worst100 : worst1000, e);
  }
  worst1000 = std::max(worst1000, worst100);
  INFO("energy error to T=100: " << worst100 << ", to T=1000: " << worst1000);
  REQUIRE(worst100 > 0.0);
  REQUIRE(worst1000 <= 30 * worst100);
}

TEST_CASE("heavy symmetric top: energy, p_phi and p_psi conserved to the tolerance") {
  RigidBodyModel m;
  m.I_P = Vec3(0.0035, 0.0035, 0.000625);  // about the pivot; e3 the axle
  m.gravity = true;
  m.mass_kg = 0.5;
  m.d_P_m = Vec3(0, 0, 0.08);
  m.g_S = Vec3(0, 0, -9.81);
  const Quat q0(Eigen::AngleAxisd(0.5, Vec3::UnitY()));
  const Vec3 m0(0, 0, m.I_P.z() * 150);
  RungeKutta rk(m, RkMethod::rkf78, 1e-11, m0.norm());
  State7 y = pack(m0, q0);
  const double E0 = m.kinetic(m0) + m.potential(q0);
  const double pphi0 = (q0 * m0).z(), ppsi0 = m0.z();
  double t = 0;
  for (int k = 1; k <= 200; ++k) {
    rk.advance(y, t, k * 0.01);
    t = k * 0.01;
    const Vec3 mm = momentum_of(y);
    const Quat q = attitude_of(y);
    // Per-step tolerance 1e-11 relative to |m0| over ~1000 steps: within 1000 tol (linear
    // accumulation); measured ~50 tol.
    const double bound = 1e3 * 1e-11;
    REQUIRE_THAT(m.kinetic(mm) + m.potential(q), WithinAbs(E0, bound * std::abs(E0)));
    REQUIRE_THAT((q * mm).z(), WithinAbs(pphi0, bound * m0.norm()));
    REQUIRE_THAT(mm.z(), WithinAbs(ppsi0, bound * m0.norm()));
  }
  // Gravity does act: the axle has moved (precession), unlike a torque-free top released so.
  REQUIRE((attitude_of(y) * Vec3::UnitZ() - q0 * Vec3::UnitZ()).norm() > 1e-2);
}

TEST_CASE("a constant torque in space adds tau t to L in space, exactly") {
  RigidBodyModel m;
  m.I_P = Vec3(1, 2, 3);
  m.torque = true;
  m.torque_in_space = true;
  m.torque_Nm = Vec3(0.1, -0.2, 0.3);
  const Vec3 m0(0.5, 0.2, -0.4);
  RungeKutta rk(m, RkMethod::rkf78, 1e-12, 1.0);
  State7 y = pack(m0, Quat::Identity());
  rk.advance(y, 0, 7.0);
  const Vec3 L = attitude_of(y) * momentum_of(y);
  // dL_S/dt = tau exactly; the integration error is within ~steps * tol * scale.
  REQUIRE((L - (m0 + 7.0 * m.torque_Nm)).norm() <= 1e-9);
}

TEST_CASE("integrator input is validated") {
  const RigidBodyModel model = free_model();
  REQUIRE_THROWS_AS(RungeKutta(model, RkMethod::dopri5, 0.0, 1.0), std::invalid_argument);
  REQUIRE_THROWS_AS(RungeKutta(model, RkMethod::dopri5, 1e-8, NAN), std::invalid_argument);
  RigidBodyModel bad = model;
  bad.I_P = Vec3(1, 0, 1);
  REQUIRE_THROWS_AS(RungeKutta(bad, RkMethod::rk4, 0.1, 1.0), std::invalid_argument);
}
