#include "core/exact_heavy_top.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <stdexcept>

#include "core/elliptic.hpp"

namespace wobble {

namespace {
Quat rot_z(double angle) {
  return Quat(Eigen::AngleAxisd(angle, Vec3::UnitZ()));
}
}  // namespace

ExactHeavyTop::ExactHeavyTop(const HeavyTop& top, const Vec3& m0_B, const Quat& q0_BtoS)
    : top_(top), m0_(m0_B), q0_(q0_BtoS.normalized()) {
  top.validate();
  if (!m0_B.allFinite() || !q0_BtoS.coeffs().allFinite())
    throw std::invalid_argument("exact heavy top: the state must be finite");
  const double I1 = top.I1_kgm2;
  const Vec3 I(I1, I1, top.I3_kgm2);
  const Vec3 e3 = q0_ * Vec3::UnitZ();
  const Vec3 w_S = q0_ * m0_.cwiseQuotient(I);
  const double sin0 = std::hypot(e3.x(), e3.y());
  u0_ = e3.z();
  w3_ = m0_.z() / top.I3_kgm2;
  a_ = m0_.z() / I1;               // p_psi / I1
  // The spin's rate to double-double: psi grows by w3 t, hundreds of radians, whose rounding
  // would otherwise be the attitude's error (eps per radian).
  const DoubleDouble w3_dd = DoubleDouble(m0_.z()) / DoubleDouble(top.I3_kgm2);
  psidot_lin_ = w3_dd;
  if (sin0 == 0.0) {
    if (m0_.x() != 0.0 || m0_.y() != 0.0)
      throw std::invalid_argument(
          "exact heavy top: the axis starts vertical and moving (theta is no coordinate there)");
    kind_ = Kind::sleeping;
    nutation_ = Nutation{u0_, u0_, std::acos(u0_), std::acos(u0_)};
    return;
  }
  nodes0_S_ = Vec3(-e3.y(), e3.x(), 0.0) / sin0;
  // Distances to the poles without cancellation: 1 -+ u0 = sin^2 / (1 +- u0) on the side where
  // the sum is large.
  const double sin0_2 = sin0 * sin0;
  const double one_plus_u0 = u0_ < 0.0 ? sin0_2 / (1.0 - u0_) : 1.0 + u0_;
  const double one_minus_u0 = u0_ > 0.0 ? sin0_2 / (1.0 + u0_) : 1.0 - u0_;
  // b -+ a = L . (z -+ e3) / I1 and b - a u0 = L . (z - u0 e3) / I1, each from a vector whose
  // small components are formed without cancellation: near a pole b and a nearly cancel.
  const Vec3 L_S = q0_ * m0_;
  b_minus_a_ = L_S.dot(Vec3(-e3.x(), -e3.y(), one_minus_u0)) / I1;
  b_plus_a_ = L_S.dot(Vec3(e3.x(), e3.y(), one_plus_u0)) / I1;
  HeavyTopStart start;
  start.theta = std::atan2(sin0, u0_);
  start.thetadot = w_S.dot(nodes0_S_);
  start.phidot = L_S.dot(Vec3(-u0_ * e3.x(), -u0_ * e3.y(), sin0_2)) / (I1 * sin0_2);
  start.psidot = w3_ - start.phidot * u0_;
  nutation_ = nutation_limits(top, start);
  theta0_ = start.theta;  // the steady case keeps it
  const double u1 = nutation_.u_min, u2 = nutation_.u_max;
  // The limits' distances to the poles: the start's and the roots' offsets d from u0.
  one_plus_u1_ = std::max(0.0, one_plus_u0 + nutation_.d_min);
  one_minus_u2_ = std::max(0.0, one_minus_u0 - nutation_.d_max);
  du_ = nutation_.d_max - nutation_.d_min;
  if (du_ == 0.0) {
    kind_ = Kind::steady;
    phidot_lin_ = DoubleDouble(start.phidot);
    psidot_lin_ = w3_dd - two_prod(start.phidot, u0_);  // start.psidot, to double-double
    return;
  }
  kind_ = Kind::nutating;
  const double beta = 2 * top.M_kg * top.g_m_s2 * top.l_m / I1;
  // The sum of the roots of f (its u^2 coefficient over beta), written with the start's
  // kinetic term P = thetadot^2 + phidot^2 sin^2 >= 0 so that no large terms cancel.
  const double P = start.thetadot * start.thetadot + start.phidot * start.phidot * sin0 * sin0;
  u3_ = std::max(1.0, u0_ + (P + a_ * a_) / beta - u1 - u2);
  // u3 - u2 = (u3 - 1) + (1 - u2), u3 - u1 = (u3 - u2) + du: sums.
  const double u3_minus_u2 = (u3_ - 1.0) + one_minus_u2_, u3_minus_u1 = u3_minus_u2 + du_;
  kc2_ = u3_minus_u2 / u3_minus_u1;
  K_ = kc2_ > 0.0 ? complete_K(kc2_) : std::numeric_limits<double>::infinity();
  rate_ = 0.5 * std::sqrt(beta * u3_minus_u1);
  period_ = 2.0 * K_ / rate_;
  // tau0: sn^2(tau0) = (u0 - u1)/du, on the rising side (u' >= 0) for tau0 in [0, K].
  double sn0 = std::sqrt(std::max(0.0, -nutation_.d_min) / du_);
  double cn0 = std::sqrt(std::max(0.0, nutation_.d_max) / du_);
  // Near a turning point the smaller of sn, cn comes from a difference u0 - u_limit that is a
  // rounding, and so carries only sqrt(eps) (a start at rest could begin moving at 1e-7 of its
  // rates): take it from the start's velocity instead, u' = 2 du sn cn dn tau'.
  const double dn0 = std::sqrt((u3_minus_u2 + nutation_.d_max) / u3_minus_u1);
  const double v = std::abs(sin0 * start.thetadot) / (2.0 * du_ * dn0 * rate_);
  if (sn0 >= cn0) {
    cn0 = v / sn0;
  } else {
    sn0 = v / cn0;
  }
  const double h = std::hypot(sn0, cn0);
  const double F0 = incomplete_F(sn0 / h, cn0 / h, kc2_);
  tau0_ = start.thetadot > 0.0 ? -F0 : F0;  // theta rising is u falling
  // The partial fractions over 1 - u and 1 + u; a term whose numerator is zero is left out (at
  // u1 = -1 the numerator b + a is zero with it, and n- would be infinite).
  const double one_minus_u1 = one_minus_u2_ + du_;
  n_plus_ = du_ / one_minus_u1;
  const double lin_plus = 0.5 * b_minus_a_ / one_minus_u1;
  phidot_lin_ = DoubleDouble(lin_plus);
  psidot_lin_ = w3_dd - DoubleDouble(m0_.z()) / DoubleDouble(I1) - DoubleDouble(lin_plus);  // w3 - a - lin+
  if (b_minus_a_ != 0.0) {
    c_plus_ = 0.5 * b_minus_a_ * n_plus_ / (one_minus_u1 * rate_);
    if (kc2_ > 0.0) complete_plus_ = complete_third_kind_excess(kc2_, n_plus_);
  }
  if (b_plus_a_ != 0.0 && one_plus_u1_ > 0.0) {
    n_minus_ = -du_ / one_plus_u1_;
    const double lin = 0.5 * b_plus_a_ / one_plus_u1_;
    phidot_lin_ = phidot_lin_ + DoubleDouble(lin);
    psidot_lin_ = psidot_lin_ + DoubleDouble(lin);
    c_minus_ = 0.5 * b_plus_a_ * n_minus_ / (one_plus_u1_ * rate_);
    if (kc2_ > 0.0) complete_minus_ = complete_third_kind_excess(kc2_, n_minus_);
  }
  const Phase p0 = phase(tau0_);
  if (c_plus_ != 0.0) G_plus0_ = excess(p0, n_plus_, complete_plus_);
  if (c_minus_ != 0.0) G_minus0_ = excess(p0, n_minus_, complete_minus_);
  // theta0 as the closed form gives it at t = 0 (not the start's own, which differs by a
  // rounding): then at(0) is the start exactly, and theta(t) - theta0 has no offset.
  theta0_ = 0.0;
  theta0_ = angles(0.0).dtheta;
}

ExactHeavyTop::Angles ExactHeavyTop::angles(double t) const {
  Angles a;
  a.u = u0_;
  a.one_minus_u = 1.0 - u0_;
  a.one_plus_u = 1.0 + u0_;
  // The linear parts, which grow with t, in double-double and reduced by 2 pi there.
  const DoubleDouble t_dd(t);
  const double phi_lin = remainder_two_pi(phidot_lin_ * t_dd);
  const double psi_lin = remainder_two_pi(psidot_lin_ * t_dd);
  if (kind_ != Kind::nutating) {
    a.dphi = phi_lin;
    a.dpsi = psi_lin;
    return a;
  }
  const Phase p = phase(tau0_ + rate_ * t);
  const double sn = p.of_r.sn, cn = p.of_r.cn, dn = p.of_r.dn;
  const double u1 = nutation_.u_min;
  a.u = u1 + du_ * sn * sn;
  a.udot = 2.0 * du_ * sn * cn * dn * rate_;
  // sin(theta) from 1 - u = (1 - u2) + du cn^2 and 1 + u = (1 + u1) + du sn^2: sums, no
  // cancellation near the poles.
  a.one_minus_u = one_minus_u2_ + du_ * cn * cn;
  a.one_plus_u = one_plus_u1_ + du_ * sn * sn;
  a.dtheta = std::atan2(std::sqrt(a.one_minus_u * a.one_plus_u), a.u) - theta0_;
  const double dG_plus = c_plus_ != 0.0 ? excess(p, n_plus_, complete_plus_) - G_plus0_ : 0.0;
  const double dG_minus = c_minus_ != 0.0 ? excess(p, n_minus_, complete_minus_) - G_minus0_ : 0.0;
  a.dphi = phi_lin + c_plus_ * dG_plus + c_minus_ * dG_minus;
  a.dpsi = psi_lin - c_plus_ * dG_plus + c_minus_ * dG_minus;
  return a;
}

double ExactHeavyTop::euler_rate_bound() const {
  if (kind_ == Kind::sleeping) return std::abs(w3_);
  // phi' = 1/2 (b - a)/(1 - u) + 1/2 (b + a)/(1 + u) is monotonic between the poles in each
  // term: its extremes are at the nutation limits; psi' = w3 - u phi'.
  // (Steady precession: du = 0, both limits are the start.)
  double bound = 0.0;
  for (const auto& [one_minus, one_plus, u] :
       {std::tuple{one_minus_u2_ + du_, one_plus_u1_, nutation_.u_min},
        std::tuple{one_minus_u2_, one_plus_u1_ + du_, nutation_.u_max}}) {
    const double phidot = (one_minus > 0.0 ? 0.5 * b_minus_a_ / one_minus : 0.0) +
                          (one_plus > 0.0 ? 0.5 * b_plus_a_ / one_plus : 0.0);
    bound = std::max(bound, std::abs(phidot) + std::abs(w3_ - u * phidot));
  }
  return bound;
}

double ExactHeavyTop::u_at(double t) const {
  return angles(t).u;
}

FreeBodyState ExactHeavyTop::at(double t) const {
  const Angles a = angles(t);
  FreeBodyState s;
  if (kind_ == Kind::sleeping) {
    s.m_B = m0_;
    s.q_BtoS = (q0_ * rot_z(a.dpsi)).normalized();
    return s;
  }
  const Quat turn_phi = rot_z(a.dphi);
  s.q_BtoS = (turn_phi * Quat(Eigen::AngleAxisd(a.dtheta, nodes0_S_)) * q0_ * rot_z(a.dpsi))
                 .normalized();
  // The angular velocity from the Euler rates: w = phi' z + theta' n + psi' e3.
  const double phidot = 0.5 * b_minus_a_ / a.one_minus_u + 0.5 * b_plus_a_ / a.one_plus_u;
  const double psidot = w3_ - a.u * phidot;
  const double sin_theta = std::sqrt(a.one_minus_u * a.one_plus_u);
  const double thetadot = sin_theta > 0.0 ? -a.udot / sin_theta : 0.0;
  const Vec3 e3 = s.q_BtoS * Vec3::UnitZ();
  const Vec3 w_S = phidot * Vec3::UnitZ() + thetadot * (turn_phi * nodes0_S_) + psidot * e3;
  const Vec3 w_B = s.q_BtoS.conjugate() * w_S;
  s.m_B = Vec3(top_.I1_kgm2 * w_B.x(), top_.I1_kgm2 * w_B.y(), m0_.z());  // p_psi is conserved
  return s;
}

}  // namespace wobble
