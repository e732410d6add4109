#include "simulate/method.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/exact_heavy_top.hpp"
#include "core/input_error.hpp"
#include "core/principal_axes.hpp"

namespace wobble {

const std::vector<std::pair<std::string, std::string>>& simulation_method_names() {
  static const std::vector<std::pair<std::string, std::string>> names{
      {"closed_form", "torque-free axially symmetric body: exact formulas, no integration"},
      {"exact",
       "torque-free body or heavy symmetric top: elliptic functions, any t without stepping"},
      {"rk4", "classical Runge-Kutta, fixed step (order 4)"},
      {"dopri5", "Dormand-Prince 5(4), adaptive"},
      {"rkf78", "Fehlberg 7(8), adaptive"},
      {"dop853", "Dormand-Prince 8(5,3), adaptive, samples from its dense output"},
      {"vern9", "Verner 9(8), adaptive (order 9: the cheapest pair at equal error from 1e-8 down)"},
      {"split2", "Lie-Poisson splitting, Strang (order 2), torque-free"},
      {"split4", "Lie-Poisson splitting, Yoshida composition (order 4), torque-free"},
  };
  return names;
}

std::string name_of(SimMethod m) {
  return simulation_method_names()[static_cast<std::size_t>(m)].first;
}

std::optional<RkMethod> runge_kutta_of(SimMethod m) {
  switch (m) {
    case SimMethod::rk4:
      return RkMethod::rk4;
    case SimMethod::dopri5:
      return RkMethod::dopri5;
    case SimMethod::rkf78:
      return RkMethod::rkf78;
    case SimMethod::dop853:
      return RkMethod::dop853;
    case SimMethod::vern9:
      return RkMethod::vern9;
    case SimMethod::closed_form:
    case SimMethod::exact:
    case SimMethod::split2:
    case SimMethod::split4:
      break;
  }
  return std::nullopt;
}

namespace {
// The axle's tilt from the vertical at t = 0 (sin theta0).
double axle_tilt(const SceneSetup& s) {
  const Vec3 e3 = s.q0_PtoS * Vec3::UnitZ();
  return std::hypot(e3.x(), e3.y());
}
// A tilt below about 1.5e-154 rad, but not 0: the closed form works with sin^2(theta), which
// underflows to 0 there (a steady precession at theta = 0 came out as NaN). An integrator
// follows such a start (a top that cannot sleep falls from it).
bool tilt_underflows(double tilt) { return tilt > 0.0 && tilt * tilt == 0.0; }
}  // namespace

std::optional<HeavyTop> exact_heavy_top(const SceneSetup& s) {
  const RigidBodyModel& m = s.model;
  if (!m.gravity || m.torque) return std::nullopt;
  const double eps = std::numeric_limits<double>::epsilon();
  const Vec3& I = m.I_P;
  if (std::abs(I[0] - I[1]) > kDegeneracyEps * eps * I.maxCoeff()) return std::nullopt;
  const Vec3& d = m.d_P_m;
  if (!(d.z() > 0.0) || std::hypot(d.x(), d.y()) > kDegeneracyEps * eps * d.norm())
    return std::nullopt;
  const double tilt = axle_tilt(s);
  if (tilt == 0.0 && (s.m0_P.x() != 0.0 || s.m0_P.y() != 0.0)) return std::nullopt;
  if (tilt_underflows(tilt)) return std::nullopt;
  return HeavyTop{m.mass_kg, d.z(), -m.g_S.z(), 0.5 * (I[0] + I[1]), I[2]};
}

double exact_heavy_top_rounding(const SceneSetup& s) {
  const auto top = exact_heavy_top(s);
  if (!top) return INFINITY;
  // What grows with t is formed in double-double, so the rounding does not grow with the run
  // (hard case 14, to 1e6 s): the reduced phase's rounding is a time error of about eps T / 2
  // (T the nutation period), which the fastest Euler rate turns into the attitude and, twice,
  // into the rates; and a few eps from composing the rotations.
  const ExactHeavyTop motion(*top, s.m0_P, s.q0_PtoS);
  const double period = motion.nutation_period_s();
  const double rate_term = std::isfinite(period) ? 2.0 * motion.euler_rate_bound() * period : 0.0;
  return std::numeric_limits<double>::epsilon() * (16.0 + rate_term);
}

namespace {
int order(SimMethod m) {
  switch (m) {
    case SimMethod::rk4:
      return 4;
    case SimMethod::split2:
      return 2;
    case SimMethod::split4:
      return 4;
    default:
      return 0;
  }
}

// Fixed step from the tolerance when the scene gives none: the local error of an order-p
// method is ~ (h Omega)^(p+1), so h = tol^(1/p) / Omega keeps the global error near tol over
// a few turns. Omega is the fastest rate in the scene: the spin, and for a heavy top the
// pendulum rate sqrt(M g d / I1). A rule of thumb, said so in the header.
double fastest_rate(const SceneSetup& s) {
  double rate = s.model.omega_P(s.m0_P).norm();
  if (s.model.gravity) {
    rate = std::max(rate, std::sqrt(s.model.mass_kg * s.model.g_S.norm() * s.model.d_P_m.norm() /
                                    s.model.I_P.minCoeff()));
  }
  if (s.model.torque) {
    rate = std::max(rate, std::sqrt(s.model.torque_Nm.norm() / s.model.I_P.minCoeff()));
  }
  return rate;
}

double default_step(const SceneSetup& s, int p) {
  return std::min(s.t_end, std::pow(s.tolerance, 1.0 / p) / std::max(fastest_rate(s), 1e-300));
}

// The rate a run reaches: a constant torque spins the body up by at most its size times t_end
// over the smallest moment; gravity conserves the energy, so T <= T(0) + 2 M g d bounds it.
double rate_reached(const SceneSetup& s) {
  const RigidBodyModel& m = s.model;
  double rate = fastest_rate(s);
  if (m.gravity) {
    const double T_max = m.kinetic(s.m0_P) + 2 * m.mass_kg * m.g_S.stableNorm() * m.d_P_m.stableNorm();
    rate = std::max(rate, std::sqrt(2 * T_max / m.I_P.minCoeff()));
  }
  if (m.torque) rate += m.torque_Nm.stableNorm() * s.t_end / m.I_P.minCoeff();
  return rate;
}

// Evaluations of an adaptive pair of order p with `stages` new evaluations per step.
double adaptive_evaluations(const SceneSetup& s, double tolerance, int p, int stages) {
  const double steps = 0.1 * rate_reached(s) * s.t_end * std::pow(tolerance, -1.0 / p);
  return std::max(steps, 1.0) * stages;
}
}  // namespace

MethodChoice choose_method(const SceneSetup& s, const std::string& requested,
                           const std::string& field) {
  const bool free = s.model.torque_free();
  MethodChoice c;
  if (requested == "auto") {
    if (free && s.symmetric) {
      c = {SimMethod::closed_form,
           "torque-free and axially symmetric: closed form, no integration"};
    } else if (free) {
      c = {SimMethod::exact,
           "torque-free: exact solution in Jacobi elliptic functions, no integration"};
    } else if (const double rounding = exact_heavy_top_rounding(s); rounding <= s.tolerance) {
      c = {SimMethod::exact,
           "a heavy symmetric top (gravity alone, pivot on the axle): exact solution in "
           "elliptic functions and integrals, no integration"};
    } else if (std::isfinite(rounding)) {  // a heavy top, but the closed form would round more
      c = {SimMethod::vern9,
           fmt::format("a heavy symmetric top, but the exact solution's Euler angles would "
                       "carry {:.1e} of rounding over the run (their rates grow near the "
                       "vertical), more than the tolerance; Verner 9(8)",
                       rounding)};
    } else {
      c = {SimMethod::vern9,
           "torques present; Verner 9(8), the cheapest pair at equal error from 1e-8 down and "
           "level with the others above (wobble bench, the heavy top P4)"};
    }
  } else {
    const auto& names = simulation_method_names();
    std::size_t i = 0;
    while (i < names.size() && names[i].first != requested) ++i;
    if (i == names.size()) {
      std::string list = "auto";
      for (const auto& n : names) list += ", " + n.first;
      throw InputError(field + ": unknown method '" + requested + "' (expected one of: " + list +
                       ")");
    }
    c.method = static_cast<SimMethod>(i);
    c.reason = "requested";
    const bool needs_free = c.method == SimMethod::closed_form || c.method == SimMethod::exact ||
                            c.method == SimMethod::split2 || c.method == SimMethod::split4;
    const bool heavy_top_exact = c.method == SimMethod::exact && exact_heavy_top(s);
    if (needs_free && !free && !heavy_top_exact) {
      // Why a heavy top is not one the exact solution serves. A top that would be one at rest
      // but starts vertical and moving is refused for its start alone, and told so.
      SceneSetup at_rest = s;
      at_rest.m0_P.x() = 0.0;
      at_rest.m0_P.y() = 0.0;
      const char* why_not_top =
          c.method != SimMethod::exact || !s.model.gravity || s.model.torque ? ""
          : tilt_underflows(axle_tilt(s))
              ? " with the axle within 1.5e-154 rad of the vertical but not on it (the exact "
                "solution squares that tilt, which double precision cannot)"
          : axle_tilt(s) == 0.0 && exact_heavy_top(at_rest)
              ? " with the axle starting vertical and moving (theta is no coordinate of the "
                "exact solution there: start it tilted, a moment later)"
              : " on a body that is no symmetric top pivoted on its axle";
      throw InputError(field + " " + requested +
                       ": applies to torque-free motion only, and this scene has " +
                       (s.model.gravity ? "gravity about a pivot" : "a torque") + why_not_top +
                       "; use rk4, dopri5, rkf78, dop853, vern9 or auto");
    }
    if (c.method == SimMethod::closed_form && !s.symmetric) {
      throw InputError(fmt::format(
          "{} closed_form: the body is not axially symmetric (moments {:.10g}, {:.10g}, "
          "{:.10g} kg m^2); use exact or auto",
          field, s.moments[0], s.moments[1], s.moments[2]));
    }
  }
  if (const int p = order(c.method); p > 0) {
    c.step_s = s.step ? *s.step : default_step(s, p);
    if (!s.step)
      c.reason += fmt::format("; step tol^(1/{}) / rate = {:.3g} s (rule of thumb)", p, c.step_s);
  }
  return c;
}

double reference_tolerance(const SceneSetup& s) {
  constexpr double kTighter = 100;
  return std::max(s.tolerance / kTighter, kMinSceneTolerance);
}

WorkEstimate estimate_work(const SceneSetup& s, const MethodChoice& c) {
  const double samples = s.samples;
  const bool free = s.model.torque_free();
  const double tight = reference_tolerance(s);
  // The error estimate's run: the exact solution when there is one, else Fehlberg 7(8) tighter.
  const double reference =
      free || exact_heavy_top(s) ? samples : adaptive_evaluations(s, tight, 8, 13);
  const double rate = rate_reached(s);
  switch (c.method) {
    case SimMethod::closed_form:
    case SimMethod::exact:
      return {samples, fmt::format("{} samples of the solution", s.samples)};
    case SimMethod::rk4:
    case SimMethod::split2:
    case SimMethod::split4: {
      const double per_step = c.method == SimMethod::rk4 ? 4 : c.method == SimMethod::split2 ? 3 : 9;
      const double steps = std::ceil(s.t_end / c.step_s);
      return {steps * per_step + reference,
              fmt::format("{:.3g} steps of {:.3g} s over {:.6g} s", steps, c.step_s, s.t_end)};
    }
    case SimMethod::dopri5:
    case SimMethod::rkf78:
    case SimMethod::dop853:
    case SimMethod::vern9:
      break;
  }
  // New evaluations per step: 6 (Dormand-Prince, first same as last), 13 (Fehlberg), 12 and
  // 3 more for the dense output of a step with samples (DOP853), 16 (Verner, order 9).
  const int stages = c.method == SimMethod::dopri5  ? 6
                     : c.method == SimMethod::rkf78 ? 13
                     : c.method == SimMethod::vern9 ? 16
                                                    : 15;
  return {adaptive_evaluations(s, s.tolerance, order_of(runge_kutta_of(c.method).value()),
                               stages) +
              reference,
          fmt::format("a rate up to {:.3g} rad/s over {:.6g} s at tolerance {:.0e}", rate, s.t_end,
                      s.tolerance)};
}

void require_within_budget(const WorkEstimate& w, double limit, const std::string& option) {
  if (w.evaluations <= limit) return;
  throw InputError(fmt::format(
      "{}: this run needs about {:.2g} evaluations ({}), more than the limit of {:.2g}; "
      "shorten the run (--t-end), loosen --tolerance or lengthen the step, or raise {}",
      option, w.evaluations, w.basis, limit, option));
}

}  // namespace wobble
