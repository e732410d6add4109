#pragma once
/// @file
/// The heavy symmetric top solved exactly: its state at any time t, without stepping.
///
/// Frames and units as core/rigid_body.hpp and core/heavy_top.hpp: S has z up (against
/// gravity), B is the body frame with e3 the symmetry axis; the pivot is B's origin and the
/// centre of mass sits at l e3; moments (I1, I1, I3) about the pivot (kg m^2); the state is
/// (m_B, q_BtoS). Taylor's z-y-z Euler angles, u = cos(theta).
///
/// The motion (Goldstein 5.7; Landau-Lifshitz 35): u' ^2 = f(u) = beta (u - u1)(u - u2)(u - u3),
/// u1 <= u2 the nutation limits (core/heavy_top.hpp), u3 >= 1. Then
///   u(t) = u1 + (u2 - u1) sn^2(tau, k),  tau = tau0 + tau' t,  tau'^2 = beta (u3 - u1) / 4,
///   k^2 = (u2 - u1) / (u3 - u1) (k'^2 = (u3 - u2) / (u3 - u1) from the differences, never
///   as 1 - k^2),
/// and the azimuth and spin rates split into partial fractions over 1 - u and 1 + u,
///   phi' = (b - a u)/(1 - u^2) = 1/2 [(b - a)/(1 - u) + (b + a)/(1 + u)],
///   psi' = w3 - u phi' = w3 - a - 1/2 (b - a)/(1 - u) + 1/2 (b + a)/(1 + u),
/// with 1 -+ u = (1 -+ u1)(1 - n± sn^2), n+ = (u2 - u1)/(1 - u1), n- = -(u2 - u1)/(1 + u1), so
/// each is a linear term plus an incomplete elliptic integral of the third kind,
/// Pi(n; am tau) = tau + n G(tau), G continued past K through the periods (core/elliptic.hpp);
/// for n- < -1 (a top that swings near hanging down) Pi(n-) is taken by A&S 17.7.15 instead,
/// whose terms are no larger than Pi(n-) itself (negative_third_kind, core/elliptic.hpp).
/// The attitude follows from the Euler angles relative to the start, which never needs psi0
/// or phi0 themselves: q(t) = Rz(dphi) Rot(n0, theta - theta0) q0 Rz(dpsi), n0 the line of
/// nodes at t = 0. The momentum is m_B = I1 (theta' n_B + phi' sin(theta) z x n_B) + p_psi z,
/// n_B the line of nodes in the body: phi' and psi' grow as 1/(1 -+ u) near a pole, but
/// phi' sin(theta) does not (w = phi' z + theta' n + psi' e3 summed them: 7.7e4 eps of m for a
/// top that swings 1.6e-5 rad past hanging down). n_B turns with psi, and near a pole psi' is
/// large: a time error would show in m. The phase's rounding is one of r, eps |r|, next to
/// nothing at the lowest point (r = 0), and at the highest (r = +-K) cn comes from K - |r| in
/// double-double (core/elliptic.hpp), not from r rounded to eps K.
///
/// Exact at any time: what grows with t (tau and its reduction by 2K, the complete parts
/// 2 j (Pi(n±) - K) / n± of the integrals, the linear parts of phi and psi) is formed in
/// double-double and reduced there, from constants in double-double (the start state's b -+ a
/// and cubic, its roots polished by Newton's method, tau', k'^2, K, c±), so the error against
/// 50 digits does not grow with t (hard case 14, to 1e6 s).
#include <limits>

#include "core/elliptic.hpp"
#include "core/free_body.hpp"
#include "core/heavy_top.hpp"

namespace wobble {

class ExactHeavyTop {
 public:
  /// sleeping: the axis vertical and not moving, the body spins about it for ever (stable or
  /// not: the exact motion never leaves it); steady: u stays at its start (steady precession);
  /// nutating: u between the nutation limits.
  enum class Kind { sleeping, steady, nutating };

  /// @throws std::invalid_argument for an invalid top, a non-finite state, or an axis that
  ///   starts vertical while it moves (theta is not a coordinate there; start a moment later),
  ///   or within 1.5e-154 rad of the vertical but not on it (sin^2(theta0) underflows).
  ExactHeavyTop(const HeavyTop& top, const Vec3& m0_B, const Quat& q0_BtoS);

  /// The state at t (s), any t: (m_B, q_BtoS).
  FreeBodyState at(double t_s) const;
  /// cos(theta(t)): the height of the axis' tip on the unit sphere.
  double u_at(double t_s) const;

  Kind kind() const { return kind_; }
  /// u1 <= u2 (and theta_max >= theta_min): the nutation limits.
  const Nutation& nutation() const { return nutation_; }
  /// The third root of f, >= 1.
  double u3() const { return u3_; }
  /// The nutation's elliptic parameter k^2 = (u2 - u1) / (u3 - u1) (0 when theta is constant).
  double k2() const { return k2_; }
  /// Period of theta(t) in s (infinite when theta is constant).
  double nutation_period_s() const { return period_; }
  /// The largest |phi'| + |psi'| over the motion (rad/s). The reduced phase is rounded to
  /// eps K, a time error of about eps T / 2 (T the nutation period), which this rate turns into
  /// the attitude: the error that is left, bounded however long the run. It grows as
  /// 1/sin(theta_limit) when the axle passes near the vertical (the Euler angles' singularity),
  /// where an integrator does better.
  double euler_rate_bound() const;
  /// The fastest of the phases that grow with t (rad/s): the nutation's tau', and phi's and
  /// psi's secular rates, their linear parts and the complete integrals' share per second (2 j
  /// of them after j half periods of tau). Formed and reduced in double-double, each keeps
  /// every digit up to about 2^50. Not the Euler rates' bound: near a pole phi' is large for a
  /// moment, but phi turns by pi there and no more.
  double fastest_phase_rate() const;

