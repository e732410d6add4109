#include "simulate/scene_setup.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/euler_angles.hpp"
#include "core/principal_axes.hpp"
#include "problem/field_lines.hpp"
#include "problem/values.hpp"
#include "solvers/inertia_body.hpp"
#include "symbolic/quantity.hpp"

namespace wobble {

namespace {
struct Eval {
  const BodyContext& ctx;
  // A quantity in `si_unit` ("s", "rad/s", "m/s^2"; "rad" for an angle), as
  // symbolic/quantity.hpp reads it: "2*pi/omega", "500 ms", "1432 rpm", "30°".
  double quantity(const std::string& text, const std::string& field,
                  const std::string& si_unit) const {
    return sym::evaluate(sym::parse_quantity(ctx.table, text, field, si_unit), ctx.exact.at, field);
  }
  Vec3 vec(const Expr3& v, const std::string& field, const std::string& si_unit) const {
    Vec3 out;
    for (int i = 0; i < 3; ++i)
      out[i] = quantity(v[i], field + "[" + std::to_string(i) + "]", si_unit);
    return out;
  }
  double positive(const std::string& text, const std::string& field,
                  const std::string& si_unit) const {
    const double v = quantity(text, field, si_unit);
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw InputError(fmt::format("{}: \"{}\" is {:.10g} {}; it must be finite and > 0", field,
                                   text, v, si_unit));
    }
    return v;
  }
};

// How far from a rotation an input may be: it is typed with ~15 digits, so 1e-12 accepts
// rounded entries (a quaternion (0.7071067811865476, ...) ) and refuses mistakes.
constexpr double kUnitTolerance = 1e-12;

// An orientation's angle beyond a whole turn is no orientation anyone writes on purpose; it is
// nearly always degrees written as a bare number, which is radians ("30" is 30 rad, and the body
// would start at 1.42 rad to the vertical with no word said).
void refuse_more_than_a_turn(const std::string& text, double angle_rad, const std::string& field) {
  constexpr double kTurn = 2.0 * M_PI * (1.0 + 1e-12);  // 2 pi as written, rounded, is a turn
  if (std::abs(angle_rad) <= kTurn) return;
  const std::string hint = degrees_meant_hint(text, true, "\"" + text + "deg\"");
  throw InputError(fmt::format("{}: \"{}\" is {:.10g} rad, more than a turn{}", field, text,
                               angle_rad, hint.empty() ? "; give the angle within one" : hint));
}

Quat initial_orientation(const Scene& scene, const Eval& ev) {
  const OrientationSpec& o = scene.orientation;
  switch (o.kind) {
    case OrientationSpec::Kind::identity:
      return Quat::Identity();
    case OrientationSpec::Kind::quaternion: {
      double q[4];
      for (int i = 0; i < 4; ++i)
        q[i] = ev.quantity(o.quaternion[i], "initial.quaternion[" + std::to_string(i) + "]", "");
      const Quat out(q[0], q[1], q[2], q[3]);
      if (std::abs(out.norm() - 1.0) > kUnitTolerance) {
        throw InputError(fmt::format(
            "initial.quaternion: ({}, {}, {}, {}) has norm {:.17g}; it must be a unit quaternion",
            q[0], q[1], q[2], q[3], out.norm()));
      }
      return out.normalized();
    }
    case OrientationSpec::Kind::matrix: {
      Mat3 R;
      for (int i = 0; i < 3; ++i)
        R.row(i) = ev.vec(o.matrix[i], "initial.matrix[" + std::to_string(i) + "]", "").transpose();
      const double off = (R.transpose() * R - Mat3::Identity()).cwiseAbs().maxCoeff();
      if (off > kUnitTolerance || R.determinant() < 0) {
        throw InputError(fmt::format(
            "initial.matrix: not a rotation (|R^T R - 1| = {:.3g}, det = {:.6g}); rows must be "
            "orthonormal and right-handed",
            off, R.determinant()));
      }
      return Quat(R).normalized();
    }
    case OrientationSpec::Kind::euler: {
      Vec3 a;
      for (int i = 0; i < 3; ++i) {
        const std::string field = "initial.euler[" + std::to_string(i) + "]";
        a[i] = ev.quantity(o.euler[i], field, "rad");
        refuse_more_than_a_turn(o.euler[i], a[i], field);
      }
      return Quat(rotation_from_euler(a, euler_convention(o.convention))).normalized();
    }
  }
  return Quat::Identity();
}
}  // namespace

