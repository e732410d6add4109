#include "core/exact_free_body.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "core/elliptic.hpp"

namespace wobble {

namespace {
Mat3 rot_z(double phi) {
  Mat3 R;
  const double c = std::cos(phi), s = std::sin(phi);
  R << c, -s, 0, s, c, 0, 0, 0, 1;
  return R;
}

double sgn(double x) {
  return x < 0.0 ? -1.0 : 1.0;
}
}  // namespace

// Rows u1 = (m1 m3, m2 m3, -rho^2)/(rho |m|), u2 = (-m2, m1, 0)/rho, u3 = m/|m|,
// rho^2 = m1^2 + m2^2 > 0.
Mat3 precession_frame(const Vec3& m) {
  const double rho2 = m[0] * m[0] + m[1] * m[1], rho = std::sqrt(rho2), M = m.norm();
  Mat3 P;
  P.row(0) << m[0] * m[2] / (rho * M), m[1] * m[2] / (rho * M), -rho2 / (rho * M);
  P.row(1) << -m[1] / rho, m[0] / rho, 0.0;
  P.row(2) = m.transpose() / M;
  return P;
}

ExactFreeMotion::ExactFreeMotion(const Vec3& I_P, const Vec3& m0_P, const Quat& q0_PtoS)
    : I_(I_P), m0_(m0_P), q0_(q0_PtoS.normalized()) {
  FreeBody{I_P}.validate();
  if (!m0_P.allFinite()) throw std::invalid_argument("exact free body: m0 must be finite");
  int zeros = 0;
  for (int i = 0; i < 3; ++i) zeros += m0_P[i] == 0.0 ? 1 : 0;
  if (zeros == 3) throw std::invalid_argument("exact free body: m0 must not be zero");
  using DD = DoubleDouble;
  if (zeros == 2) {  // steady rotation about a principal axis, at |m_k| / I_k
    for (int k = 0; k < 3; ++k) {
      if (m0_P[k] != 0.0) rate_dd_ = DD(std::abs(m0_P[k])) / DD(I_[k]);
    }
    return;
  }
  for (int j = 0; j < 3; ++j) {
    const int a = (j + 1) % 3, b = (j + 2) % 3;
    if (I_[a] == I_[b]) {
      kind_ = Kind::symmetric;
      axis_ = j;
      I_perp_ = I_[a];
      // (I_perp - I_j) / (I_j I_perp), not 1/I_j - 1/I_perp: the difference of two rounded
      // reciprocals loses its digits for an almost spherical top.
      c_ = (I_perp_ - I_[j]) / (I_[j] * I_perp_) * m0_[j];
      if (c_ != 0.0) period_ = 2.0 * M_PI / std::abs(c_);
      // The rates to double-double, so that the angles c t and |L| t / I_perp keep their digits
      // over many turns (as the elliptic phase below): in double each rate's rounding, a few
      // eps, grows into the angle with t (7e-9 rad of a flying plate's attitude after 1e7 s).
      c_dd_ = two_sum(I_perp_, -I_[j]) / two_prod(I_[j], I_perp_) * DD(m0_[j]);
      DD L2;
      for (int k = 0; k < 3; ++k) L2 = L2 + two_prod(m0_[k], m0_[k]);
      rate_dd_ = sqrt(L2) / DD(I_perp_);
      return;
    }
  }
  kind_ = Kind::elliptic;
  // W: the axes sorted ascending by a proper permutation (a row negated if it was odd).
  std::array<int, 3> idx{0, 1, 2};
  std::sort(idx.begin(), idx.end(), [&](int x, int y) { return I_[x] < I_[y]; });
  Mat3 S = Mat3::Zero();
  for (int i = 0; i < 3; ++i) S(i, idx[i]) = 1.0;
  if (S.determinant() < 0) S.row(2) *= -1.0;
  Vec3 J(I_[idx[0]], I_[idx[1]], I_[idx[2]]);
  Vec3 m = S * m0_;
  // D = |m|^2 - 2 T J2 = m3^2 (J3-J2)/J3 - m1^2 (J2-J1)/J1, in factored form, to
  // double-double (it decides k'^2, and so the period, whose rounding grows with time).
  const auto difference = [](double x, double y) { return two_sum(x, -y); };  // exact
  const DD alpha = sqrt(difference(J[2], J[1]) / DD(J[2])),
           beta = sqrt(difference(J[1], J[0]) / DD(J[0]));
  const DD a3 = alpha * DD(std::abs(m[2])), b1 = beta * DD(std::abs(m[0]));
  const DD D_dd = (a3 - b1) * (a3 + b1);
  const double D = D_dd.hi;
  Mat3 flip = Mat3::Identity();
  if (D < 0.0) {  // m circles the axis of least moment: make it W's third axis
    flip << 0, 0, 1, 0, -1, 0, 1, 0, 0;
    J = Vec3(J[2], J[1], J[0]);
    m = flip * m;
  }
  C_ = flip * S;
  J_ = J;
  const double d21 = J[1] - J[0], d31 = J[2] - J[0], d32 = J[2] - J[1];
  const double m1 = m[0], m2 = m[1], m3 = m[2];
  M_ = m.norm();
  const double A = m1 * m1 * d31 / J[0] + m2 * m2 * d32 / J[1];  // 2 T J3 - |m|^2
  // B = |m|^2 - 2 T J1, to double-double.
  // The phase's rate and period to double-double (the phase u0 + lambda t is formed so too).
  const DD d21_dd = difference(J[1], J[0]), d31_dd = difference(J[2], J[0]),
           d32_dd = difference(J[2], J[1]);
  const DD B_dd = two_prod(m2, m2) * d21_dd / DD(J[1]) + two_prod(m3, m3) * d31_dd / DD(J[2]);
  amp_ = Vec3(std::sqrt(m1 * m1 + m2 * m2 * J[0] * d32 / (J[1] * d31)),
              std::sqrt(m1 * m1 * J[1] * d31 / (J[0] * d32) + m2 * m2),
              std::sqrt(m2 * m2 * J[2] * d21 / (J[1] * d31) + m3 * m3));
  lambda_dd_ = sqrt(d32_dd * B_dd / (DD(J[0]) * DD(J[1]) * DD(J[2])));
  lambda_ = lambda_dd_.value();
  // k'^2 = (J3-J1) D / ((J3-J2) B): every factor keeps its sign, so no cancellation.
  const DD kc2_dd = d31_dd * D_dd / (d32_dd * B_dd);
  kc2_ = std::clamp(kc2_dd.value(), 0.0, 1.0);
  (void)A;
  sign_ = Vec3(sgn(m1), 0.0, sgn(m3));
  sign_[1] = sign_[0] * sign_[2] * sgn(d32);
  const double sn0 = std::clamp(sign_[1] * m2 / amp_[1], -1.0, 1.0);
  const double cn0 = std::clamp(std::abs(m1) / amp_[0], 0.0, 1.0);
  const double h = std::hypot(sn0, cn0);
  u0_ = incomplete_F(sn0 / h, cn0 / h, kc2_);
  K_ = std::numeric_limits<double>::infinity();  // on the separatrix
  if (kc2_ > 0.0) {
    // k'^2 rounded above 1 is a sphere up to rounding: K(k'^2 = 1) = pi / 2.
    K_dd_ = complete_K_dd(kc2_dd.hi <= 1.0 ? kc2_dd : DD(1.0));
    K_ = K_dd_.value();
    period_ = (DD(4.0) * K_dd_ / lambda_dd_).value();
  }
  n_ = -J[2] * d21 / (J[0] * d32);
  phi_rate_ = M_ / J[0];
  phi_coef_ = M_ * d21 * d31 / (J[0] * J[0] * d32 * lambda_);
  Gc_ = kc2_ > 0.0 ? complete_third_kind_excess(kc2_, n_) : 0.0;
  if (kc2_ > 0.0) {
    // The precession's terms that grow with t, phi_rate t and phi_coef 2 j Gc, to double-double.
    const DD M_dd = sqrt(two_prod(m1, m1) + two_prod(m2, m2) + two_prod(m3, m3));
    const DD n_dd = -(DD(J[2]) * d21_dd) / (DD(J[0]) * d32_dd);
    phi_rate_dd_ = M_dd / DD(J[0]);
    const DD phi_coef_dd = M_dd * d21_dd * d31_dd / (DD(J[0]) * DD(J[0]) * d32_dd * lambda_dd_);
    phi_per_half_period_dd_ =
        DD(2.0) * phi_coef_dd * complete_third_kind_excess_dd(kc2_dd, DD(1.0) - n_dd);
  }
  G0_ = G(phase_at(0.0));
  const Mat3 R0 = q0_.toRotationMatrix() * C_.transpose();  // W -> S at t = 0
  Q_ = R0 * precession_frame(m).transpose();
}

// u = u0 + lambda t reduced by the period 2K, and sn, cn, dn of u itself: sn and cn change
// sign every 2K, dn does not. u and its reduction in double-double: in double, the rounding of
// lambda t and of j 2K (eps u) would be the phase's error, growing with t.
ExactFreeMotion::Phase ExactFreeMotion::phase_at(double t) const {
  Phase p;
  if (std::isfinite(K_)) {
    const DoubleDouble u = DoubleDouble(u0_) + lambda_dd_ * DoubleDouble(t);
    p.reduced = reduce_by_half_period(u, K_dd_, kc2_);
  } else {
    p.reduced = reduce_by_half_period(u0_ + lambda_ * t, K_, kc2_);
  }
  const double odd = p.reduced.sign();
  p.sn = odd * p.reduced.of_r.sn;
  p.cn = odd * p.reduced.of_r.cn;
  p.dn = p.reduced.of_r.dn;
  return p;
}

// (Pi(n; am u) - u)/n, continued past |u| = K through the periods.
double ExactFreeMotion::G(const Phase& p) const {
  return third_kind_excess(p.reduced, kc2_, n_, Gc_);
}

// m in W: (s1 a1 cn, s2 a2 sn, s3 a3 dn).
Vec3 ExactFreeMotion::m_W(const Phase& p) const {
  return Vec3(sign_[0] * amp_[0] * p.cn, sign_[1] * amp_[1] * p.sn, sign_[2] * amp_[2] * p.dn);
}

// phi = phi_rate t - phi_coef (G(u) - G0), G(u) = 2 j Gc + (the excess of r). The two terms
// that grow with t, phi_rate t - phi_coef 2 j Gc, are formed and reduced by 2 pi in
// double-double (in double their rounding, eps per radian turned, would be phi's error); the
// bounded rest in double.
double ExactFreeMotion::precession_angle(double t, const Phase& p) const {
  if (!std::isfinite(K_)) return phi_rate_ * t - phi_coef_ * (G(p) - G0_);  // the separatrix
  const DoubleDouble growing =
      phi_rate_dd_ * DoubleDouble(t) - phi_per_half_period_dd_ * DoubleDouble(p.reduced.j);
  const double excess = third_kind_excess(p.reduced.of_r.sn, p.reduced.of_r.cn, kc2_, n_);
  return remainder_two_pi(growing) - phi_coef_ * (excess - G0_);
}

FreeBodyState ExactFreeMotion::at_elliptic(double t) const {
  const Phase p = phase_at(t);
  const Vec3 m = m_W(p);
  const double phi = precession_angle(t, p);
  const Mat3 R_WtoS = Q_ * rot_z(phi) * precession_frame(m);
  FreeBodyState s;
  s.m_B = C_.transpose() * m;
  s.q_BtoS = Quat(Mat3(R_WtoS * C_)).normalized();
  return s;
}

double ExactFreeMotion::fastest_phase_rate() const {
  switch (kind_) {
    case Kind::steady:
      return rate_dd_.hi;
    case Kind::symmetric:
      return std::max(std::abs(c_dd_.hi), std::abs(rate_dd_.hi));
    case Kind::elliptic:
      break;
  }
  return std::max(std::abs(lambda_), std::abs(phi_rate_));
}

double ExactFreeMotion::angle(const DoubleDouble& rate, double t) {
  return remainder_two_pi(rate * DoubleDouble(t));
}

Vec3 ExactFreeMotion::momentum_at(double t) const {
  switch (kind_) {
    case Kind::steady:
      return m0_;
    case Kind::symmetric:
      return Eigen::AngleAxisd(-angle(c_dd_, t), Vec3::Unit(axis_)) * m0_;
    case Kind::elliptic:
      break;
  }
  // m alone needs sn, cn, dn of u, not the third-kind integral of the attitude.
  return C_.transpose() * m_W(phase_at(t));
}

FreeBodyState ExactFreeMotion::at(double t) const {
  FreeBodyState s;
  switch (kind_) {
    case Kind::steady: {
      const Vec3 w = m0_.cwiseQuotient(I_);
      s.m_B = m0_;
      s.q_BtoS = q0_ * Quat(Eigen::AngleAxisd(angle(rate_dd_, t), w.normalized()));
      return s;
    }
    case Kind::symmetric: {
      const Vec3 L_S = q0_ * m0_;
      const Eigen::AngleAxisd body(angle(c_dd_, t), Vec3::Unit(axis_));
      const Eigen::AngleAxisd space(angle(rate_dd_, t), L_S.normalized());
      s.q_BtoS = (Quat(space) * q0_ * Quat(body)).normalized();
      s.m_B = body.inverse() * m0_;
      return s;
    }
    case Kind::elliptic:
      break;
  }
  return at_elliptic(t);
}

}  // namespace wobble
