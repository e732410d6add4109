#include "simulate/cross_check.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "simulate/problem_scene.hpp"
#include "simulate/simulation.hpp"

namespace wobble {

namespace {
double key_value(const Key& key, const std::string& name) {
  for (const auto& part : key.parts) {
    for (const auto& a : part.answers) {
      if (a.quantity == name) return a.value.data.at(0);
    }
  }
  throw InputError("--cross-check: the key has no answer '" + name + "'");
}

// Accumulated turn of the vectors v(t) about a fixed unit axis n: the sum of the signed angles
// between consecutive projections (each well below pi at this sampling).
double turned(const std::vector<Vec3>& v, const Vec3& n) {
  double total = 0.0;
  for (std::size_t k = 1; k < v.size(); ++k) {
    const Vec3 a = v[k - 1] - v[k - 1].dot(n) * n, b = v[k] - v[k].dot(n) * n;
    total += std::atan2(a.cross(b).dot(n), a.dot(b));
  }
  return total;
}
}  // namespace

CrossCheck cross_check_torque_free(const Problem& problem, const sym::Values& values,
                                   const Key& key) {
  if (problem.solver != "torque_free_symmetric" || !problem.motion) {
    throw InputError("--cross-check: problem " + problem.id +
                     " has no dynamic answers to simulate (only torque-free symmetric tops do)");
  }
  const double max_angle = key_value(key, "max_angle"), t_max = key_value(key, "t_max");
  const double rate_body = key_value(key, "Omega_body_rate");
  const double rate_space = key_value(key, "Omega_space_rate");

  if (!(max_angle >= kSmallestResolvedWobble)) {
    CrossCheck none;
    none.method = "none";
    none.not_compared =
        max_angle == 0.0
            ? "alpha = 0: w lies along the symmetry axis and nothing wobbles; e3 stays on z and "
              "there is no motion to compare (the key's rates are those a small wobble would have)"
            : fmt::format("the wobble ({:.3g} rad) is below what the simulation resolves ({:g} "
                          "rad): its angles would be integration error; cross-check a larger alpha",
                          max_angle, kSmallestResolvedWobble);
    return none;
  }
  // The problem as a scene: w(0) = omega (sin alpha, 0, cos alpha) in the body, body = space.
  Scene scene = *motion_scene(problem);
  scene.t_end = fmt::format("{:.17g}", kCrossCheckSpan * t_max);
  scene.samples = kCrossCheckSamples;
  scene.tolerance = kCrossCheckTolerance;
  scene.outputs = {"e3_space"};
  const SceneSetup s = setup_scene_at(scene, values);
  const MethodChoice choice = choose_method(s, "rkf78");
  std::vector<double> times(static_cast<std::size_t>(s.samples));
  for (std::size_t k = 0; k < times.size(); ++k)
    times[k] = s.t_end * static_cast<double>(k) / static_cast<double>(times.size() - 1);
  SimulationResult cost;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<SimState> states = propagate(s, choice, times, cost);
  CrossCheck out;
  out.simulation_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.rhs_evals = cost.cost;
  out.method = fmt::format("Fehlberg 7(8) at tolerance {:.0e}, {} samples over {:g} t_max",
                           kCrossCheckTolerance, kCrossCheckSamples, kCrossCheckSpan);

  // e3 of the problem (the symmetry axis z of the body) in space, and w in the body.
  const Vec3 e3_P = s.axes_B.transpose() * Vec3::UnitZ();
  std::vector<Vec3> e3_S, w_B;
  std::vector<double> angle;
  for (const auto& st : states) {
    e3_S.push_back(st.q_PtoS * e3_P);
    w_B.push_back(s.axes_B * s.model.omega_P(st.m_P));
    angle.push_back(std::acos(std::clamp(e3_S.back().z(), -1.0, 1.0)));
  }
  std::size_t k = 1;
  for (std::size_t i = 1; i + 1 < angle.size(); ++i) {
    if (angle[i] > angle[k]) k = i;
  }
  // Parabola through (k-1, k, k+1): vertex offset and height.
  const double dt = times[1] - times[0];
  const double y0 = angle[k - 1], y1 = angle[k], y2 = angle[k + 1];
  const double denom = y0 - 2 * y1 + y2;
  const double off = denom != 0.0 ? 0.5 * (y0 - y2) / denom : 0.0;
  const double peak = y1 - 0.25 * (y0 - y2) * off;
  const Vec3 L_S = states.front().q_PtoS * states.front().m_P;
  const double T = times.back();
  out.rows = {
      {"max_angle", "rad", max_angle, peak},
      {"t_max", "s", t_max, times[k] + off * dt},
      {"Omega_body_rate", "rad/s", rate_body, turned(w_B, Vec3::UnitZ()) / T},
      {"Omega_space_rate", "rad/s", rate_space, turned(e3_S, L_S.normalized()) / T},
  };
  return out;
}

}  // namespace wobble