SceneSetup setup_scene(const Scene& scene, const std::vector<std::string>& assignments) {
  return setup_scene_at(scene, parameter_values(scene.model, assignments));
}

namespace {
// The brake's axis must be a symmetry axis (then w along it falls linearly and stops at a time
// known exactly); the torque must oppose the spin about it.
void set_brake(SceneSetup& s, const PrincipalAxes& pa) {
  const Vec3 tau_P = s.model.torque_Nm;
  const double tau = tau_P.norm();
  if (!(tau > 0.0)) return;  // no torque: nothing brakes
  const Vec3 a = tau_P / tau;
  int axis = -1;
  for (int k = 0; k < 3; ++k) {
    // Along a principal axis up to the rounding of the axes (a few eps; far below any tilt a
    // scene would give on purpose).
    constexpr double kAlongAxis = 1e-12;
    if (std::abs(std::abs(a[k]) - 1.0) <= kAlongAxis) axis = k;
  }
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  const double tolerance = pa.degeneracy_tolerance;
  if (axis < 0 || std::abs(pa.moments[i] - pa.moments[j]) > tolerance) {
    throw InputError(
        "effects.torque.brake: a brake acts about a symmetry axis of the body (the other two "
        "moments equal), so that its spin stops at a time known exactly; this torque is not "
        "along one");
  }
  const double w_a = s.m0_P[axis] / pa.moments[axis];
  if (w_a * tau_P[axis] > 0.0) {
    throw InputError(fmt::format(
        "effects.torque.brake: a brake opposes the spin about its axis; here it would speed up "
        "the spin ({:.6g} rad/s): give the torque the other sign",
        w_a));
  }
  s.brake_axis_P = Vec3::Zero();
  s.brake_axis_P[axis] = 1.0;
  s.brake_stops_s = pa.moments[axis] * std::abs(w_a) / tau;
  s.effects.back() += fmt::format(", a brake: the spin about its axis stops at t = {:.10g} s",
                                  *s.brake_stops_s);
}
}  // namespace

namespace {
// What a run reaches must stay inside double precision with room for the squares the energy
// and the integrator's error norm take: |m| grows at most by the torques' size times t_end, the
// energy is at most |m|^2 / (2 I_min) plus the potential's range. Norms by stableNorm: a torque
// of 1e200 must not overflow in the check itself.
constexpr double kMaxEnergyJ = 1e280, kMaxMomentum = 1e150;

std::string size_text(double x) {
  return std::isfinite(x) ? fmt::format("{:.3g}", x) : "more than 1e308";
}

void check_ranges(const SceneSetup& s) {
  const RigidBodyModel& m = s.model;
  const double I_min = m.I_P.minCoeff();
  const double pull = m.gravity ? m.mass_kg * m.g_S.stableNorm() * m.d_P_m.stableNorm() : 0.0;
  const double torque = (m.torque ? m.torque_Nm.stableNorm() : 0.0) + pull;
  const double L_max = s.m0_P.stableNorm() + torque * s.t_end;
  const double E_max = L_max / I_min * L_max / 2 + 2 * pull;
  // |L|^2 is taken too (|L| conserved, the error norm): L itself must stay below 1e150.
  if (!(E_max < kMaxEnergyJ) || !(L_max < kMaxMomentum)) {
    // Beyond already at the start: the spin's doing (or the body's size), whatever the effects.
    const double L0 = s.m0_P.stableNorm(), E0 = L0 / I_min * L0 / 2;
    if (!(E0 < kMaxEnergyJ) || !(L0 < kMaxMomentum)) {
      throw InputError(fmt::format(
          "initial.omega: at the start the angular momentum is {} kg m^2/s and the energy {} J, "
          "beyond what double precision holds (about 1e308 for the squares taken); scale the "
          "values down",
          size_text(L0), size_text(E0)));
    }
    const std::string field = m.torque ? "effects.torque.value" : "effects.gravity";
    throw InputError(fmt::format(
        "{}: over the run (t_end = {:.6g} s) the angular momentum reaches {} kg m^2/s and the "
        "energy {} J, beyond what double precision holds (about 1e308 for the squares "
        "taken); scale the values down or shorten the run",
        field, s.t_end, size_text(L_max), size_text(E_max)));
  }
  // A component of w(0) whose square underflows: double precision cannot follow its growth
  // (a wobble of 1e-300 next to a spin of 1).
  // Near the square root of double's smallest normal number (1.5e-154), with a margin for the
  // moments and rates that multiply the square: a smaller share squares to nothing.
  constexpr double smallest_share = 1e-150;
  const double size = s.m0_P.stableNorm();
  for (int i = 0; i < 3; ++i) {
    const double part = std::abs(s.m0_P[i]);
    if (part > 0.0 && part < smallest_share * size) {
      throw InputError(fmt::format(
          "initial.omega: along principal axis {} it is {:.3g} of its size: too small for double "
          "precision to follow (its square underflows); give 0 or at least {:.2g} of the spin",
          i + 1, part / size, smallest_share));
    }
  }
}
}  // namespace

