#include "simulate/simulation.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <optional>

#include "core/euler_angles.hpp"
#include "core/exact_free_body.hpp"
#include "core/runge_kutta.hpp"

namespace wobble {

namespace {
void report(const std::function<void(double)>& progress, std::size_t k, std::size_t n) {
  if (progress && (n < 100 || k % (n / 100) == 0)) progress(static_cast<double>(k) / n);
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

// The characteristic angular momentum: the initial one, or under gravity the momentum of the
// pendulum rate, so that a top released at rest still has a scale.
double momentum_scale(const SceneSetup& s) {
  double scale = s.m0_P.norm();
  const RigidBodyModel& m = s.model;
  if (m.gravity) {
    scale = std::max(scale, m.I_P.maxCoeff() * std::sqrt(m.mass_kg * m.g_S.norm() * m.d_P_m.norm() /
                                                         m.I_P.minCoeff()));
  }
  if (m.torque) {
    scale = std::max(scale, std::sqrt(m.torque_Nm.norm() * m.I_P.maxCoeff()));
  }
  return scale > 0.0 ? scale : 1.0;
}

// The symmetry axis (index in P) when the body is symmetric about the line pivot -> centre of
// mass, so that p_psi is conserved; -1 otherwise.
int symmetry_axis(const SceneSetup& s) {
  if (!s.symmetric) return -1;
  const Vec3& I = s.model.I_P;
  const int j = I[0] == I[1] ? 2 : (I[1] == I[2] ? 0 : -1);
  if (j < 0) return -1;
  const Vec3 d = s.model.d_P_m;
  const double off = std::hypot(d[(j + 1) % 3], d[(j + 2) % 3]);
  return off <= 1e-12 * std::max(d.norm(), 1e-300) ? j : -1;
}
}  // namespace

std::vector<SimState> propagate(const SceneSetup& s, const MethodChoice& choice,
                                const std::vector<double>& times, SimulationResult& result,
                                const std::function<void(double)>& progress) {
  std::vector<SimState> out;
  out.reserve(times.size());
  const std::size_t n = times.size();
  switch (choice.method) {
    case SimMethod::closed_form:
    case SimMethod::exact: {
      const ExactFreeMotion motion(s.model.I_P, s.m0_P, s.q0_PtoS);
      describe(motion, result.notes);
      for (std::size_t k = 0; k < n; ++k) {
        const FreeBodyState st = motion.at(times[k]);
        out.push_back({st.m_B, st.q_BtoS});
        report(progress, k, n);
      }
      result.cost_label = "evaluations of the solution";
      result.cost += static_cast<std::int64_t>(n);
      return out;
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
        const double span = times[k] - t;
        if (span > 0.0) {
          const auto steps =
              static_cast<std::int64_t>(std::ceil(span / choice.step_s * (1 - 1e-12)));
          split_free_body(body, st, span / static_cast<double>(steps), steps, order, &subflows);
          result.steps += steps;
          t = times[k];
        }
        out.push_back({st.m_B, st.q_BtoS});
        report(progress, k, n);
      }
      result.cost_label = "sub-flows";
      result.cost += subflows;
      return out;
    }
    default:
      break;
  }
  const RkMethod rk = choice.method == SimMethod::rk4      ? RkMethod::rk4
                      : choice.method == SimMethod::dopri5 ? RkMethod::dopri5
                                                           : RkMethod::rkf78;
  const double tol_or_step = rk == RkMethod::rk4 ? choice.step_s : s.tolerance;
  RungeKutta integrator(s.model, rk, tol_or_step, momentum_scale(s));
  State7 y = pack(s.m0_P, s.q0_PtoS);
  double t = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    if (times[k] > t) {
      integrator.advance(y, t, times[k]);
      t = times[k];
    }
    out.push_back({momentum_of(y), attitude_of(y)});
    report(progress, k, n);
  }
  result.cost_label = "right-hand-side evaluations";
  result.cost += integrator.cost().rhs_evals;
  result.steps += integrator.cost().steps;
  result.rejected += integrator.cost().rejected;
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
  const std::vector<SimState> states = propagate(s, choice, times, r, first_half);
  r.run_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const RigidBodyModel& model = s.model;
  const Mat3& A = s.axes_B;  // P -> B
  const double M = s.mass_kg;
  const int sym = model.gravity ? symmetry_axis(s) : -1;
  const double Lscale = momentum_scale(s);