 private:
  /// tau reduced by the period 2K of sn^2: u, u' and the integrals' reduced parts need only r.
  using Phase = ReducedArgument;
  /// tau = tau0 + tau' t reduced by 2K, both in double-double (in double the rounding of
  /// tau' t, eps tau, would be the phase's error, growing with t).
  Phase phase_at(double t_s) const;
  /// (Pi(n; am r) - r) / n of the reduced argument r alone (|r| <= K: bounded).
  /// one_minus_n: 1 - n without cancellation, for n+ (a start within about 1e-8 rad of upright
  /// rounds n+ to 1, and 1 - n+ sn^2 to 0 at the upper limit).
  double incomplete_excess(const Phase& p, double n, double one_minus_n) const {
    return third_kind_excess(p.of_r.sn, p.of_r.cn, kc2_, n, one_minus_n);
  }
  /// theta(t) - theta0, phi(t) - phi0, psi(t) - psi0.
  struct Angles {
    double dtheta = 0.0, dphi = 0.0, dpsi = 0.0, u = 0.0, udot = 0.0, thetadot = 0.0;
    double one_minus_u = 0.0, one_plus_u = 0.0;  ///< as sums of terms >= 0 (no cancellation)
    double phidot_sin_theta = 0.0;  ///< phi' sin(theta), bounded where phi' is not (poles)
  };
  Angles angles(double t) const;

  /// The constants from the start to the rates, in double-double: the double chain's values
  /// lifted, or all of them refined from the start state (refine).
  struct Chain {
    DoubleDouble d_min, d_max;              ///< the nutation limits' offsets from u0
    DoubleDouble one_minus_u0, one_plus_u0;
    DoubleDouble u3_minus_u1, u3_minus_u2;
    DoubleDouble b_minus_a, b_plus_a, a, beta, w3;
    bool third_root_from_pole;  ///< u3 - 1 from f(1) (near upright), else from the roots' sum
  };
  /// Replaces the chain by the same quantities from the start state in double-double, the
  /// cubic's roots polished by Newton's method, where they confirm the double ones.
  void refine(Chain& c) const;
  /// From the chain: the nutation's rate and period, the partial fractions' coefficients, their
  /// complete integrals and the linear rates.
  void set_up_rates(const Chain& c);
  /// The minus term for n- < -1 by A&S 17.7.15 (see the .cpp): its linear rate, G_N's
  /// coefficient and parameter, and the arctangent's.
  void set_up_minus_transformed(const DoubleDouble& n, const DoubleDouble& one_minus_n,
                                const DoubleDouble& lin_minus, const DoubleDouble& k2,
                                const DoubleDouble& kc2, const DoubleDouble& rate);
  /// atan(p sn cn / dn) of the transformed minus term at the phase (0 when it is not used).
  double minus_atan(const Phase& p) const;
  /// tau0 (sin(theta0) thetadot0 = -u'(0) gives its side and, near a turning point, its
  /// distance from it) and the integrals' incomplete parts at t = 0.
  void set_up_phase(double sin_thetadot0, const Chain& c);

  HeavyTop top_;
  Vec3 m0_;
  Quat q0_;
  Kind kind_ = Kind::sleeping;
  Nutation nutation_{};
  double u0_ = 1.0, theta0_ = 0.0, w3_ = 0.0, a_ = 0.0;  ///< a = p_psi / I1
  double b_minus_a_ = 0.0, b_plus_a_ = 0.0;  ///< without the cancellation near the poles
  Vec3 nodes0_S_ = Vec3::UnitY();  ///< line of nodes at t = 0
  // nutating
  double u3_ = std::numeric_limits<double>::infinity(), du_ = 0.0, k2_ = 0.0, kc2_ = 1.0, K_ = 0.0;
  double rate_ = 0.0;     ///< tau'
  DoubleDouble tau0_dd_;  ///< tau(0) to double-double (K - tau' near the turning point at K)
  double one_plus_u1_ = 0.0, one_minus_u2_ = 0.0;  ///< from the start and the roots in d
  /// +-1 when the axle passes through hanging or upright (Nutation), else 0: the sign of
  /// sin(theta) against sn(tau) or cn(tau) (angles()).
  double sign_hanging_ = 0.0, sign_upright_ = 0.0;
  double period_ = std::numeric_limits<double>::infinity();
  double n_plus_ = 0.0, n_minus_ = 0.0;
  /// 1 - n-, or 1 - N of the transformed minus term (set_up_minus_transformed)
  double one_minus_n_minus_ = 1.0;
  /// The transformed minus term's arctangent: its coefficient (rad), p, and value at t = 0.
  double minus_atan_coef_ = 0.0, minus_atan_p_ = 0.0, minus_atan0_ = 0.0;
  double one_minus_n_plus_ = 1.0;  ///< (1 - u2) / (1 - u1), without cancellation
  /// The phase's half periods and the integrals' incomplete parts at t = 0: G± grow from them.
  double j0_ = 0.0, G_plus0_ = 0.0, G_minus0_ = 0.0;
  /// What grows with t, to double-double: tau' and K (tau and its reduction), c± (the
  /// coefficients of G±), the complete integrals (Pi(n±) - K) / n± (2 j of them in G± after j
  /// half periods), and the linear parts of phi' and psi'.
  DoubleDouble rate_dd_, K_dd_, c_plus_, c_minus_, complete_plus_, complete_minus_;
  DoubleDouble phidot_lin_, psidot_lin_;
};

}  // namespace wobble
