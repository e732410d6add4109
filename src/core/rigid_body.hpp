#pragma once
/// @file
/// The rotating rigid body with optional torques: the model every integrator advances.
///
/// Frames and units (SI): P is the body frame along the principal axes through the point the
/// body turns about (the centre of mass, or the fixed pivot of a heavy top); S is the space
/// frame (z up). The state is y = (m_P, q_PtoS): the angular momentum about that point in P
/// components (kg m^2/s) and the unit quaternion taking P components to S components.
/// Equations: dm/dt = m x w + tau_P, w = I^-1 m (rad/s); dq/dt = q (0, w) / 2.
/// Torques (only those switched on exist; none means torque-free):
/// - gravity about a fixed pivot: tau = d x (M g), d = pivot -> centre of mass;
/// - a constant torque, fixed in the body (P) or in space (S).
#include <Eigen/Core>

#include "core/free_body.hpp"
#include "core/inertia.hpp"

namespace wobble {

using State7 = Eigen::Matrix<double, 7, 1>;  ///< (m_P[0..2], q.w, q.x, q.y, q.z)

struct RigidBodyModel {
  Vec3 I_P = Vec3::Ones();  ///< principal moments about the turning point, kg m^2 (each > 0)

  bool gravity = false;
  double mass_kg = 0.0;
  Vec3 d_P_m = Vec3::Zero();            ///< pivot -> centre of mass, P components, m
  Vec3 g_S = Vec3(0.0, 0.0, -9.80665);  ///< gravitational acceleration, S components, m/s^2

  bool torque = false;
  bool torque_in_space = false;
  Vec3 torque_Nm = Vec3::Zero();  ///< in P, or in S if torque_in_space

  bool torque_free() const { return !gravity && !torque; }
  /// @throws std::invalid_argument for a moment that is not finite and > 0, a non-finite
  ///   torque, or gravity without a positive mass.
  void validate() const;

  Vec3 omega_P(const Vec3& m_P) const { return m_P.cwiseQuotient(I_P); }
  /// q_PtoS any nonzero quaternion: the torque of the rotation q / |q|.
  Vec3 torque_P(const Vec3& m_P, const Quat& q_PtoS) const;
  /// dy/dt for any nonzero q: the torques act for the rotation q / |q|, and dq/dt = q (0, w) / 2
  /// scales with |q|, so |q| never enters the motion (the integrators renormalise now and then).
  /// For one evaluation; an integrator evaluates through RigidBodyRhs (the same values).
  State7 rhs(const State7& y) const;

  /// Kinetic energy (J); potential energy of gravity about the pivot, M g-height of the centre
  /// of mass above the pivot (J; zero without gravity).
  double kinetic(const Vec3& m_P) const { return 0.5 * m_P.dot(omega_P(m_P)); }
  double potential(const Quat& q_PtoS) const;
};

/// The right-hand side of one model, prepared for the many evaluations of a run: the rates
/// w = m .* (1/I) take a multiplication where m / I took a division, three divisions on the path
/// from one stage to the next (measured on the free body: 18 ns per evaluation with them, 13 ns
/// without). Holds a copy of the model, so a model changed later cannot leave it stale.
/// RigidBodyModel::rhs evaluates through it: every caller gets the same values, bit for bit.
class RigidBodyRhs {
 public:
  explicit RigidBodyRhs(const RigidBodyModel& model)
      : model_(model), inverse_I_P_(model.I_P.cwiseInverse()) {}
  State7 operator()(const State7& y) const;
  const RigidBodyModel& model() const { return model_; }

 private:
  RigidBodyModel model_;
  Vec3 inverse_I_P_;  ///< 1/I, kg^-1 m^-2
};

State7 pack(const Vec3& m_P, const Quat& q_PtoS);
Vec3 momentum_of(const State7& y);
Quat attitude_of(const State7& y);  ///< normalised

}  // namespace wobble
