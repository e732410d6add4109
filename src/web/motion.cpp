#include "web/motion.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "core/exact_free_body.hpp"
#include "problem/values.hpp"
#include "simulate/problem_scene.hpp"
#include "simulate/simulation.hpp"
#include "symbolic/quantity.hpp"

namespace wobble::web {

namespace {
using nlohmann::json;

// Lengths and times: 6 significant digits, far finer than a pixel.
double shown(double x) { return std::stod(fmt::format("{:.6g}", x)); }
// Unit vectors, quaternions, w over |w(0)|, angles: to kDirectionStep, a hundredth of a pixel
// on a 1000-pixel view. Absolute, as a picture's precision is: a wobble of 1e-6 rad shows as
// none, as it does on the screen.
double direction(double x) { return std::round(x / kDirectionStep) * kDirectionStep; }
json vec(const Vec3& v) { return json::array({shown(v.x()), shown(v.y()), shown(v.z())}); }
json unit_vec(const Vec3& v) {
  return json::array({direction(v.x()), direction(v.y()), direction(v.z())});
}
json quat(const Quat& q) {
  return json::array({direction(q.w()), direction(q.x()), direction(q.y()), direction(q.z())});
}

// The body as drawn, relative to the turning point, in B.
json body_parts(const Scene& scene, const sym::Values& values, const SceneSetup& s) {
  const Problem& p = scene.model;
  const sym::SymbolTable table = p.symbol_table();
  const GiNaC::lst at = sym::substitution(table, values);
  // Read as the body was built (solvers/inertia_body.cpp): each may carry a unit ("20 cm").
  const auto number = [&](const std::string& text, const std::string& field,
                          const std::string& si_unit) {
    return sym::evaluate(sym::parse_quantity(table, text, field, si_unit), at, field);
  };
  const auto point = [&](const std::array<std::string, 3>& v, const std::string& field) -> Vec3 {
    Vec3 x = Vec3::Zero();
    for (int i = 0; i < 3; ++i) x[i] = number(v[i], field, "m");
    return x - s.turning_point_B;
  };
  json parts = json::array();
  for (std::size_t k = 0; k < p.body.shapes.size(); ++k) {
    const ShapeSpec& shape = p.body.shapes[k];
    const std::string field = fmt::format("body.shapes[{}]", k);
    json sizes = json::array();
    for (const auto& size : shape.sizes) sizes.push_back(shown(number(size, field, "m")));
    parts.push_back({{"shape", shape.shape},
                     {"sizes", sizes},
                     {"center", vec(point(shape.center, field))},
                     {"q", quat(Quat::Identity())}});
  }
  for (std::size_t k = 0; k < p.body.masses.size(); ++k) {
    const MassSpec& m = p.body.masses[k];
    const std::string field = fmt::format("body.masses[{}]", k);
    parts.push_back({{"shape", "point"},
                     {"mass", shown(number(m.mass, field, "kg"))},
                     {"center", vec(point(m.at, field))},
                     {"q", quat(Quat::Identity())}});
  }
  if (parts.empty()) {
    // A tensor given directly: the uniform box with the same moments per unit mass, along the
    // principal axes (I1 = (b^2 + c^2)/12 and cyclically, so a^2 = 6 (I2 + I3 - I1)).
    const Vec3& I = s.moments;
    json sizes = json::array();
    for (int i = 0; i < 3; ++i) {
      const double side2 = 6.0 * (I[(i + 1) % 3] + I[(i + 2) % 3] - I[i]);
      sizes.push_back(shown(std::sqrt(std::max(side2, 0.0))));
    }
    parts.push_back({{"shape", "box"},
                     {"sizes", sizes},
                     {"center", vec(Vec3::Zero())},
                     {"q", quat(Quat(s.axes_B))},
                     {"equivalent", true}});
  }
  return parts;
}

// The span that shows what the motion is about, s.
double natural_span(const SceneSetup& s, bool from_problem, double omega0) {
  const double L = s.m0_P.norm();
  const double turn = 2.0 * std::numbers::pi;
  if (!from_problem) return s.t_end;
  if (s.model.gravity) {
    // About one precession: a fast top precesses at ~ M g l / L; a slow one swings like a
    // pendulum, in ~ 2 pi sqrt(I / (M g l)).
    const double mgl = s.model.mass_kg * s.model.g_S.norm() * s.model.d_P_m.norm();
    const double pendulum = turn * std::sqrt(s.moments.maxCoeff() / mgl);
    return std::min(turn * L / mgl, 10.0 * pendulum);
  }
  if (!(omega0 > 0.0)) return 1.0;
  if (s.symmetric) {
    // Two turns of the body cone about the space cone: the space precession |L| / I_perp. The
    // moments ascend, so the middle one is one of the equal pair.
    return 2.0 * turn * s.moments[1] / L;
  }
  const ExactFreeMotion free(s.moments, s.m0_P, s.q0_PtoS);
  if (std::isfinite(free.period_s())) return 2.0 * free.period_s();
  return 4.0 * turn / omega0;
}

// The largest turn of the attitude between two consecutive states, rad.
double largest_turn(const std::vector<SimState>& states) {
  double largest = 0.0;
  for (std::size_t k = 1; k < states.size(); ++k) {
    largest = std::max(largest, states[k - 1].q_PtoS.angularDistance(states[k].q_PtoS));
  }
  return largest;
}

std::string motion_json(const Scene& scene, const sym::Values& values, bool from_problem) {
  SceneSetup s = setup_scene_at(scene, values);
  const Vec3 w0_P = s.model.omega_P(s.m0_P);
  const double omega0 = w0_P.norm();
  // Two significant digits, rounded up: the span is "about two precessions", and does not
  // carry a period to all its digits.
  double span = natural_span(s, from_problem, omega0);
  if (from_problem) {
    const double unit = std::pow(10.0, std::floor(std::log10(span)) - 1);
    span = std::ceil(span / unit) * unit;
  }
  // Samples for |w(0)|; |w| changes along the motion (an asymmetric body's, a heavy top's), so
  // the run is sampled again, finer, if a step turned further than allowed.
  int samples = std::clamp(static_cast<int>(std::ceil(span * omega0 / kMaxTurnPerSample)) + 1,
                           kMinSamples, kMaxSamples);
  if ((samples - 1) * kMaxTurnPerSample < span * omega0) {
    span = (samples - 1) * kMaxTurnPerSample / omega0;
  }
  s.t_end = span;
  const MethodChoice choice = choose_method(s, from_problem ? "auto" : s.method);
  std::vector<double> times;
  std::vector<SimState> states;
  for (int round = 0; round < 4; ++round) {
    times.resize(static_cast<std::size_t>(samples));
    for (int k = 0; k < samples; ++k) times[k] = span * k / (samples - 1);
    SimulationResult cost;
    s.samples = samples;
    states = propagate(s, choice, times, cost);
    const double turn = largest_turn(states);
    if (turn <= kMaxTurnPerSample) break;
    const double finer = std::ceil((samples - 1) * turn / kMaxTurnPerSample * 1.05);
    if (finer + 1 > kMaxSamples) {
      // As many samples as allowed, over the part of the run they cover at the allowed turn.
      span *= (kMaxSamples - 1) / finer;
      samples = kMaxSamples;
    } else {
      samples = static_cast<int>(finer) + 1;
    }
  }
  if (largest_turn(states) > kMaxTurnPerSample) {
    throw InputError(fmt::format("{}: the motion turns too fast to be shown ({:.3g} rad between "
                                 "samples)", s.id, largest_turn(states)));
  }

  const Quat q_BtoP(Mat3(s.axes_B.transpose()));
  const double w_scale = omega0 > 0.0 ? omega0 : 1.0;
  json t = json::array(), q = json::array(), w = json::array(), L = json::array();
  for (std::size_t k = 0; k < states.size(); ++k) {
    const SimState& st = states[k];
    t.push_back(shown(times[k]));
    q.push_back(quat((st.q_PtoS * q_BtoP).normalized()));
    w.push_back(unit_vec(s.axes_B * s.model.omega_P(st.m_P) / w_scale));
    const Vec3 L_S = st.q_PtoS * st.m_P;
    L.push_back(unit_vec(L_S.norm() > 0.0 ? Vec3(L_S.normalized()) : Vec3::Zero()));
  }
  json out = {{"id", s.id},
              {"title", s.title},
              {"description", s.description},
              {"method", name_of(choice.method)},
              {"method_reason", choice.reason},
              {"turning_point", s.turning_point},
              {"parts", body_parts(scene, values, s)},
              {"t", t},
              {"q_BtoS", q},
              {"w_B", w},
              {"L_dir_S", L},
              {"gravity", s.model.gravity}};
  if (from_problem && s.symmetric && !s.model.gravity && omega0 > 0.0) {
    // The body cone (w about e3 in the body) rolls on the space cone (w about L in space).
    const Vec3 e3_B = Vec3::UnitZ();
    const Vec3 w0_B = s.axes_B * w0_P, L0_S = s.q0_PtoS * s.m0_P;
    const Vec3 w0_S = s.q0_BtoS * w0_B;
    out["cones"] = {
        {"body_axis_B", unit_vec(e3_B)},
        {"body_half_angle", direction(std::atan2(e3_B.cross(w0_B).norm(), e3_B.dot(w0_B)))},
        {"space_axis_S", unit_vec(L0_S.normalized())},
        {"space_half_angle", direction(std::atan2(L0_S.cross(w0_S).norm(), L0_S.dot(w0_S)))}};
  }
  return out.dump();
}
}  // namespace

bool has_motion(const Problem& problem) { return has_motion_scene(problem); }

std::string problem_motion_json(const Problem& problem,
                                const std::vector<std::string>& assignments) {
  const auto scene = motion_scene(problem);
  if (!scene) {
    throw InputError(fmt::format("problem {} has no motion to show (its solver, {}, answers "
                                 "without one)",
                                 problem.id, problem.solver));
  }
  return motion_json(*scene, parameter_values(problem, assignments), true);
}

std::string scene_motion_json(const Scene& scene) {
  return motion_json(scene, parameter_values(scene.model, {}), false);
}

}  // namespace wobble::web