  // Invariants: name, unit, value(state, t), scale.
  struct Inv {
    std::string name, unit;
    std::function<Vec3(const SimState&, double)> value;  // up to 3 components, max-normed
    double scale;
  };
  std::vector<Inv> invs;
  const auto energy = [&](const SimState& st, double) {
    return Vec3(model.kinetic(st.m_P) + model.potential(st.q_PtoS), 0, 0);
  };
  const double E0 = energy({s.m0_P, s.q0_PtoS}, 0)[0];
  if (model.torque_free()) {
    invs.push_back({"rotational_energy", "J", energy, std::abs(E0)});
    invs.push_back({"L_norm", "kg m^2/s",
                    [](const SimState& st, double) { return Vec3(st.m_P.norm(), 0, 0); }, Lscale});
    invs.push_back({"L_space", "kg m^2/s",
                    [](const SimState& st, double) { return Vec3(st.q_PtoS * st.m_P); }, Lscale});
  } else if (model.gravity && !model.torque) {
    const double Escale =
        std::max({std::abs(E0), model.kinetic(s.m0_P), M * model.g_S.norm() * model.d_P_m.norm()});
    invs.push_back({"total_energy", "J", energy, Escale});
    invs.push_back(
        {"p_phi", "kg m^2/s",
         [](const SimState& st, double) { return Vec3(Vec3(st.q_PtoS * st.m_P).z(), 0, 0); },
         Lscale});
    if (sym >= 0) {
      invs.push_back({"p_psi", "kg m^2/s",
                      [sym](const SimState& st, double) { return Vec3(st.m_P[sym], 0, 0); },
                      Lscale});
    }
  } else if (model.torque && model.torque_in_space && !model.gravity) {
    const Vec3 tau = model.torque_Nm;
    invs.push_back(
        {"L_space_minus_tau_t", "kg m^2/s",
         [tau](const SimState& st, double t) { return Vec3(st.q_PtoS * st.m_P - tau * t); },
         Lscale});
  }
  std::vector<Vec3> inv0;
  for (const auto& inv : invs) inv0.push_back(inv.value({s.m0_P, s.q0_PtoS}, 0.0));
  for (const auto& inv : invs) r.invariants.push_back({inv.name, inv.unit, 0.0, inv.scale});

  // Columns.
  r.columns.push_back("t");
  r.units.push_back("s");
  const auto add3 = [&](const std::string& name, const std::string& unit, const char* a = "x",
                        const char* b = "y", const char* c = "z") {
    for (const char* suffix : {a, b, c}) {
      r.columns.push_back(name + "_" + suffix);
      r.units.push_back(unit);
    }
  };
  for (const auto& o : s.outputs) {
    if (o == "omega_body" || o == "omega_space")
      add3(o, "rad/s");
    else if (o == "L_body" || o == "L_space")
      add3(o, "kg m^2/s");
    else if (o == "e1_space" || o == "e2_space" || o == "e3_space")
      add3(o, "1");
    else if (o == "euler_zyz" || o == "euler_zxz")
      add3(o, "rad", "phi", "theta", "psi");
    else if (o == "com_position")
      add3(o, "m");
    else if (o == "invariant_errors") {
      for (const auto& inv : invs) {
        r.columns.push_back("err_" + inv.name);
        r.units.push_back(inv.unit == "J" ? "J" : inv.unit);
      }
    } else {
      r.columns.push_back(o);
      r.units.push_back("J");
    }
  }

