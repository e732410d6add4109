#include "simulate/simulation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <span>

#include "core/exact_free_body.hpp"
#include "core/exact_heavy_top.hpp"
#include "core/input_error.hpp"
#include "core/runge_kutta.hpp"
#include "core/work_budget.hpp"
#include "simulate/outputs.hpp"

namespace wobble {

namespace {
// A span that is a whole number of splitting steps up to rounding gets no extra tiny step.
constexpr double kStepCountSlack = 1e-12;
}  // namespace

namespace {
void report(const std::function<void(double)>& progress, std::size_t k, std::size_t n) {
  if (progress && (n < 100 || k % (n / 100) == 0))
    progress(static_cast<double>(k) / static_cast<double>(n));
}

void describe(const ExactFreeMotion& motion, std::vector<std::string>& notes) {
  switch (motion.kind()) {
    case ExactFreeMotion::Kind::steady:
      notes.push_back("steady rotation about a principal axis");
      return;
    case ExactFreeMotion::Kind::symmetric:
      if (std::isfinite(motion.period_s())) {
        notes.push_back(fmt::format("w turns about the symmetry axis in the body every {:.10g} s",
                                    motion.period_s()));
      }
      return;
    case ExactFreeMotion::Kind::elliptic:
      break;
  }
  if (!std::isfinite(motion.period_s())) {
    notes.push_back("on the separatrix (k'^2 = 0): w approaches the intermediate axis forever");
    return;
  }
  notes.push_back(
      fmt::format("w(t) is periodic: period {:.10g} s (k'^2 = 1 - k^2 = {:.6g}); its "
                  "component along e2 changes sign every {:.10g} s",
                  motion.period_s(), motion.kc2(), motion.period_s() / 2));
}

void describe(const ExactHeavyTop& top, std::vector<std::string>& notes) {
  constexpr double kDeg = 180.0 / M_PI;
  switch (top.kind()) {
    case ExactHeavyTop::Kind::sleeping:
      notes.push_back("the axle stays vertical (a sleeping top): the body spins about it");
      return;
    case ExactHeavyTop::Kind::steady:
      notes.push_back(fmt::format("steady precession at theta = {:.10g} deg",
                                  top.nutation().theta_min * kDeg));
      return;
    case ExactHeavyTop::Kind::nutating:
      break;
  }
  notes.push_back(fmt::format(
      "theta nods between {:.10g} and {:.10g} deg with period {:.10g} s (elliptic parameter "
      "k^2 = {:.6g})",
      top.nutation().theta_min * kDeg, top.nutation().theta_max * kDeg, top.nutation_period_s(),
      top.k2()));
  // A limit at a pole: the Euler angles' singularity, which the body does not feel.
  const Nutation& n = top.nutation();
  if (n.through_hanging || n.through_upright) {
    notes.push_back(fmt::format(
        "the axle passes through the vertical ({}): there theta turns back and phi and psi jump "
        "by 180 deg, while the body moves on smoothly",
        n.through_hanging && n.through_upright ? "over the top, upright and hanging down"
        : n.through_hanging                    ? "hanging straight down"
                                               : "upright"));
  }
}

template <class Motion>
void sample_exact(const Motion& motion, const std::vector<double>& times, SimulationResult& result,
                  const std::function<void(std::size_t k, const SimState& state)>& at_sample,
                  const std::function<void(double)>& progress) {
  const std::size_t n = times.size();
  // Past this a phase formed in double-double (rate t, reduced by its period) no longer keeps
  // every digit: the samples would print digits the solution does not hold.
  constexpr double kMostPhase = 0x1p50;
  if (n > 0 && times.back() * motion.fastest_phase_rate() > kMostPhase) {
    throw InputError(fmt::format(
        "run.t_end: {:.6g} s is past what the exact solution resolves here: its phases would "
        "pass 2^50 (1.1e15) rad, where their digits start to go; at most {:.3g} s for this scene",
        times.back(), kMostPhase / motion.fastest_phase_rate()));
  }
  describe(motion, result.notes);
  for (std::size_t k = 0; k < n; ++k) {
    throw_if_interrupted();
    const FreeBodyState st = motion.at(times[k]);
    at_sample(k, {st.m_B, st.q_BtoS});
    report(progress, k, n);
  }
  result.cost_label = "evaluations of the solution";
  result.cost += static_cast<std::int64_t>(n);
}
}  // namespace

void propagate_each(const SceneSetup& s, const MethodChoice& choice,
                    const std::vector<double>& times, SimulationResult& result,
                    const std::function<void(std::size_t k, const SimState& state)>& at_sample,
                    const std::function<void(double)>& progress) {
  const std::size_t n = times.size();
  switch (choice.method) {
    case SimMethod::closed_form:
    case SimMethod::exact: {
      if (const auto top = exact_heavy_top(s)) {
        sample_exact(ExactHeavyTop(*top, s.m0_P, s.q0_PtoS), times, result, at_sample, progress);
      } else {
        sample_exact(ExactFreeMotion(s.model.I_P, s.m0_P, s.q0_PtoS), times, result, at_sample,
                     progress);
      }
      return;
    }
    case SimMethod::split2:
    case SimMethod::split4: {
      const FreeBody body{s.model.I_P};
      FreeBodyState st{s.m0_P, s.q0_PtoS};
      const auto order =
          choice.method == SimMethod::split2 ? SplittingOrder::strang2 : SplittingOrder::yoshida4;
      double t = 0.0;
      std::int64_t subflows = 0;
      for (std::size_t k = 0; k < n; ++k) {
        throw_if_interrupted();
        const double span = times[k] - t;
        if (span > 0.0) {
          const auto steps =
              static_cast<std::int64_t>(std::ceil(span / choice.step_s * (1 - kStepCountSlack)));
          split_free_body(body, st, span / static_cast<double>(steps), steps, order, &subflows);
          result.steps += steps;
          t = times[k];
        }
        at_sample(k, {st.m_B, st.q_BtoS});
        report(progress, k, n);
      }
      result.cost_label = "sub-flows";
      result.cost += subflows;
      return;
    }
    default:
      break;
  }
  const RkMethod rk = runge_kutta_of(choice.method).value();  // the others returned above
  const double tol_or_step = rk == RkMethod::rk4 ? choice.step_s : s.tolerance;
  RungeKutta integrator(s.model, rk, tol_or_step, momentum_scale(s));
  // A brake acts until its spin stops, then no more: the run is split there, and continues
  // torque-free with the spin about the brake's axis exactly zero (it never turns backwards).
  RigidBodyModel released = s.model;
  released.torque = false;
  RungeKutta after_stop(released, rk, tol_or_step, momentum_scale(s));
  const auto budget = static_cast<std::int64_t>(std::min(s.max_evaluations, 9e18));
  integrator.set_evaluation_limit(budget);
  after_stop.set_evaluation_limit(budget);
  const double stop = s.brake_stops_s.value_or(INFINITY);
  // The samples before the stop, from one run (dense output where the method has it: the
  // sample times do not shorten its steps), then the brake's release, then the rest.
  const auto before = static_cast<std::size_t>(
      std::lower_bound(times.begin(), times.end(), stop) - times.begin());
  State7 y = pack(s.m0_P, s.q0_PtoS);
  const auto emit_from = [&](std::size_t first) {
    return [&, first](std::size_t k, const State7& state) {
      at_sample(first + k, {momentum_of(state), attitude_of(state)});
      report(progress, first + k, n);
    };
  };
  const std::span<const double> all(times);
  integrator.sample(y, 0.0, all.first(before), emit_from(0));
  if (before < n) {
    const double t = before > 0 ? times[before - 1] : 0.0;
    if (stop > t) integrator.advance(y, t, stop);
    const Vec3 m = momentum_of(y);
    y = pack(m - m.dot(s.brake_axis_P) * s.brake_axis_P, attitude_of(y));
    after_stop.sample(y, stop, all.subspan(before), emit_from(before));
  }
  result.cost_label = "right-hand-side evaluations";
  for (const RungeKutta* r : {&integrator, &after_stop}) {
    result.cost += r->cost().rhs_evals;
    result.steps += r->cost().steps;
    result.rejected += r->cost().rejected;
  }
}

std::vector<SimState> propagate(const SceneSetup& s, const MethodChoice& choice,
                                const std::vector<double>& times, SimulationResult& result,
                                const std::function<void(double)>& progress) {
  std::vector<SimState> out;
  out.reserve(times.size());
  propagate_each(
      s, choice, times, result, [&](std::size_t, const SimState& st) { out.push_back(st); },
      progress);
  return out;
}

SimulationResult simulate(const SceneSetup& s, const MethodChoice& choice,
                          const std::function<void(double)>& progress) {
  SimulationResult r;
  r.choice = choice;
  std::vector<double> times(static_cast<std::size_t>(s.samples));
  for (std::size_t k = 0; k < times.size(); ++k) {
    times[k] = k + 1 == times.size() ? s.t_end : s.t_end * static_cast<double>(k) / (s.samples - 1);
  }
  const auto start = std::chrono::steady_clock::now();
  // An integrator's run is followed by a second one (the error estimate): each is half the bar.
  const bool exact = choice.method == SimMethod::closed_form || choice.method == SimMethod::exact;
  const auto first_half = [&](double f) {
    if (progress) progress(exact ? f : 0.5 * f);
  };
  const std::vector<ConservedQuantity> conserved = conserved_quantities(s);
  std::vector<Vec3> at_start;
  for (const auto& q : conserved) {
    at_start.push_back(q.value({s.m0_P, s.q0_PtoS}, 0.0));
    r.invariants.push_back({q.name, q.unit, 0.0, q.scale});
  }
  const Columns columns = output_columns(s, conserved);
  r.columns = columns.names;
  r.units = columns.units;
  const auto make_row = [&](const SimState& state, std::size_t k, bool track) {
    std::vector<double> errors;
    for (std::size_t i = 0; i < conserved.size(); ++i) {
      const double e = (conserved[i].value(state, times[k]) - at_start[i]).cwiseAbs().maxCoeff();
      if (track) r.invariants[i].max_abs = std::max(r.invariants[i].max_abs, e);
      errors.push_back(e);
    }
    return output_row(s, state, times[k], errors);
  };
  // Each sample becomes a row as it is computed (the rows go to a file past a few MiB): memory
  // does not grow with the number of samples.
  propagate_each(
      s, choice, times, r,
      [&](std::size_t k, const SimState& state) { r.rows.append(make_row(state, k, true)); },
      first_half);
  r.run_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // How far to trust the samples: a second, more accurate run, compared column by column as
  // its samples arrive.
  if (exact) {
    r.error_reference = "exact";
    return r;
  }
  MethodChoice ref;
  if (s.model.torque_free() || exact_heavy_top(s)) {
    ref.method = SimMethod::exact;
    r.error_reference = "the exact solution";
  } else {
    const double tol = reference_tolerance(s);
    // Nothing tighter: a pair of order 8 or 9 already at the smallest tolerance a scene may ask.
    const bool high_order = choice.method == SimMethod::rkf78 ||
                            choice.method == SimMethod::dop853 || choice.method == SimMethod::vern9;
    if (high_order && tol >= s.tolerance) return r;
    ref.method = SimMethod::rkf78;
    r.error_reference = fmt::format("rkf78 at tolerance {:.0e}", tol);
  }
  SceneSetup tight = s;
  tight.tolerance = reference_tolerance(s);
  SimulationResult rc;
  const auto second_half = [&](double f) {
    if (progress) progress(0.5 + 0.5 * f);
  };
  std::vector<double> scale(r.columns.size(), 0.0), diff(r.columns.size(), 0.0);
  propagate_each(
      tight, ref, times, rc,
      [&](std::size_t k, const SimState& state) {
        const std::vector<double> ref_row = make_row(state, k, false);
        const std::vector<double> row = r.rows[k];
        for (std::size_t j = 1; j < r.columns.size(); ++j) {
          scale[j] = std::max(scale[j], std::abs(ref_row[j]));
          double d = row[j] - ref_row[j];
          if (r.units[j] == "rad") d = std::remainder(d, 2 * M_PI);  // angles wrap at +-pi
          diff[j] = std::max(diff[j], std::abs(d));
        }
      },
      second_half);
  r.estimate_cost = rc.cost;
  double worst = 0.0;
  for (std::size_t j = 1; j < r.columns.size(); ++j) {
    if (r.columns[j].rfind("err_", 0) == 0) continue;
    if (scale[j] > 0.0) worst = std::max(worst, diff[j] / scale[j]);
  }
  r.error_estimate = worst;
  return r;
}

}  // namespace wobble
