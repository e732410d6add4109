#include "core/exact_heavy_top.hpp"

#include <cmath>
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
  b_ = Vec3(q0_ * m0_).z() / I1;  // p_phi / I1
  if (sin0 == 0.0) {
    if (m0_.x() != 0.0 || m0_.y() != 0.0)
      throw std::invalid_argument(
          "exact heavy top: the axis starts vertical and moving (theta is no coordinate there)");
    kind_ = Kind::sleeping;
    nutation_ = Nutation{u0_, u0_, std::acos(u0_), std::acos(u0_)};
    return;
  }
  nodes0_S_ = Vec3(-e3.y(), e3.x(), 0.0) / sin0;
  HeavyTopStart start;
  start.theta = std::atan2(sin0, u0_);
  start.thetadot = w_S.dot(nodes0_S_);
  start.phidot = (b_ - a_ * u0_) / (sin0 * sin0);
  start.psidot = w3_ - start.phidot * u0_;
  nutation_ = nutation_limits(top, start);
  theta0_ = start.theta;  // the steady case keeps it
  const double u1 = nutation_.u_min, u2 = nutation_.u_max;
  du_ = u2 - u1;
  if (du_ == 0.0) {
    kind_ = Kind::steady;
    phidot_lin_ = start.phidot;
    psidot_lin_ = start.psidot;
    return;
  }
  kind_ = Kind::nutating;
  const double beta = 2 * top.M_kg * top.g_m_s2 * top.l_m / I1;
  // The sum of the roots of f (its u^2 coefficient over beta), written with the start's
  // kinetic term P = thetadot^2 + phidot^2 sin^2 >= 0 so that no large terms cancel.
  const double P = start.thetadot * start.thetadot + start.phidot * start.phidot * sin0 * sin0;
  u3_ = std::max(1.0, u0_ + (P + a_ * a_) / beta - u1 - u2);
  kc2_ = (u3_ - u2) / (u3_ - u1);
  K_ = kc2_ > 0.0 ? complete_K(kc2_) : std::numeric_limits<double>::infinity();
  rate_ = 0.5 * std::sqrt(beta * (u3_ - u1));
  period_ = 2.0 * K_ / rate_;
  // tau0: sn^2(tau0) = (u0 - u1)/du, on the rising side (u' >= 0) for tau0 in [0, K].
  const double s2 = std::max(0.0, u0_ - u1) / du_, c2 = std::max(0.0, u2 - u0_) / du_;
  const double h = std::sqrt(s2 + c2);
  const double F0 = incomplete_F(std::sqrt(s2) / h, std::sqrt(c2) / h, kc2_);
  tau0_ = start.thetadot > 0.0 ? -F0 : F0;  // theta rising is u falling
  // The partial fractions over 1 - u and 1 + u; a term whose numerator is zero is left out (at
  // u1 = -1 the numerator b + a is zero with it, and n- would be infinite).
  n_plus_ = du_ / (1.0 - u1);
  phidot_lin_ = 0.5 * (b_ - a_) / (1.0 - u1);
  psidot_lin_ = w3_ - a_ - phidot_lin_;
  if (b_ - a_ != 0.0) {
    c_plus_ = 0.5 * (b_ - a_) * n_plus_ / ((1.0 - u1) * rate_);
    if (kc2_ > 0.0) complete_plus_ = complete_third_kind_excess(kc2_, n_plus_);
  }
  if (b_ + a_ != 0.0 && 1.0 + u1 > 0.0) {
    n_minus_ = -du_ / (1.0 + u1);
    const double lin = 0.5 * (b_ + a_) / (1.0 + u1);
    phidot_lin_ += lin;
    psidot_lin_ += lin;
    c_minus_ = 0.5 * (b_ + a_) * n_minus_ / ((1.0 + u1) * rate_);
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

// tau reduced by the period 2K of sn^2 (r in [-K, K]); u, u' and the integrals' reduced parts
// need only r.
ExactHeavyTop::Phase ExactHeavyTop::phase(double tau) const {
  Phase p;
  p.r = tau;
  if (std::isfinite(K_)) {
    p.j = std::nearbyint(tau / (2.0 * K_));
    p.r = tau - 2.0 * K_ * p.j;
  }
  const SnCnDn s = jacobi_sncndn(p.r, kc2_);
  p.sn = s.sn;
  p.cn = s.cn;
  p.dn = s.dn;
  return p;
}

double ExactHeavyTop::excess(const Phase& p, double n, double complete) const {
  if (n == 0.0) return 0.0;
  return 2.0 * p.j * complete + third_kind_excess(p.sn, p.cn, kc2_, n);
}

ExactHeavyTop::Angles ExactHeavyTop::angles(double t) const {
  Angles a;
  a.u = u0_;
  a.one_minus_u = 1.0 - u0_;
  a.one_plus_u = 1.0 + u0_;
  if (kind_ != Kind::nutating) {
    a.dphi = phidot_lin_ * t;
    a.dpsi = kind_ == Kind::sleeping ? w3_ * t : psidot_lin_ * t;
    return a;
  }
  const Phase p = phase(tau0_ + rate_ * t);
  const double u1 = nutation_.u_min, u2 = nutation_.u_max;
  a.u = u1 + du_ * p.sn * p.sn;
  a.udot = 2.0 * du_ * p.sn * p.cn * p.dn * rate_;
  // sin(theta) from 1 - u = (1 - u2) + du cn^2 and 1 + u = (1 + u1) + du sn^2: sums, no
  // cancellation near the poles.
  a.one_minus_u = (1.0 - u2) + du_ * p.cn * p.cn;
  a.one_plus_u = (1.0 + u1) + du_ * p.sn * p.sn;
  a.dtheta = std::atan2(std::sqrt(a.one_minus_u * a.one_plus_u), a.u) - theta0_;
  const double dG_plus = c_plus_ != 0.0 ? excess(p, n_plus_, complete_plus_) - G_plus0_ : 0.0;
  const double dG_minus = c_minus_ != 0.0 ? excess(p, n_minus_, complete_minus_) - G_minus0_ : 0.0;
  a.dphi = phidot_lin_ * t + c_plus_ * dG_plus + c_minus_ * dG_minus;
  a.dpsi = psidot_lin_ * t - c_plus_ * dG_plus + c_minus_ * dG_minus;
  return a;
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
  const double phidot = 0.5 * (b_ - a_) / a.one_minus_u + 0.5 * (b_ + a_) / a.one_plus_u;
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
