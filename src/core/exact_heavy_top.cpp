#include "core/exact_heavy_top.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

#include "core/elliptic.hpp"

namespace wobble {

namespace {
using DD = DoubleDouble;

Quat rot_z(double angle) {
  return Quat(Eigen::AngleAxisd(angle, Vec3::UnitZ()));
}

// The start's constants to double-double, from the state as given (m0 and q0 are exact inputs,
// R(q) / |q|^2 its rotation): f(u0 + d) = c0 + c1 d + c2 d^2 + beta d^3 (core/heavy_top.cpp's
// expansion) and b -+ a, each formed as the double chain forms them (sums of vectors whose
// small components carry no cancellation near the poles), at twice the precision.
struct StartDD {
  DD a, beta, b_minus_a, b_plus_a, one_minus_u0, one_plus_u0, c0, c1, c2;
};

StartDD start_dd(const HeavyTop& top, const Vec3& m, const Quat& q) {
  const DD qw = q.w(), qx = q.x(), qy = q.y(), qz = q.z(), two = 2.0;
  const DD n2 = qw * qw + qx * qx + qy * qy + qz * qz;
  const DD e3x = two * (qx * qz + qw * qy) / n2, e3y = two * (qy * qz - qw * qx) / n2;
  const DD u0 = (qw * qw - qx * qx - qy * qy + qz * qz) / n2;
  const DD r11 = (qw * qw + qx * qx - qy * qy - qz * qz) / n2, r12 = two * (qx * qy - qw * qz) / n2;
  const DD r21 = two * (qx * qy + qw * qz) / n2, r22 = (qw * qw - qx * qx + qy * qy - qz * qz) / n2;
  const DD r31 = two * (qx * qz - qw * qy) / n2, r32 = two * (qy * qz + qw * qx) / n2;
  const DD mx = m.x(), my = m.y(), mz = m.z(), I1 = top.I1_kgm2, I3 = top.I3_kgm2;
  const DD Lx = r11 * mx + r12 * my + e3x * mz, Ly = r21 * mx + r22 * my + e3y * mz;
  const DD Lz = r31 * mx + r32 * my + u0 * mz;
  const DD sin0_2 = e3x * e3x + e3y * e3y;
  StartDD s;
  s.one_plus_u0 = u0.hi < 0.0 ? sin0_2 / (DD(1.0) - u0) : DD(1.0) + u0;
  s.one_minus_u0 = u0.hi > 0.0 ? sin0_2 / (DD(1.0) + u0) : DD(1.0) - u0;
  s.a = mz / I1;
  s.beta = DD(2.0) * DD(top.M_kg) * DD(top.g_m_s2) * DD(top.l_m) / I1;
  s.b_minus_a = (Lz * s.one_minus_u0 - Lx * e3x - Ly * e3y) / I1;
  s.b_plus_a = (Lz * s.one_plus_u0 + Lx * e3x + Ly * e3y) / I1;
  // thetadot sin0 = w_S . (-e3y, e3x, 0) and phidot sin0^2 = b - a u0 = L . (z - u0 e3) / I1.
  const DD wx = mx / I1, wy = my / I1, wz = mz / I3;
  const DD w_nodes =
      e3x * (r21 * wx + r22 * wy + e3y * wz) - e3y * (r11 * wx + r12 * wy + e3x * wz);
  const DD phidot_s2 = (Lz * sin0_2 - u0 * (Lx * e3x + Ly * e3y)) / I1;
  const DD P = (w_nodes * w_nodes + phidot_s2 * phidot_s2) / sin0_2;  // thetadot^2 + phidot^2 sin^2
  s.c0 = w_nodes * w_nodes;
  s.c1 = -(s.beta * sin0_2) - two * u0 * P + two * s.a * phidot_s2;
  s.c2 = two * u0 * s.beta - P - s.a * s.a;
  return s;
}

// A root of f(u0 + d) polished from its double value by Newton's method, f in double-double
// (the slope only in double: each step then gains ~52 bits).
DD polish_root(double d0, const StartDD& s) {
  DD d = d0;
  for (int i = 0; i < 3; ++i) {
    const DD f = s.c0 + d * (s.c1 + d * (s.c2 + d * s.beta));
    const double x = d.hi, slope = s.c1.hi + x * (2.0 * s.c2.hi + 3.0 * s.beta.hi * x);
    if (!(slope != 0.0) || !std::isfinite(f.hi)) break;
    d = d - DD(f.value() / slope);
  }
  return d;
}

// |x - y| within rel of |y|: the polished value is the same root as the double one.
bool same_root(const DD& x, double y, double rel) {
  return std::isfinite(x.hi) && std::abs(x.hi - y) <= rel * std::abs(y);
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
  a_ = m0_.z() / I1;  // p_psi / I1
  // The spin's rate to double-double: psi grows by w3 t, hundreds of radians, whose rounding
  // would otherwise be the attitude's error (eps per radian).
  const DoubleDouble w3_dd = DoubleDouble(m0_.z()) / DoubleDouble(top.I3_kgm2);
  psidot_lin_ = w3_dd;
  if (sin0 > 0.0 && sin0 * sin0 == 0.0)
    throw std::invalid_argument(
        "exact heavy top: the axis starts within 1.5e-154 rad of the vertical but not on it (its "
        "tilt's square underflows)");
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
  // Through a pole f vanishes there, b -+ a = 0, and the limit is the pole exactly: the offsets
  // are this start's distances to it (nutation_limits takes its u0 from theta, an ulp apart).
  // Decided on b -+ a formed here without cancellation: near a pole nutation_limits' own can
  // round to zero (cos(theta0) rounds to 1 within 1e-8 rad of upright), and the limit is then
  // short of the pole. With b = -a the motion always reaches hanging once it moves (f = (1 + u)
  // H(u) with H > 0 below the start: its terms in d = u - u0 are all >= 0 there); with b = a
  // it reaches upright only with the energy for it, which nutation_limits decides.
  const bool moving = nutation_.d_min < 0.0 || nutation_.d_max > 0.0;
  nutation_.through_hanging = moving && b_plus_a_ == 0.0 && one_plus_u0 > 0.0;
  nutation_.through_upright = nutation_.through_upright && b_minus_a_ == 0.0;
  if (nutation_.through_hanging) nutation_.d_min = -one_plus_u0;
  if (nutation_.through_upright) nutation_.d_max = one_minus_u0;
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
  // u3 - 1 from the sum of the roots carries a rounding of about eps (1 + a^2 / beta): all of
  // it where u3 - 1 is small. A top released near upright with too little spin to sleep has
  // u3 - 1 and 1 - u2 both ~ theta0^2, and u3 - u2 is k'^2's numerator (released 1e-8 rad from
  // upright, w was 3e-2 off a 30-digit integration after 2 s; 1e-4 rad, 8e-9). From
  // f(1) = -(b - a)^2 = beta (1 - u1)(1 - u2)(1 - u3) it is instead a quotient of distances to
  // the pole, each without cancellation where the upper limit is no nearer the pole than half
  // the start's distance (1 - u2 = (1 - u0) - d_max then keeps all but a bit).
  const bool third_root_from_pole = one_minus_u2_ > 0.0 && nutation_.d_max <= 0.5 * one_minus_u0;
  const double u3_minus_1 =
      third_root_from_pole
          ? b_minus_a_ * b_minus_a_ / (beta * (one_minus_u0 - nutation_.d_min) * one_minus_u2_)
          : std::max(0.0, u0_ + (P + a_ * a_) / beta - u1 - u2 - 1.0);
  u3_ = 1.0 + u3_minus_1;
  // Likewise an upper limit near upright that the start is far from (a top thrown over the top
  // that passes 2.4e-6 rad from upright has 1 - u2 = 3e-12, and (1 - u0) - d_max kept 1e-5 of
  // it): from f(1), 1 - u2 = (b - a)^2 / (beta (1 - u1)(u3 - 1)), u3 - 1 from the roots' sum,
  // where u3 is the farther from the pole (else both are near it and the sum is no better).
  DD d_max_chain = nutation_.d_max;
  if (!nutation_.through_upright && nutation_.d_max > 0.5 * one_minus_u0 &&
      u3_minus_1 > one_minus_u2_) {
    one_minus_u2_ =
        b_minus_a_ * b_minus_a_ / (beta * (one_minus_u0 - nutation_.d_min) * u3_minus_1);
    d_max_chain = DD(one_minus_u0) - DD(one_minus_u2_);  // exact: 1 - u2 = (1 - u0) - this
  }
  // u3 - u2 = (u3 - 1) + (1 - u2), u3 - u1 = (u3 - u2) + du: sums.
  const double u3_minus_u2 = u3_minus_1 + one_minus_u2_, u3_minus_u1 = u3_minus_u2 + du_;
  // A lower limit near hanging that the start is far from: 1 + u1 = (1 + u0) + d_min cancels,
  // and d_min's rounding, eps, is all of 1 + u1 (a slow top that swings 1.6e-5 rad past hanging
  // has 1 + u1 = 1.3e-10, known to 3e-6 so: it sets n- and how far phi turns as the axle passes
  // the pole, and phi came out 3.1e-6 rad short after the first passage). From
  // f(-1) = -(b + a)^2 = -beta (1 + u1)(1 + u2)(1 + u3) it is a quotient of sums instead.
  DD d_min_chain = nutation_.d_min;
  if (!nutation_.through_hanging && nutation_.d_min < -0.5 * one_plus_u0) {
    const double one_plus_u1 =
        b_plus_a_ * b_plus_a_ / (beta * (one_plus_u0 + nutation_.d_max) * (2.0 + u3_minus_1));
    d_min_chain = DD(one_plus_u1) - DD(one_plus_u0);  // exact: 1 + u1 = (1 + u0) + this
  }
  // The chain in double, lifted; refined below where the polished roots confirm it.
  Chain chain{.d_min = d_min_chain,
              .d_max = d_max_chain,
              .one_minus_u0 = one_minus_u0,
              .one_plus_u0 = one_plus_u0,
              .u3_minus_u1 = u3_minus_u1,
              .u3_minus_u2 = u3_minus_u2,
              .b_minus_a = b_minus_a_,
              .b_plus_a = b_plus_a_,
              .a = m0_.z() / DD(I1),
              .beta = beta,
              .w3 = w3_dd,
              .third_root_from_pole = third_root_from_pole};
  if (u3_minus_u2 > 0.0) refine(chain);
  set_up_rates(chain);  // through a pole, 1 + u1 or 1 - u2 is 0 exactly: d is the start's offset
  set_up_phase(sin0 * start.thetadot, chain);
}

void ExactHeavyTop::refine(Chain& c) const {
  const StartDD s = start_dd(top_, m0_, q0_);
  // A limit at a pole is the pole: 1 + u1 = 0 or 1 - u2 = 0 exactly, not Newton's approach to it.
  const bool hanging = nutation_.through_hanging, upright = nutation_.through_upright;
  const DD d_min = hanging ? -s.one_plus_u0 : polish_root(c.d_min.hi, s);
  const DD d_max = upright ? s.one_minus_u0 : polish_root(c.d_max.hi, s);
  // The third root as the double chain takes it (the constructor): near upright from
  // f(1) = -(b - a)^2 = beta (1 - u1)(1 - u2)(1 - u3), a quotient of distances to the pole (in
  // double-double too, the sum leaves u3 - u2 ~ theta0^2 only 1e-32 absolute: 1e-9 relative for
  // a top released 1e-12 rad from upright), else from the sum of the roots, -c2 / beta.
  const DD one_minus_u2 = s.one_minus_u0 - d_max, one_minus_u1 = s.one_minus_u0 - d_min;
  const DD u3_minus_u2 =
      c.third_root_from_pole
          ? s.b_minus_a * s.b_minus_a / (s.beta * one_minus_u1 * one_minus_u2) + one_minus_u2
          : -(s.c2 / s.beta) - d_min - d_max - d_max;
  const DD u3_minus_u1 = u3_minus_u2 + (d_max - d_min);
  // Newton's method near a double root (a nutation near rounding, a top all but in steady
  // precession) or a root at a pole may settle elsewhere: keep the double chain unless every
  // refined difference is the double one to its own accuracy (1e-9 is far above it and far
  // below another root's distance). The scene tests' near-steady tops (du ~ 1e-16) take it.
  constexpr double kSameRoot = 1e-9;
  const double du = c.d_max.hi - c.d_min.hi;
  if (!same_root(d_max - d_min, du, kSameRoot) ||
      !same_root(u3_minus_u1, c.u3_minus_u1.hi, kSameRoot) ||
      !same_root(u3_minus_u2, c.u3_minus_u2.hi, kSameRoot) ||
      (!hanging &&
       !same_root(s.one_plus_u0 + d_min, (c.one_plus_u0 + c.d_min).value(), kSameRoot)) ||
      (!upright &&
       !same_root(s.one_minus_u0 - d_max, (c.one_minus_u0 - c.d_max).value(), kSameRoot))) {
    return;
  }
  c.d_min = d_min;
  c.d_max = d_max;
  c.one_minus_u0 = s.one_minus_u0;
  c.one_plus_u0 = s.one_plus_u0;
  c.u3_minus_u1 = u3_minus_u1;
  c.u3_minus_u2 = u3_minus_u2;
  c.b_minus_a = upright ? DD(0.0) : s.b_minus_a;
  c.b_plus_a = hanging ? DD(0.0) : s.b_plus_a;
  c.a = s.a;
  c.beta = s.beta;
}

void ExactHeavyTop::set_up_rates(const Chain& c) {
  const DD du = c.d_max - c.d_min;
  const DD one_minus_u1 = c.one_minus_u0 - c.d_min, one_plus_u1 = c.one_plus_u0 + c.d_min;
  du_ = du.value();
  one_plus_u1_ = std::max(0.0, one_plus_u1.value());
  one_minus_u2_ = std::max(0.0, (c.one_minus_u0 - c.d_max).value());
  k2_ = (du / c.u3_minus_u1).value();
  const DD kc2 = c.u3_minus_u2 / c.u3_minus_u1;
  kc2_ = std::clamp(kc2.value(), 0.0, 1.0);
  K_ = std::numeric_limits<double>::infinity();  // on the separatrix
  const DD rate = DD(0.5) * sqrt(c.beta * c.u3_minus_u1);
  rate_ = rate.hi;
  rate_dd_ = rate;
  if (kc2_ > 0.0) {
    K_dd_ = complete_K_dd(kc2.hi <= 1.0 ? kc2 : DD(1.0));
    K_ = K_dd_.value();
    period_ = (DD(2.0) * K_dd_ / rate).value();
  }
  // The partial fractions over 1 - u and 1 + u; a term whose numerator is zero is left out (at
  // u1 = -1 the numerator b + a is zero with it, and n- would be infinite).
  // 1 - n+ = (1 - u2) / (1 - u1), not from n+: released near upright, n+ is within theta0^2
  // of 1, and 1 - n+ formed from it, even in double-double, kept no digit below 1e-16 rad.
  const DD n_plus = du / one_minus_u1;
  const DD one_minus_n_plus = (c.one_minus_u0 - c.d_max) / one_minus_u1;
  n_plus_ = n_plus.value();
  one_minus_n_plus_ = one_minus_n_plus.value();
  const DD lin_plus = DD(0.5) * c.b_minus_a / one_minus_u1;
  phidot_lin_ = lin_plus;
  psidot_lin_ = c.w3 - c.a - lin_plus;
  if (b_minus_a_ != 0.0) {
    c_plus_ = lin_plus * n_plus / rate;
    if (kc2_ > 0.0) complete_plus_ = complete_third_kind_excess_dd(kc2, one_minus_n_plus);
  }
  if (b_plus_a_ != 0.0 && one_plus_u1_ > 0.0) {
    const DD n = -(du / one_plus_u1), one_minus_n = DD(1.0) - n;
    const DD lin_minus = DD(0.5) * c.b_plus_a / one_plus_u1;
    if (n.hi >= -1.0) {
      n_minus_ = n.value();
      one_minus_n_minus_ = one_minus_n.value();
      phidot_lin_ = phidot_lin_ + lin_minus;
      psidot_lin_ = psidot_lin_ + lin_minus;
      c_minus_ = lin_minus * n / rate;
      if (kc2_ > 0.0) complete_minus_ = complete_third_kind_excess_dd(kc2, one_minus_n);
    } else {
      set_up_minus_transformed(n, one_minus_n, lin_minus, du / c.u3_minus_u1, kc2, rate);
    }
  }
}

// A top that swings near hanging down (1 + u1 small beside du) has n- = -du/(1 + u1) << -1:
// Pi(n-; am tau) = tau + n- G is then a small difference of large terms (lin- t against c- G,
// hundreds of radians a half period apart for one that swings to 0.17 rad from the bottom), and
// G's rounding in double, times c-, was 1e-13 rad in phi and psi. Pi(n-) itself is small, and
// A&S 17.7.15 writes it with terms no larger (core/elliptic.hpp, negative_third_kind):
//   Pi(n-; am tau) = linear tau + excess_coef G_N(tau) + atan_coef atan(p sn cn / dn).
void ExactHeavyTop::set_up_minus_transformed(const DD& n, const DD& one_minus_n,
                                             const DD& lin_minus, const DD& k2, const DD& kc2,
                                             const DD& rate) {
  const NegativeThirdKind form = negative_third_kind(n, one_minus_n, k2, kc2);
  n_minus_ = form.N.value();
  one_minus_n_minus_ = form.one_minus_N.value();
  phidot_lin_ = phidot_lin_ + lin_minus * form.linear;
  psidot_lin_ = psidot_lin_ + lin_minus * form.linear;
  const DD scale = lin_minus / rate;
  c_minus_ = scale * form.excess_coef;
  if (kc2_ > 0.0) complete_minus_ = complete_third_kind_excess_dd(kc2, form.one_minus_N);
  minus_atan_p_ = form.atan_p;
  minus_atan_coef_ = (scale * form.atan_coef).value();
}

double ExactHeavyTop::minus_atan(const Phase& p) const {
  return minus_atan_coef_ == 0.0 ? 0.0 : negative_third_kind_atan(minus_atan_p_, p.of_r);
}

// tau0 from the start, and the integrals' values there (G± grow from them).
void ExactHeavyTop::set_up_phase(double sin_thetadot0, const Chain& chain) {
  // tau0: sn^2(tau0) = (u0 - u1)/du, on the rising side (u' >= 0) for tau0 in [0, K].
  double sn0 = std::sqrt(std::max(0.0, -nutation_.d_min) / du_);
  double cn0 = std::sqrt(std::max(0.0, nutation_.d_max) / du_);
  // Near a turning point the smaller of sn, cn comes from a difference u0 - u_limit that is a
  // rounding, and so carries only sqrt(eps) (a start at rest could begin moving at 1e-7 of its
  // rates): take it from the start's velocity instead, u' = 2 du sn cn dn tau'.
  const double dn0 =
      std::sqrt((chain.u3_minus_u2.value() + nutation_.d_max) / chain.u3_minus_u1.value());
  const double v = std::abs(sin_thetadot0) / (2.0 * du_ * dn0 * rate_);
  if (sn0 >= cn0) {
    cn0 = v / sn0;
  } else {
    sn0 = v / cn0;
  }
  const double h = std::hypot(sn0, cn0);
  sn0 /= h;
  cn0 /= h;
  // Nearer the turning point at K (sn0 > cn0), tau0 = K - tau' with sn(tau') = cd(tau0),
  // cn(tau') = k' sd(tau0), K in double-double: F(am tau0) in double carried eps K, a time
  // error at every later time (a top released at rest starts exactly at K, now kept exact).
  // dn from the normalised sn0, cn0, so that the complement's sine and cosine are unit.
  const double dn = std::sqrt(cn0 * cn0 + kc2_ * sn0 * sn0), kc = std::sqrt(kc2_);
  const DD F0 = sn0 > cn0 && kc2_ > 0.0 ? K_dd_ - DD(incomplete_F(cn0 / dn, kc * sn0 / dn, kc2_))
                                        : DD(incomplete_F(sn0, cn0, kc2_));
  tau0_dd_ = sin_thetadot0 > 0.0 ? -F0 : F0;  // theta rising is u falling
  const Phase p0 = phase_at(0.0);
  j0_ = p0.j;  // 0, or +-1 when tau0 rounds to the far side of +-K
  // Through a pole: the sign that makes sin(theta0) > 0 (angles()).
  if (nutation_.through_hanging) sign_hanging_ = p0.sign() * p0.of_r.sn >= 0.0 ? 1.0 : -1.0;
  if (nutation_.through_upright) sign_upright_ = p0.sign() * p0.of_r.cn >= 0.0 ? 1.0 : -1.0;
  if (c_plus_.hi != 0.0) G_plus0_ = incomplete_excess(p0, n_plus_, one_minus_n_plus_);
  if (c_minus_.hi != 0.0) G_minus0_ = incomplete_excess(p0, n_minus_, one_minus_n_minus_);
  minus_atan0_ = minus_atan(p0);
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
  if (kind_ != Kind::nutating) {
    a.dphi = remainder_two_pi(phidot_lin_ * t_dd);
    a.dpsi = remainder_two_pi(psidot_lin_ * t_dd);
    return a;
  }
  // tau, its reduction by 2K and the integrals' complete parts 2 j (Pi(n) - K) / n, which grow
  // with t, in double-double; the reduced parts, bounded, in double.
  const Phase p = phase_at(t);
  const double sn = p.of_r.sn, cn = p.of_r.cn, dn = p.of_r.dn;
  const double u1 = nutation_.u_min;
  a.u = u1 + du_ * sn * sn;
  a.udot = 2.0 * du_ * sn * cn * dn * rate_;
  // sin(theta) from 1 - u = (1 - u2) + du cn^2 and 1 + u = (1 + u1) + du sn^2: sums, no
  // cancellation near the poles.
  a.one_minus_u = one_minus_u2_ + du_ * cn * cn;
  a.one_plus_u = one_plus_u1_ + du_ * sn * sn;
  if (sign_hanging_ == 0.0 && sign_upright_ == 0.0) {
    // Away from the poles' passages: one square root and one division, the per-sample cost.
    const double sin_theta = std::sqrt(a.one_minus_u * a.one_plus_u);
    a.dtheta = std::atan2(sin_theta, a.u) - theta0_;
    a.thetadot = sin_theta > 0.0 ? -a.udot / sin_theta : 0.0;
    a.phidot_sin_theta =
        sin_theta > 0.0
            ? (0.5 * b_minus_a_ * a.one_plus_u + 0.5 * b_plus_a_ * a.one_minus_u) / sin_theta
            : 0.0;
  } else {
    // Through a pole the axle passes the vertical: sqrt(1 + u) = sqrt(du) |sn| (hanging) or
    // sqrt(1 - u) = sqrt(du) |cn| (upright) takes the sign of sn(tau) or cn(tau) (sn(r) or
    // cn(r) flipped with each half period), and theta goes on past pi or 0. Rot(n0, theta -
    // theta0) carries the attitude through; in the Euler angles phi and psi would jump by pi.
    // theta' = -u'/sin(theta) with u' = 2 du sn cn dn tau': sn (cn) cancels, finite at the pole.
    const double flip = p.sign(), root_du = std::sqrt(du_);
    // sqrt(1 + u) and du sn / sqrt(1 + u); sqrt(1 - u) and cn / sqrt(1 - u).
    double root_plus, plus_part, root_minus, minus_part;
    if (sign_hanging_ != 0.0) {
      root_plus = sign_hanging_ * flip * root_du * sn;
      plus_part = sign_hanging_ * flip * root_du;
    } else {
      root_plus = std::sqrt(a.one_plus_u);
      plus_part = root_plus > 0.0 ? du_ * sn / root_plus : 0.0;
    }
    if (sign_upright_ != 0.0) {
      root_minus = sign_upright_ * flip * root_du * cn;
      minus_part = sign_upright_ * flip / root_du;
    } else {
      root_minus = std::sqrt(a.one_minus_u);
      minus_part = root_minus > 0.0 ? cn / root_minus : 0.0;
    }
    a.dtheta = std::atan2(root_minus * root_plus, a.u) - theta0_;
    a.thetadot = -2.0 * dn * rate_ * plus_part * minus_part;
    a.phidot_sin_theta = (b_minus_a_ == 0.0 ? 0.0 : 0.5 * b_minus_a_ * root_plus / root_minus) +
                         (b_plus_a_ == 0.0 ? 0.0 : 0.5 * b_plus_a_ * root_minus / root_plus);
  }
  const DD two_j = 2.0 * (p.j - j0_);  // exact
  const auto dG = [&](const DD& c, double n, double one_minus_n, const DD& complete, double G0) {
    return c.hi == 0.0 ? DD()
                       : c * (two_j * complete + DD(incomplete_excess(p, n, one_minus_n) - G0));
  };
  const DD dG_plus = dG(c_plus_, n_plus_, one_minus_n_plus_, complete_plus_, G_plus0_);
  const DD dG_minus = dG(c_minus_, n_minus_, one_minus_n_minus_, complete_minus_, G_minus0_) +
                      DD(minus_atan_coef_ * (minus_atan(p) - minus_atan0_));
  a.dphi = remainder_two_pi(phidot_lin_ * t_dd + dG_plus + dG_minus);
  a.dpsi = remainder_two_pi(psidot_lin_ * t_dd - dG_plus + dG_minus);
  return a;
}

ExactHeavyTop::Phase ExactHeavyTop::phase_at(double t) const {
  // The separatrix (K infinite): no reduction, and tau0 is a double (F(am tau0) in double).
  if (!std::isfinite(K_)) return reduce_by_half_period(tau0_dd_.hi + rate_ * t, K_, kc2_);
  return reduce_by_half_period(tau0_dd_ + rate_dd_ * DD(t), K_dd_, kc2_);
}

double ExactHeavyTop::fastest_phase_rate() const {
  if (kind_ != Kind::nutating || !std::isfinite(K_))
    return std::max({std::abs(phidot_lin_.hi), std::abs(psidot_lin_.hi), std::abs(rate_)});
  // 2 j grows by tau' / K per second.
  const double half_periods = std::abs(rate_) / K_;
  const double integrals = std::abs(c_plus_.hi * complete_plus_.hi) * half_periods +
                           std::abs(c_minus_.hi * complete_minus_.hi) * half_periods;
  return std::max({std::abs(rate_), std::abs(phidot_lin_.hi) + integrals,
                   std::abs(psidot_lin_.hi) + integrals});
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
  s.q_BtoS =
      (turn_phi * Quat(Eigen::AngleAxisd(a.dtheta, nodes0_S_)) * q0_ * rot_z(a.dpsi)).normalized();
  // The angular velocity from the Euler rates, w = phi' z + theta' n + psi' e3, written as
  // theta' n + phi' sin(theta) (e3 x n) + w3 e3 (psi' = w3 - u phi'): near a pole phi' and psi'
  // grow as 1/(1 -+ u), and their terms, summed, cancelled to the error. In the body frame n is
  // n_B and e3 x n is z x n_B; the axial part, p_psi, is conserved.
  const Vec3 n_B = s.q_BtoS.conjugate() * (turn_phi * nodes0_S_);
  const double c = a.phidot_sin_theta, thetadot = a.thetadot;
  s.m_B = Vec3(top_.I1_kgm2 * (thetadot * n_B.x() - c * n_B.y()),
               top_.I1_kgm2 * (thetadot * n_B.y() + c * n_B.x()), m0_.z());
  return s;
}

}  // namespace wobble
