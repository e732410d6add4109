#pragma once
/// @file
/// The torque-free rigid body solved exactly: its state at any time t, without stepping.
///
/// Frames and units as core/free_body.hpp: moments I (kg m^2) along the body axes P, body
/// angular momentum m_P (kg m^2/s), attitude q_PtoS. Three kinds of motion:
/// - steady: m along a principal axis; the body turns uniformly about it;
/// - symmetric: two moments exactly equal (I_a == I_b = I_perp, axis j the other). Closed form:
///   R(t) = Rot(L_S, |L| t / I_perp) R0 Rot(e_j, c t), m_P(t) = Rot(e_j, -c t) m0,
///   c = (1/I_j - 1/I_perp) m_j: the body cone turns at c about e_j, the body at |L|/I_perp
///   about L;
/// - elliptic: three distinct moments. In a working frame W (the axes sorted, and turned so that
///   m circles W's third axis) m = (s1 a1 cn u, s2 a2 sn u, s3 a3 dn u), u = u0 + lambda t, with
///   the parameter's complement k'^2 computed from factored invariants (never as 1 - k^2), so it
///   stays accurate at the separatrix. The attitude is R_WtoS = Q Rz(phi(t)) P(m(t)), P(m) the
///   rotation taking m to |m| z; phi' = |m| (m1^2/J1 + m2^2/J2) / (m1^2 + m2^2), integrated as
///   an elliptic integral of the third kind (Celledoni, Fasso, Safstrom, Zanna, SIAM J. Sci.
///   Comput. 30 (2008)).
#include <limits>

#include "core/elliptic.hpp"
#include "core/free_body.hpp"

namespace wobble {

/// P(m): the rotation taking m (working frame) to |m| z, from which the attitude's precession
/// angle phi is measured (R_WtoS = Q Rz(phi) P(m)); m must not lie on the z axis.
Mat3 precession_frame(const Vec3& m);

class ExactFreeMotion {
 public:
  enum class Kind { steady, symmetric, elliptic };

  /// @throws std::invalid_argument for a moment not finite and > 0, a non-finite or zero m0.
  ExactFreeMotion(const Vec3& I_P, const Vec3& m0_P, const Quat& q0_PtoS);

  FreeBodyState at(double t_s) const;
  /// The body angular momentum alone (no attitude): cheaper, for w(t) = I^-1 m(t).
  Vec3 momentum_at(double t_s) const;
  Kind kind() const { return kind_; }
  /// Period of m_P(t) in s (infinity for steady motion and on the separatrix).
  double period_s() const { return period_; }
  /// Elliptic only: k'^2 = 1 - k^2 (0 on the separatrix).
  double kc2() const { return kc2_; }
  /// The fastest of the phases that grow with t (rad/s, or the elliptic argument's rate):
  /// each is formed and reduced in double-double, which keeps every digit of a phase up to
  /// about 2^50 (its error 2^50 2^-104 is below half an ulp of the reduced angle).
  double fastest_phase_rate() const;

 private:
  FreeBodyState at_elliptic(double t) const;
  Vec3 I_, m0_;
  Quat q0_;
  Kind kind_ = Kind::steady;
  double period_ = std::numeric_limits<double>::infinity();
  // symmetric (and steady: rate_dd_ alone)
  int axis_ = 2;
  double c_ = 0.0, I_perp_ = 1.0;
  /// c and the turning rate about L, |L| / I_perp (steady: |w|), rad/s, to double-double
  DoubleDouble c_dd_, rate_dd_;
  /// rate t, rad, reduced to (-pi, pi] with its digits kept however many turns it holds
  static double angle(const DoubleDouble& rate, double t_s);
  // elliptic, in W: m_W = C m_P
  Mat3 C_ = Mat3::Identity();
  Vec3 J_ = Vec3::Ones(), amp_ = Vec3::Zero(), sign_ = Vec3::Ones();
  double M_ = 0.0, lambda_ = 0.0, u0_ = 0.0, kc2_ = 0.0, K_ = 0.0, n_ = 0.0;
  DoubleDouble lambda_dd_, K_dd_;  ///< lambda and K to double-double, for the phase
  DoubleDouble phi_rate_dd_, phi_per_half_period_dd_;  ///< phi_rate and phi_coef 2 Gc, likewise
  double phi_rate_ = 0.0, phi_coef_ = 0.0, G0_ = 0.0, Gc_ = 0.0;
  Mat3 Q_ = Mat3::Identity();  ///< R_WtoS(0) P(m0)^T
  struct Phase {
    ReducedArgument reduced;              ///< u = r + 2 K j, and sn, cn, dn of r
    double sn = 0.0, cn = 0.0, dn = 0.0;  ///< of u
  };
  Phase phase_at(double t_s) const;
  double precession_angle(double t_s, const Phase& p) const;
  double G(const Phase& p) const;
  Vec3 m_W(const Phase& p) const;
};

}  // namespace wobble
