#include "bench/work_precision.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "bench/mp_reference.hpp"
#include "bench/odeint.hpp"
#include "bench/peers.hpp"
#include "core/exact_free_body.hpp"
#include "core/exact_heavy_top.hpp"
#include "core/runge_kutta.hpp"

namespace wobble::bench {

std::vector<BenchProblem> bench_problems() {
  std::vector<BenchProblem> out;
  BenchProblem p1;
  p1.id = "P1";
  p1.description = "free body I = (2, 1, 2/3), m0 = (cos 1.1, 0, sin 1.1), T = 10";
  p1.model.I_P = Vec3(2.0, 1.0, 2.0 / 3.0);
  p1.m0 = Vec3(std::cos(1.1), 0.0, std::sin(1.1));
  p1.T = 10.0;
  out.push_back(p1);
  BenchProblem p2 = p1;
  p2.id = "P2";
  p2.description = "the same body over T = 1e4";
  p2.T = 1e4;
  out.push_back(p2);
  BenchProblem p3;
  p3.id = "P3";
  p3.description = "near the separatrix: I = (1, 2, 3), m0 = (1e-4, 1, 1e-4), T = 200";
  p3.model.I_P = Vec3(1.0, 2.0, 3.0);
  p3.m0 = Vec3(1e-4, 1.0, 1e-4);
  p3.T = 200.0;
  out.push_back(p3);
  BenchProblem p4;
  p4.id = "P4";
  p4.description =
      "heavy top: I = (3.5, 3.5, 0.625) g m^2 about the pivot, M = 0.5 kg, l = 8 cm, spin 150 "
      "rad/s, tilt 30 deg, T = 2; reference: its closed form at 50 digits (Boost.Math "
      "ellint_3 and jacobi_elliptic in cpp_bin_float_50)";
  p4.model.I_P = Vec3(0.0035125, 0.0035125, 0.000625);
  p4.model.gravity = true;
  p4.model.mass_kg = 0.5;
  p4.model.d_P_m = Vec3(0, 0, 0.08);
  p4.model.g_S = Vec3(0, 0, -9.81);
  p4.m0 = Vec3(0, 0, 0.000625 * 150);
  p4.q0 = Quat(Eigen::AngleAxisd(M_PI / 6, Vec3::UnitY()));
  p4.T = 2.0;
  out.push_back(p4);
  return out;
}

namespace {
struct Outcome {
  Vec3 m;
  Quat q;
  std::int64_t evals = 0;
};

double attitude_distance(const Quat& a, const Quat& b) {
  return (a.toRotationMatrix() - b.toRotationMatrix()).norm();
}

Outcome run_wobble_rk(const BenchProblem& p, RkMethod m, double tol_or_h) {
  RungeKutta rk(p.model, m, tol_or_h, p.m0.norm());
  State7 y = pack(p.m0, p.q0);
  rk.advance(y, 0.0, p.T);
  return {momentum_of(y), attitude_of(y), rk.cost().rhs_evals};
}

Outcome run_split(const BenchProblem& p, SplittingOrder order, double h) {
  FreeBodyState s{p.m0, p.q0};
  std::int64_t subflows = 0;
  const auto steps = static_cast<std::int64_t>(std::llround(p.T / h));
  split_free_body(FreeBody{p.model.I_P}, s, p.T / static_cast<double>(steps), steps, order,
                  &subflows);
  return {s.m_B, s.q_BtoS, subflows};
}

// The peers: Boost.Odeint's controlled steppers on std::array, the same right-hand side.
using Array7 = std::array<double, 7>;
template <class Stepper>
Outcome run_odeint(const BenchProblem& p, double tol) {
  Array7 x;
  Eigen::Map<State7>(x.data()) = pack(p.m0, p.q0);
  std::int64_t evals = 0;
  const RigidBodyRhs f(p.model);  // prepared, as wobble's integrators evaluate it
  auto rhs = [&](const Array7& s, Array7& d, double) {
    Eigen::Map<State7>(d.data()) = f(Eigen::Map<const State7>(s.data()));
    ++evals;
  };
  namespace ode = boost::numeric::odeint;
  ode::controlled_runge_kutta<Stepper> stepper(
      ode::default_error_checker<double, ode::array_algebra, ode::default_operations>(tol, tol));
  ode::integrate_adaptive(stepper, rhs, x, 0.0, p.T, p.T / 1000);
  const State7 y = Eigen::Map<const State7>(x.data());
  return {momentum_of(y), attitude_of(y), evals};
}

struct Reference {
  Vec3 m;
  Quat q;
};

HeavyTop heavy_top_of(const BenchProblem& p) {
  return {p.model.mass_kg, p.model.d_P_m.z(), -p.model.g_S.z(), p.model.I_P.x(), p.model.I_P.z()};
}

// Never the method measured: the free body's and the heavy top's state at T at 50 digits.
Reference reference(const BenchProblem& p) {
  if (p.model.torque_free()) {
    return {mp_free_momentum(p.model.I_P, p.m0, p.T),
            mp_free_attitude(p.model.I_P, p.m0, p.q0, p.T)};
  }
  const FreeBodyState s = MpHeavyTop(heavy_top_of(p), p.m0, p.q0).at(p.T);
  return {s.m_B, s.q_BtoS};
}

Run evaluate(const BenchProblem& p, const Reference& ref, const std::string& method, bool peer,
             const std::string& setting, const Outcome& o) {
  Run r;
  r.problem = p.id;
  r.method = method;
  r.peer = peer;
  r.setting = setting;
  r.error = std::max((o.m - ref.m).norm() / p.m0.norm(), attitude_distance(o.q, ref.q));
  const double E0 = p.model.kinetic(p.m0) + p.model.potential(p.q0);
  const double E = p.model.kinetic(o.m) + p.model.potential(o.q);
  r.energy_error = std::abs(E - E0) / std::max(std::abs(E0), 1e-300);
  // The second invariant: |L| when torque-free, p_phi = L_z in space under gravity.
  r.L_error = p.model.torque_free()
                  ? std::abs(o.m.norm() - p.m0.norm()) / p.m0.norm()
                  : std::abs(Vec3(o.q * o.m).z() - Vec3(p.q0 * p.m0).z()) / p.m0.norm();
  r.evals = o.evals;
  return r;
}

// One problem's runs, every method at every setting, timed side by side (median_times_s): the
// targets are ratios of these times, read between settings on two curves, and a change of the
// machine's speed while the bench runs must fall on both curves alike. The runs' functions are
// kept until timed: whatever they capture must outlive the loop that adds them.
class SideBySide {
 public:
  SideBySide(const BenchProblem& p, const Reference& ref) : p_(p), ref_(ref) {}
  void add(const std::string& method, bool peer, const std::string& setting,
           std::function<Outcome()> f) {
    runs_.push_back(evaluate(p_, ref_, method, peer, setting, f()));
    fs_.push_back([f = std::move(f)] { (void)f(); });
  }
  std::vector<Run> timed(const TimingPlan& plan) && {
    const std::vector<double> t = median_times_s(fs_, plan);
    for (std::size_t i = 0; i < runs_.size(); ++i) runs_[i].time_s = t[i];
    return std::move(runs_);
  }