namespace {
SceneSetup set_up(const Scene& scene, const sym::Values& values) {
  const BodyContext ctx(scene.model, values);
  const Eval ev{ctx};
  SceneSetup s;
  s.id = scene.model.id;
  s.title = scene.model.title;
  s.description = scene.model.statement;
  s.has_mass = ctx.body.has_mass;
  const MassProperties& mp = ctx.body.numeric;
  s.mass_kg = mp.mass_kg;
  if ((scene.gravity || scene.free_flight) && !s.has_mass) {
    throw InputError(std::string("effects.") + (scene.gravity ? "gravity" : "free_flight") +
                     ": needs the body's mass and centre of mass; give masses or shapes, not a "
                     "tensor");
  }
  Mat3 I_turn = mp.I_O;
  s.turning_point = "origin O";
  if (scene.gravity) {
    s.turning_point_B = ev.vec(scene.gravity->pivot, "effects.gravity.pivot", "m");
    s.turning_point = "pivot";
    I_turn = shift_from_cm(shift_to_cm(mp.I_O, mp.mass_kg, -mp.r_cm_m), mp.mass_kg,
                           s.turning_point_B - mp.r_cm_m);
  } else if (s.has_mass) {
    s.turning_point_B = mp.r_cm_m;
    s.turning_point = "centre of mass";
    I_turn = shift_to_cm(mp.I_O, mp.mass_kg, -mp.r_cm_m);
  }
  if (!I_turn.allFinite()) {
    throw InputError(fmt::format(
        "body: its inertia tensor about the {} leaves double precision's range (entries beyond "
        "1e308 kg m^2); scale the sizes or masses down",
        s.turning_point));
  }
  PrincipalAxes pa = principal_axes(I_turn);
  if (scene.gravity && pa.degeneracy == Degeneracy::pair23) {
    // A top: its unique axis (the axle, the smallest moment about the pivot) is e3, as in the
    // heavy-top problem, not e1. A cyclic turn of the columns keeps the frame right-handed.
    pa.moments = Vec3(pa.moments[1], pa.moments[2], pa.moments[0]);
    pa.axes = (Mat3() << pa.axes.col(1), pa.axes.col(2), pa.axes.col(0)).finished();
    s.symmetry_axis_last = true;
  }
  const bool unique_axis_last =
      pa.degeneracy == Degeneracy::pair12 || pa.degeneracy == Degeneracy::pair23;
  if (scene.gravity && unique_axis_last &&
      pa.axes.col(2).dot(mp.r_cm_m - s.turning_point_B) < 0.0) {
    // A top's axle e3 points from the pivot toward the centre of mass (d = l e3, l > 0), as in
    // the heavy-top problem and its exact solution: an eigenvector's sign is arbitrary, and a
    // top written with its body below the pivot along the axle (a cone on its apex, which the
    // cone shape puts above its centre) would otherwise be no top the exact solution serves.
    // Turning the frame by pi about e1 keeps it right-handed; I1 = I2 makes e2's sign free.
    // Subtracted from zero, not negated: a zero component stays +0 (the header prints -0).
    pa.axes.col(1) = Vec3::Zero() - pa.axes.col(1);
    pa.axes.col(2) = Vec3::Zero() - pa.axes.col(2);
  }
  require_rotating_body(scene.model.file.string(), pa.moments, "a scene");
  s.moments = pa.moments;
  s.axes_B = pa.axes;
  s.symmetric = pa.degeneracy == Degeneracy::pair12 || pa.degeneracy == Degeneracy::pair23 ||
                pa.degeneracy == Degeneracy::all;
  RigidBodyModel& m = s.model;
  m.I_P = pa.moments;
  if (scene.gravity) {
    m.gravity = true;
    m.mass_kg = mp.mass_kg;
    m.d_P_m = pa.axes.transpose() * (mp.r_cm_m - s.turning_point_B);
    m.g_S = Vec3(0, 0, -ev.positive(scene.gravity->g, "effects.gravity.g", "m/s^2"));
    s.effects.push_back(fmt::format("gravity, g = {:.6g} m/s^2, about a fixed pivot", -m.g_S.z()));
  }
  if (scene.torque) {
    m.torque = true;
    m.torque_in_space = scene.torque->frame == Frame::space;
    const Vec3 tau = ev.vec(scene.torque->value, "effects.torque.value", "N m");
    m.torque_Nm = m.torque_in_space ? tau : Vec3(pa.axes.transpose() * tau);
    s.effects.push_back(fmt::format("constant torque ({:.6g}, {:.6g}, {:.6g}) N m, {} frame",
                                    tau.x(), tau.y(), tau.z(),
                                    m.torque_in_space ? "space" : "body"));
  }
  if (scene.free_flight) {
    s.free_flight = true;
    s.g_S = Vec3(0, 0, -ev.positive(scene.free_flight->g, "effects.free_flight.g", "m/s^2"));
    s.x0_S = ev.vec(scene.free_flight->position, "effects.free_flight.position", "m");
    s.v0_S = ev.vec(scene.free_flight->velocity, "effects.free_flight.velocity", "m/s");
    s.effects.push_back(fmt::format(
        "free flight, g = {:.6g} m/s^2 (no torque about the centre of mass)", -s.g_S.z()));
  }
  if (s.effects.empty()) s.effects.push_back("torque-free");
  m.validate();

  s.q0_BtoS = initial_orientation(scene, ev);
  const Quat q_PtoB(pa.axes);
  s.q0_PtoS = (s.q0_BtoS * q_PtoB).normalized();
  Vec3 w_B = ev.vec(scene.omega, "initial.omega", "rad/s");
  if (scene.omega_frame == Frame::space) w_B = s.q0_BtoS.conjugate() * w_B;
  s.m0_P = pa.moments.cwiseProduct(pa.axes.transpose() * w_B);
  if (!(s.m0_P.norm() > 0.0) && !m.gravity && !m.torque) {
    throw InputError(
        "initial.omega: the body does not turn and nothing acts on it; give a "
        "non-zero angular velocity");
  }
  if (scene.torque && scene.torque->brake) set_brake(s, pa);
  s.t_end = ev.positive(scene.t_end, "run.t_end", "s");
  s.samples = scene.samples;
  s.tolerance = scene.tolerance;
  if (scene.step) s.step = ev.positive(*scene.step, "run.step", "s");
  s.method = scene.method;
  check_ranges(s);
  s.outputs = scene.outputs;
  for (const auto& o : s.outputs) {
    if (o == "com_position" && !s.has_mass) {
      throw InputError("run.outputs: com_position needs the body's mass; give masses or shapes");
    }
  }
  return s;
}
}  // namespace

SceneSetup setup_scene_at(const Scene& scene, const sym::Values& values) {
  try {
    return set_up(scene, values);
  } catch (const InputError&) {
    rethrow_placed_in_file(scene.model);
  }
}

}  // namespace wobble
