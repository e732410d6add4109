#pragma once
/// @file
/// The torque-free rigid body and its Lie-Poisson splitting integrators.
///
/// Model (body frame B along the principal axes, SI): moments I = (I1, I2, I3) in kg m^2; state
/// = body angular momentum m_B (kg m^2/s) and attitude q_BtoS, the unit quaternion taking body
/// components to space components (L_S = q m_B q*). Equations: dm/dt = m x w, w = I^-1 m;
/// dq/dt = q (0, w)/2. Conserved: energy T = sum m_i^2 / (2 I_i), |m|, and L_S.
///
/// Splitting (McLachlan; Touma and Wisdom): T = T1 + T2 + T3 with T_i = m_i^2 / (2 I_i). The flow
/// of T_i is exact: m turns about e_i by -theta and the body by +theta about e_i, theta =
/// (m_i / I_i) h. So every step keeps |m| to round-off and the attitude on the unit sphere by
/// construction, and the energy error stays bounded (no drift).
/// - Strang: T1(h/2) T2(h/2) T3(h) T2(h/2) T1(h/2), symmetric, order 2;
/// - Yoshida 4: Strang(c1 h) Strang(c0 h) Strang(c1 h), c1 = 1/(2 - 2^(1/3)), c0 = 1 - 2 c1,
///   order 4.
#include <Eigen/Geometry>
#include <cstdint>

#include "core/inertia.hpp"

namespace wobble {

using Quat = Eigen::Quaterniond;

struct FreeBodyState {
  Vec3 m_B = Vec3::Zero();         ///< body angular momentum, kg m^2/s
  Quat q_BtoS = Quat::Identity();  ///< attitude, body -> space
};

/// The body: principal moments, each > 0 (kg m^2), in body-axis order (not necessarily sorted).
struct FreeBody {
  Vec3 I_kgm2;

  /// @throws std::invalid_argument unless every moment is finite and > 0. The triangle
  ///         inequality is not required here: Euler's equations do not need it, and the standard
  ///         test body (2, 1, 2/3) violates it; physical bodies are checked where they are built
  ///         (core/validity.hpp).
  void validate() const;
  Vec3 omega_B(const Vec3& m_B) const { return m_B.cwiseQuotient(I_kgm2); }
  double energy(const Vec3& m_B) const { return 0.5 * m_B.dot(omega_B(m_B)); }
  /// L in space: q m_B q*.
  static Vec3 L_S(const FreeBodyState& s) { return s.q_BtoS * s.m_B; }
};

enum class SplittingOrder { strang2, yoshida4 };

/// Advances `s` by `steps` steps of size h_s. @throws std::invalid_argument for h not finite
/// or <= 0. Cost: 5 sub-flows per Strang step, 15 per Yoshida step (counted in `subflows`).
void split_free_body(const FreeBody& body, FreeBodyState& s, double h_s, std::int64_t steps,
                     SplittingOrder order, std::int64_t* subflows = nullptr);

}  // namespace wobble