  const auto make_rows = [&](const std::vector<SimState>& states_, bool track) {
    std::vector<std::vector<double>> rows;
    for (std::size_t k = 0; k < states_.size(); ++k) {
      const SimState& st = states_[k];
      const double t = times[k];
      const Mat3 R_PtoS = st.q_PtoS.toRotationMatrix();
      const Vec3 w_P = model.omega_P(st.m_P);
      const Vec3 v_S = s.v0_S + s.g_S * t;
      std::vector<double> row{t};
      const auto put = [&](const Vec3& v) { row.insert(row.end(), {v.x(), v.y(), v.z()}); };
      std::vector<double> errs;
      for (std::size_t i = 0; i < invs.size(); ++i) {
        const double e = (invs[i].value(st, t) - inv0[i]).cwiseAbs().maxCoeff();
        if (track) r.invariants[i].max_abs = std::max(r.invariants[i].max_abs, e);
        errs.push_back(e);
      }
      for (const auto& o : s.outputs) {
        if (o == "omega_body")
          put(A * w_P);
        else if (o == "omega_space")
          put(R_PtoS * w_P);
        else if (o == "L_body")
          put(A * st.m_P);
        else if (o == "L_space")
          put(R_PtoS * st.m_P);
        else if (o == "e1_space")
          put(R_PtoS.col(0));
        else if (o == "e2_space")
          put(R_PtoS.col(1));
        else if (o == "e3_space")
          put(R_PtoS.col(2));
        else if (o == "euler_zyz")
          put(euler_from_rotation(R_PtoS * A.transpose(), EulerConvention::zyz));
        else if (o == "euler_zxz")
          put(euler_from_rotation(R_PtoS * A.transpose(), EulerConvention::zxz));
        else if (o == "kinetic_energy" || o == "total_energy") {
          double e = model.kinetic(st.m_P);
          if (s.free_flight) e += 0.5 * M * v_S.squaredNorm();
          if (o == "total_energy") {
            e += model.potential(st.q_PtoS);
            if (s.free_flight) e -= M * s.g_S.dot(s.x0_S + s.v0_S * t + 0.5 * s.g_S * t * t);
          }
          row.push_back(e);
        } else if (o == "com_position") {
          if (s.free_flight)
            put(s.x0_S + s.v0_S * t + 0.5 * s.g_S * t * t);
          else if (model.gravity)
            put(R_PtoS * model.d_P_m);
          else
            put(Vec3::Zero());
        } else if (o == "invariant_errors") {
          row.insert(row.end(), errs.begin(), errs.end());
        }
      }
      rows.push_back(std::move(row));
    }
    return rows;
  };
  r.rows = make_rows(states, true);

  // How far to trust the samples: a second, more accurate run, compared column by column.
  if (exact) {
    r.error_reference = "exact";
    return r;
  }
  MethodChoice ref;
  if (model.torque_free()) {
    ref.method = SimMethod::exact;
    r.error_reference = "the exact solution";
  } else {
    const double tol = std::max(s.tolerance / 100, 1e-14);
    if (choice.method == SimMethod::rkf78 && tol >= s.tolerance) return r;  // nothing tighter
    ref.method = SimMethod::rkf78;
    r.error_reference = fmt::format("rkf78 at tolerance {:.0e}", tol);
  }
  SceneSetup tight = s;
  tight.tolerance = std::max(s.tolerance / 100, 1e-14);
  SimulationResult rc;
  const auto second_half = [&](double f) {
    if (progress) progress(0.5 + 0.5 * f);
  };
  const auto ref_rows = make_rows(propagate(tight, ref, times, rc, second_half), false);
  r.estimate_cost = rc.cost;
  double worst = 0.0;
  for (std::size_t j = 1; j < r.columns.size(); ++j) {
    if (r.columns[j].rfind("err_", 0) == 0) continue;
    double scale = 0.0, diff = 0.0;
    for (std::size_t k = 0; k < r.rows.size(); ++k) {
      scale = std::max(scale, std::abs(ref_rows[k][j]));
      double d = r.rows[k][j] - ref_rows[k][j];
      if (r.units[j] == "rad") d = std::remainder(d, 2 * M_PI);  // angles wrap at +-pi
      diff = std::max(diff, std::abs(d));
    }
    if (scale > 0.0) worst = std::max(worst, diff / scale);
  }
  r.error_estimate = worst;
  return r;
}

}  // namespace wobble
