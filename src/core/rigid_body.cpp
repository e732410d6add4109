#include "core/rigid_body.hpp"

#include <cmath>
#include <stdexcept>

namespace wobble {

void RigidBodyModel::validate() const {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(I_P[i]) || !(I_P[i] > 0.0))
      throw std::invalid_argument("rigid body: principal moments must be finite and > 0");
  }
  if (gravity &&
      (!std::isfinite(mass_kg) || !(mass_kg > 0.0) || !d_P_m.allFinite() || !g_S.allFinite())) {
    throw std::invalid_argument("rigid body: gravity needs a finite mass > 0, pivot and g");
  }
  if (torque && !torque_Nm.allFinite())
    throw std::invalid_argument("rigid body: torque must be finite");
}

Vec3 RigidBodyModel::torque_P(const Vec3& /*m_P*/, const Quat& q_PtoS) const {
  Vec3 tau = Vec3::Zero();
  if (gravity) tau += d_P_m.cross(q_PtoS.conjugate() * (mass_kg * g_S));
  if (torque) tau += torque_in_space ? Vec3(q_PtoS.conjugate() * torque_Nm) : torque_Nm;
  return tau;
}

double RigidBodyModel::potential(const Quat& q_PtoS) const {
  if (!gravity) return 0.0;
  return -mass_kg * g_S.dot(q_PtoS * d_P_m);
}

State7 RigidBodyModel::rhs(const State7& y) const {
  const Vec3 m = y.head<3>();
  const Vec3 w = omega_P(m);
  Vec3 dm = m.cross(w);
  // The rotation in torque_P must be a rotation: use the normalised attitude there only.
  if (!torque_free()) dm += torque_P(m, attitude_of(y));
  const double qw = y[3], qx = y[4], qy = y[5], qz = y[6];
  State7 dy;
  dy.head<3>() = dm;
  // q (0, w) / 2, written out (Hamilton product).
  dy[3] = 0.5 * (-qx * w[0] - qy * w[1] - qz * w[2]);
  dy[4] = 0.5 * (qw * w[0] + qy * w[2] - qz * w[1]);
  dy[5] = 0.5 * (qw * w[1] + qz * w[0] - qx * w[2]);
  dy[6] = 0.5 * (qw * w[2] + qx * w[1] - qy * w[0]);
  return dy;
}

State7 pack(const Vec3& m_P, const Quat& q_PtoS) {
  State7 y;
  y.head<3>() = m_P;
  y[3] = q_PtoS.w();
  y[4] = q_PtoS.x();
  y[5] = q_PtoS.y();
  y[6] = q_PtoS.z();
  return y;
}

Vec3 momentum_of(const State7& y) {
  return y.head<3>();
}

Quat attitude_of(const State7& y) {
  return Quat(y[3], y[4], y[5], y[6]).normalized();
}

}  // namespace wobble
