#pragma once
/// @file
/// Closed forms of the torque-free axially symmetric top (numeric; the symbolic twin lives in the
/// torque-free solver).
///
/// Conventions: principal moments I1 = I2 (about e1, e2) and I3 (about the symmetry axis e3),
/// kg m^2; at t = 0 the body axes are the space axes and w(0) = w (sin(alpha) x + cos(alpha) z),
/// w > 0 in rad/s, alpha in [0, pi/2). Prolate: I3 < I1; oblate: I3 > I1.
/// Results (all from Euler's equations for I1 = I2):
/// - in the body, w and L precess about e3 at Omega_body = (I3 - I1)/I1 * w3 (signed along e3);
/// - in space, e3 and w precess about the fixed L at |L| / I1;
/// - the angle between e3 and L is constant, theta_L = atan2(I1 sin(alpha), I3 cos(alpha));
/// - so the angle between z = e3(0) and e3(t) reaches its largest value 2 theta_L after half a
///   precession, t_max = pi I1 / |L|.
/// Every formula avoids cancellation: angles through atan2 of exact components, the angle between
/// w and L from their cross and dot products, so alpha = 1e-8 or alpha near pi/2 stay accurate.
#include "core/inertia.hpp"

namespace wobble {

struct SymmetricTop {
  double I1_kgm2;      ///< moment about e1 and e2
  double I3_kgm2;      ///< moment about the symmetry axis e3
  double omega_rad_s;  ///< |w(0)|
  double alpha_rad;    ///< angle between w(0) and e3

  /// @throws std::invalid_argument unless I1, I3, omega are finite and > 0, alpha in [0, pi/2),
  ///         and I1, I3 satisfy the triangle inequality (I3 <= 2 I1).
  void validate() const;

  Vec3 omega0() const;              ///< w(0), rad/s
  Vec3 L0() const;                  ///< L(0) = I w(0), kg m^2/s (body = space at t = 0)
  double omega3() const;            ///< w cos(alpha)
  double angle_L_e3() const;        ///< theta_L, rad
  double angle_omega_L() const;     ///< space-cone half angle, rad
  double omega_body_rate() const;   ///< (I3 - I1)/I1 w3, rad/s, signed along e3
  double omega_space_rate() const;  ///< |L| / I1, rad/s
  double max_angle() const;         ///< 2 theta_L, rad
  double t_max() const;             ///< pi I1 / |L|, s (0 when alpha = 0: no wobble)
};

}  // namespace wobble
