#pragma once
/// @file
/// A scene with its parameter values applied: everything in numbers, ready to simulate.
///
/// Frames (see problem/scene.hpp): B the frame the body is written in, P the principal frame
/// at the turning point (columns of axes_B are P's axes in B, moments ascending, except that a
/// top under gravity has its axle as e3, pointing from the pivot toward the centre of mass),
/// S space.
/// The turning point is the pivot under gravity, otherwise the centre of mass (or the origin O
/// for a tensor given directly, which carries no mass).
#include <optional>
#include <string>
#include <vector>

#include "core/rigid_body.hpp"
#include "problem/scene.hpp"

namespace wobble {

struct SceneSetup {
  std::string id, title, description;
  bool has_mass = false;
  double mass_kg = 0.0;
  Vec3 turning_point_B = Vec3::Zero();  ///< m, from O
  std::string turning_point;            ///< "centre of mass", "pivot" or "origin O"
  Vec3 moments = Vec3::Ones();          ///< principal moments about the turning point, ascending
  Mat3 axes_B = Mat3::Identity();       ///< principal axes (columns) in B
  bool symmetric = false;               ///< two moments equal (core/principal_axes.hpp)
  /// Under gravity a symmetric top's unique axis (the axle) is e3, its moment last, as in the
  /// heavy-top problem, and points toward the centre of mass (model.d_P_m = l e3, l >= 0);
  /// otherwise the moments are ascending.
  bool symmetry_axis_last = false;
  RigidBodyModel model;                 ///< in P
  Vec3 m0_P = Vec3::Zero();             ///< initial angular momentum, P, kg m^2/s
  Quat q0_PtoS = Quat::Identity();
  Quat q0_BtoS = Quat::Identity();
  bool free_flight = false;
  Vec3 g_S = Vec3::Zero(), x0_S = Vec3::Zero(), v0_S = Vec3::Zero();  ///< free flight
  double t_end = 10.0;
  int samples = 101;
  double tolerance = kDefaultSceneTolerance;
  /// The run's budget in evaluations (simulate --max-evaluations): each integrator run stops
  /// with WorkLimitReached past it. 5e7 is a few seconds at the 60 ns a heavy-top evaluation
  /// takes (measured).
  double max_evaluations = 5e7;
  std::optional<double> step;
  std::string method = "auto";
  std::vector<std::string> outputs;
  std::vector<std::string> effects;  ///< in words, for the header ("torque-free" if none)
  /// A brake (TorqueSpec::brake): the time its spin stops, s; the torque acts before it only.
  /// It is exact: about a symmetry axis a, I_a dw_a/dt = tau_a, so w_a falls linearly.
  std::optional<double> brake_stops_s;
  Vec3 brake_axis_P = Vec3::Zero();  ///< unit, the brake's axis in P
};

/// Evaluates the scene at its defaults with `assignments` ("NAME=VALUE") applied.
/// @throws InputError naming the field and value: a bad expression or value, a non-unit
///   quaternion, a matrix that is not a rotation, gravity or free flight without a mass, a
///   t_end or step that is not > 0, or an impossible inertia tensor.
SceneSetup setup_scene(const Scene& scene, const std::vector<std::string>& assignments);

/// The same at parameter values already read (`values` holds every parameter).
SceneSetup setup_scene_at(const Scene& scene, const sym::Values& values);

}  // namespace wobble