 private:
  const BenchProblem& p_;
  const Reference& ref_;
  std::vector<Run> runs_;
  std::vector<std::function<void()>> fs_;
};
}  // namespace

std::vector<Run> work_precision(const BenchProblem& p, bool quick, const TimingPlan& plan) {
  const Reference ref = reference(p);
  SideBySide runs(p, ref);
  const std::vector<double> tols = quick
                                       ? std::vector<double>{1e-6, 1e-9, 1e-12, 1e-14}
                                       : std::vector<double>{1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14};
  // Steps as fractions of the time the body needs to turn one radian.
  const double turn = 1.0 / p.model.omega_P(p.m0).norm();
  std::vector<double> fractions =
      quick ? std::vector<double>{0.05, 0.005} : std::vector<double>{0.1, 0.03, 0.01, 0.003, 0.001};
  if (p.T > 1000) fractions = {0.05, 0.01};  // P2: long runs
  std::vector<double> steps;
  for (double f : fractions) steps.push_back(f * turn);
  const bool free = p.model.torque_free();
  const auto tol_text = [](double t) { return fmt::format("tol {:.0e}", t); };
  const auto h_text = [](double h) { return fmt::format("h {:.2g}", h); };
  // Captured by the runs' functions, which are called again after the loops (SideBySide):
  // the loops' own variables are captured by value.
  const HeavyTop top = free ? HeavyTop{} : heavy_top_of(p);
  const State7 y0 = pack(p.m0, p.q0);
  const auto peer = [](const PeerRun& r) {
    return Outcome{momentum_of(r.y), attitude_of(r.y), r.evals};
  };
  if (free) {
    runs.add("exact", false, "-", [&] {
      const FreeBodyState s = ExactFreeMotion(p.model.I_P, p.m0, p.q0).at(p.T);
      return Outcome{s.m_B, s.q_BtoS, 1};
    });
  } else {
    runs.add("exact", false, "-", [&] {
      const FreeBodyState s = ExactHeavyTop(top, p.m0, p.q0).at(p.T);
      return Outcome{s.m_B, s.q_BtoS, 1};
    });
  }
  using ode_dopri5 = boost::numeric::odeint::runge_kutta_dopri5<Array7>;
  using ode_rkf78 = boost::numeric::odeint::runge_kutta_fehlberg78<Array7>;
  for (const double tol : tols) {
    if (tol < 1e-13 && p.T > 1000) continue;
    const std::string setting = tol_text(tol);
    for (const RkMethod m : {RkMethod::dopri5, RkMethod::rkf78, RkMethod::dop853, RkMethod::vern9})
      runs.add(name_of(m), false, setting, [&p, m, tol] { return run_wobble_rk(p, m, tol); });
    runs.add("odeint_dopri5", true, setting, [&p, tol] { return run_odeint<ode_dopri5>(p, tol); });
    runs.add("odeint_rkf78", true, setting, [&p, tol] { return run_odeint<ode_rkf78>(p, tol); });
    for (const auto& [name, method] :
         {std::pair{"gsl_rk8pd", GslMethod::rk8pd}, std::pair{"gsl_rkf45", GslMethod::rkf45}}) {
      runs.add(name, true, setting,
               [&, tol, method = method] { return peer(run_gsl(p.model, y0, p.T, tol, method)); });
    }
    runs.add("cvode_adams", true, setting,
             [&, tol] { return peer(run_cvode_adams(p.model, y0, p.T, tol)); });
  }
  for (const double h : steps) {
    runs.add("rk4", false, h_text(h), [&p, h] { return run_wobble_rk(p, RkMethod::rk4, h); });
    if (free) {
      runs.add("split2", false, h_text(h),
               [&p, h] { return run_split(p, SplittingOrder::strang2, h); });
      runs.add("split4", false, h_text(h),
               [&p, h] { return run_split(p, SplittingOrder::yoshida4, h); });
    }
  }
  return std::move(runs).timed(plan);
}

std::vector<DriftRow> drift_table(bool quick) {
  const BenchProblem p = bench_problems().at(1);  // P2
  const std::vector<double> checkpoints =
      quick ? std::vector<double>{10, 100, 1000} : std::vector<double>{10, 100, 1000, 10000};
  const double E0 = p.model.kinetic(p.m0), L0 = p.m0.norm();
  std::vector<DriftRow> out;
  const auto record = [&](DriftRow& row, const Vec3& m) {
    row.energy_error.push_back(std::abs(p.model.kinetic(m) - E0) / E0);
    row.L_error.push_back(std::abs(m.norm() - L0) / L0);
  };
  for (const auto& [method, tol] :
       {std::pair{RkMethod::dopri5, 1e-10}, std::pair{RkMethod::rkf78, 1e-10}}) {
    DriftRow row{name_of(method), fmt::format("tol {:.0e}", tol), checkpoints, {}, {}};
    RungeKutta rk(p.model, method, tol, L0);
    State7 y = pack(p.m0, p.q0);
    double t = 0;
    for (const double c : checkpoints) {
      rk.advance(y, t, c);
      t = c;
      record(row, momentum_of(y));
    }
    out.push_back(row);
  }
  for (const auto& [name, order] : {std::pair{"split2", SplittingOrder::strang2},
                                    std::pair{"split4", SplittingOrder::yoshida4}}) {
    DriftRow row{name, "h 0.01", checkpoints, {}, {}};
    FreeBodyState s{p.m0, p.q0};
    double t = 0;
    for (const double c : checkpoints) {
      const auto steps = static_cast<std::int64_t>(std::llround((c - t) / 0.01));
      split_free_body(FreeBody{p.model.I_P}, s, 0.01, steps, order);
      t = c;
      record(row, s.m_B);
    }
    out.push_back(row);
  }
  return out;
}

std::vector<ExactDriftPoint> exact_error_against_time() {
  const BenchProblem p = bench_problems().at(1);  // P2
  const ExactFreeMotion exact(p.model.I_P, p.m0, p.q0);
  std::vector<ExactDriftPoint> out;
  for (double t = 10.0; t <= 1e7; t *= 10.0) {
    const double eps = std::numeric_limits<double>::epsilon();
    const FreeBodyState s = exact.at(t);
    const double e = (s.m_B - mp_free_momentum(p.model.I_P, p.m0, t)).norm();
    const double a = attitude_distance(s.q_BtoS, mp_free_attitude(p.model.I_P, p.m0, p.q0, t));
    out.push_back({p.id, t, t / exact.period_s(), e / (eps * p.m0.norm()), a / eps});
  }
  const BenchProblem h = bench_problems().at(3);  // P4
  const HeavyTop top = heavy_top_of(h);
  const ExactHeavyTop top_exact(top, h.m0, h.q0);
  const MpHeavyTop top_50(top, h.m0, h.q0);
  for (double t = 2.0; t <= 2e6; t *= 10.0) {
    const double eps = std::numeric_limits<double>::epsilon();
    const FreeBodyState s = top_exact.at(t), r = top_50.at(t);
    out.push_back({h.id, t, t / top_exact.nutation_period_s(),
                   (s.m_B - r.m_B).norm() / (eps * h.m0.norm()),
                   attitude_distance(s.q_BtoS, r.q_BtoS) / eps});
  }
  return out;
}

std::vector<DenseRow> dense_output_table(bool quick, const TimingPlan& plan) {
  const BenchProblem p = bench_problems().at(1);  // P2
  constexpr double kTol = 1e-10;
  const std::size_t many = quick ? 10000 : 100000;
  const auto times_of = [&](std::size_t n) {
    std::vector<double> t(n);
    for (std::size_t i = 0; i < n; ++i)
      t[i] = p.T * static_cast<double>(i + 1) / static_cast<double>(n);
    return t;
  };
  const std::vector<double> few_times = times_of(10), many_times = times_of(many);
  std::vector<DenseRow> out;
  for (const RkMethod m : {RkMethod::dopri5, RkMethod::dop853, RkMethod::rkf78}) {
    DenseRow row{name_of(m), fmt::format("tol {:.0e}", kTol), 10, many, 0, 0, 0.0, 0.0};
    const auto run = [&](const std::vector<double>& times) {
      RungeKutta rk(p.model, m, kTol, p.m0.norm());
      State7 y = pack(p.m0, p.q0);
      double sum = 0.0;  // the sink's work, and what keeps the samples from being optimised out
      rk.sample(y, 0.0, times, [&](std::size_t, const State7& s) { sum += s[0]; });
      if (!std::isfinite(sum)) throw std::runtime_error("dense output bench: a non-finite state");
      return rk.cost().rhs_evals;
    };
    row.evals_few = run(few_times);
    row.evals_many = run(many_times);
    // Side by side: their ratio is the target.
    const std::vector<double> t =
        median_times_s({[&] { (void)run(few_times); }, [&] { (void)run(many_times); }}, plan);
    row.time_few_s = t[0];
    row.time_many_s = t[1];
    out.push_back(row);
  }
  return out;
}

double time_at_error(const std::vector<Run>& runs, const std::string& problem,
                     const std::string& method, double target) {
  // The curve's frontier: by time, each run that is more accurate than every cheaper one. Where
  // round-off or the problem's condition stops the error from falling (P3 near the separatrix:
  // tolerance 1e-14 ends farther off than 1e-12), a costlier run that is no better says nothing
  // about what the error costs; sorted by error alone it would bracket the target instead.
  std::vector<std::pair<double, double>> by_time;  // (log t, log e)
  for (const auto& r : runs) {
    if (r.problem == problem && r.method == method && r.error > 0)
      by_time.emplace_back(std::log(r.time_s), std::log(r.error));
  }
  std::sort(by_time.begin(), by_time.end());
  std::vector<std::pair<double, double>> frontier;
  for (const auto& p : by_time) {
    if (frontier.empty() || p.second < frontier.back().second) frontier.push_back(p);
  }
  // Interpolate log t against log e between the two frontier runs that bracket the target.
  const double le = std::log(target);
  for (std::size_t i = 1; i < frontier.size(); ++i) {
    const auto& [t0, e0] = frontier[i - 1];
    const auto& [t1, e1] = frontier[i];
    if (e1 <= le && le <= e0) {
      const double f = (le - e0) / (e1 - e0);
      return std::exp(t0 + f * (t1 - t0));
    }
  }
  return -1.0;
}

double time_ratio_at(const std::vector<Run>& runs, const std::string& problem, const std::string& a,
                     const std::string& b, double target) {
  const auto time_for = [&](const std::string& method) {
    return time_at_error(runs, problem, method, target);
  };
  const double ta = time_for(a), tb = time_for(b);
  return ta > 0 && tb > 0 ? ta / tb : -1.0;
}

double measured_condition(const BenchProblem& p) {
  if (!p.model.torque_free()) return -1.0;
  // Perturb each component by eps |m0| (one ulp of the largest), as rounding the input would.
  const double eps = std::numeric_limits<double>::epsilon();
  const Vec3 base = ExactFreeMotion(p.model.I_P, p.m0, p.q0).at(p.T).m_B;
  double worst = 0.0;
  for (int i = 0; i < 3; ++i) {
    Vec3 m = p.m0;
    m[i] += eps * p.m0.norm();
    const Vec3 moved = ExactFreeMotion(p.model.I_P, m, p.q0).at(p.T).m_B;
    worst = std::max(worst, (moved - base).norm() / p.m0.norm());
  }
  return worst / eps;
}

}  // namespace wobble::bench
