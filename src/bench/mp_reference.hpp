#pragma once
/// @file
/// 50-digit references for the exact solutions (bench and hard-case tests): the torque-free
/// body and the heavy symmetric top.
#include <algorithm>
#include <array>
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "core/exact_free_body.hpp"
#include "core/exact_heavy_top.hpp"
#include "core/inertia.hpp"

namespace wobble::bench {

// The exact solution's m(t) evaluated again at 50 digits, from the same formulas (for a body
// with ascending moments circling its third axis): sn, cn, dn and F by Boost.Math in
// multiprecision, where k = sqrt(1 - k'^2) keeps k'^2 = 1e-16.
/// Valid for moments in monotonic order (ascending or descending) with m circling e3
/// (m3^2 (I3-I2)/I3 > m1^2 (I2-I1)/I1); mp_free_momentum turns any body into that frame.
struct MpMotion {
  using mp = boost::multiprecision::cpp_bin_float_50;
  mp a1, a2, a3, lambda, u0, k, s1, s2, s3;
  mp n, phi_rate, phi_coef;  ///< the precession angle's constants (core/exact_free_body.hpp)
  MpMotion(const Vec3& I, const Vec3& m0) {
    const mp J1 = I[0], J2 = I[1], J3 = I[2], m1 = m0[0], m2 = m0[1], m3 = m0[2];
    const mp d21 = J2 - J1, d31 = J3 - J1, d32 = J3 - J2;
    const mp M = sqrt(m1 * m1 + m2 * m2 + m3 * m3);
    const mp B = m2 * m2 * d21 / J2 + m3 * m3 * d31 / J3;
    const mp D = m3 * m3 * d32 / J3 - m1 * m1 * d21 / J1;
    a1 = sqrt(m1 * m1 + m2 * m2 * J1 * d32 / (J2 * d31));
    a2 = sqrt(m1 * m1 * J2 * d31 / (J1 * d32) + m2 * m2);
    a3 = sqrt(m2 * m2 * J3 * d21 / (J2 * d31) + m3 * m3);
    lambda = sqrt(d32 * B / (J1 * J2 * J3));
    k = sqrt(1 - d31 * D / (d32 * B));
    s1 = m1 < 0 ? -1 : 1;
    s3 = m3 < 0 ? -1 : 1;
    s2 = s1 * s3 * (d32 < 0 ? -1 : 1);  // moments descending: m circles the least axis
    u0 = boost::math::ellint_1(k, atan2(s2 * m2 / a2, abs(m1) / a1));
    n = -J3 * d21 / (J1 * d32);
    phi_rate = M / J1;
    phi_coef = M * d21 * d31 / (J1 * J1 * d32 * lambda);
  }
  /// (Pi(n; am u | k) - u) / n by a second route: Legendre's Pi from Boost.Math's ellint_3 (not
  /// Carlson's R_J), am u from the reduced argument, continued through the periods.
  mp G(const mp& u) const {
    const mp K = boost::math::ellint_1(k), j = round(u / (2 * K)), r = u - 2 * K * j;
    mp cn, dn;
    const mp sn = boost::math::jacobi_elliptic(k, r, &cn, &dn);
    const mp Pi = boost::math::ellint_3(k, n, atan2(sn, cn)) +
                  2 * j * boost::math::ellint_3(k, n, boost::math::constants::pi<mp>() / 2);
    return (Pi - u) / n;
  }
  /// The precession angle phi(t) of the attitude R = Q Rz(phi) P(m(t)), reduced to [-pi, pi].
  double phi_at(double t) const {
    const mp u = u0 + lambda * mp(t);
    const mp phi = phi_rate * mp(t) - phi_coef * (G(u) - G(u0));
    const mp two_pi = 2 * boost::math::constants::pi<mp>();
    return static_cast<double>(phi - two_pi * round(phi / two_pi));
  }
  Vec3 m_at(double t) const {
    mp cn, dn;
    const mp sn = boost::math::jacobi_elliptic(k, u0 + lambda * mp(t), &cn, &dn);
    return Vec3(static_cast<double>(s1 * a1 * cn), static_cast<double>(s2 * a2 * sn),
                static_cast<double>(s3 * a3 * dn));
  }
  double period() const { return static_cast<double>(4 * boost::math::ellint_1(k) / lambda); }
  /// The first time u reaches K (u0 is in [-K, K]).
  double first_K_time() const {
    return static_cast<double>((boost::math::ellint_1(k) - u0) / lambda);
  }
};

/// m(t) of any free body with three distinct moments at 50 digits: the body turned into the
/// frame MpMotion serves (axes sorted by a proper permutation, then reversed if m circles the
/// axis of least moment, as core/exact_free_body does) and back.
/// The working frame of mp_free_momentum: m_W = C m, moments J in W.
struct MpWorkingFrame {
  Mat3 C;
  Vec3 J, m;
};
inline MpWorkingFrame mp_working_frame(const Vec3& I, const Vec3& m0) {
  std::array<int, 3> idx{0, 1, 2};
  std::sort(idx.begin(), idx.end(), [&](int x, int y) { return I[x] < I[y]; });
  Mat3 S = Mat3::Zero();
  for (std::size_t i = 0; i < 3; ++i) S(static_cast<Eigen::Index>(i), idx[i]) = 1.0;
  if (S.determinant() < 0) S.row(2) *= -1.0;
  Vec3 J(I[idx[0]], I[idx[1]], I[idx[2]]);
  Vec3 m = S * m0;
  const double D = m[2] * m[2] * (J[2] - J[1]) / J[2] - m[0] * m[0] * (J[1] - J[0]) / J[0];
  if (D < 0) {
    Mat3 flip;
    flip << 0, 0, 1, 0, -1, 0, 1, 0, 0;
    S = flip * S;
    J = Vec3(J[2], J[1], J[0]);
    m = flip * m;
  }
  return {S, J, m};
}

inline Vec3 mp_free_momentum(const Vec3& I, const Vec3& m0, double t) {
  const MpWorkingFrame w = mp_working_frame(I, m0);
  return w.C.transpose() * MpMotion(w.J, w.m).m_at(t);
}

/// The attitude q_PtoS(t) of the same motion: R_WtoS = Q Rz(phi) P(m_W), with phi and m at 50
/// digits and only this composition in double (a few eps). P(m) is core's precession_frame:
/// phi is measured from it, so the reference must use the same one.
inline Quat mp_free_attitude(const Vec3& I, const Vec3& m0, const Quat& q0, double t) {
  const MpWorkingFrame w = mp_working_frame(I, m0);
  const MpMotion motion(w.J, w.m);
  const auto P = precession_frame;
  const Mat3 Q = q0.normalized().toRotationMatrix() * w.C.transpose() * P(w.m).transpose();
  const Mat3 Rz = Eigen::AngleAxisd(motion.phi_at(t), Vec3::UnitZ()).toRotationMatrix();
  return Quat(Mat3(Q * Rz * P(motion.m_at(t)) * w.C)).normalized();
}

/// The heavy top (core/exact_heavy_top.hpp's conventions) at 50 digits by a second route:
/// the roots of f(u) polished by Newton's method on the cubic at 50 digits (started from
/// double's offsets from the start), sn, cn, dn, F and Pi(n; phi | k) from Boost.Math (ellint_3,
/// not Carlson's R_J), the Euler angles' increments reduced modulo 2 pi at 50 digits. Only the
/// final rotations are composed in double: a few eps. For a nutating top (u1 < u2), the axis not
/// vertical at t = 0. Its 1 - u keeps 50 - 2 log10(1/theta) digits near upright: 18 at 1e-16 rad;
/// MpHeavyTopAt takes more digits for tops nearer.
template <class Real>
struct MpHeavyTopAt {
  using mp = Real;
  HeavyTop top;
  Vec3 m0;
  Quat q0;
  mp I1, I3, a, b, w3, beta, u0, u1, u2, u3, k, rate, tau0, theta0, Kc;
  Vec3 nodes0;

  MpHeavyTopAt(const HeavyTop& t, const Vec3& m, const Quat& q)
      : top(t), m0(m), q0(q.normalized()) {
    I1 = top.I1_kgm2;
    I3 = top.I3_kgm2;
    const mp qw = q0.w(), qx = q0.x(), qy = q0.y(), qz = q0.z();
    const mp n2 = qw * qw + qx * qx + qy * qy + qz * qz;
    // Rows and columns of R(q) / |q|^2 as needed: e3 = R z, (R v)_z = row 3 . v.
    const mp e3x = 2 * (qx * qz + qw * qy) / n2, e3y = 2 * (qy * qz - qw * qx) / n2;
    u0 = (qw * qw - qx * qx - qy * qy + qz * qz) / n2;
    const mp r31 = 2 * (qx * qz - qw * qy) / n2, r32 = 2 * (qy * qz + qw * qx) / n2;
    const mp mx = m0.x(), my = m0.y(), mz = m0.z();
    a = mz / I1;
    b = (r31 * mx + r32 * my + u0 * mz) / I1;
    w3 = mz / I3;
    beta = 2 * mp(top.M_kg) * mp(top.g_m_s2) * mp(top.l_m) / I1;
    const mp sin0 = sqrt(e3x * e3x + e3y * e3y);
    theta0 = atan2(sin0, u0);
    // thetadot = w_S . n0, n0 = (-e3y, e3x, 0) / sin0; w_S = R w_B.
    const mp wx = mx / I1, wy = my / I1, wz = mz / I3;
    const mp r11 = (qw * qw + qx * qx - qy * qy - qz * qz) / n2, r12 = 2 * (qx * qy - qw * qz) / n2;
    const mp r21 = 2 * (qx * qy + qw * qz) / n2, r22 = (qw * qw - qx * qx + qy * qy - qz * qz) / n2;
    const mp wSx = r11 * wx + r12 * wy + e3x * wz, wSy = r21 * wx + r22 * wy + e3y * wz;
    const mp thetadot = (-e3y * wSx + e3x * wSy) / sin0;
    const mp phidot = (b - a * u0) / (sin0 * sin0);
    // The roots as offsets d from the start, f(u0 + d) = c0 + c1 d + c2 d^2 + beta d^3 (the
    // expansion of core/heavy_top.hpp), polished by Newton's method from the double offsets,
    // the third from the sum of the roots (-c2 / beta): released near upright, u2 and u3 are
    // within theta0^2 of 1 and of each other, and rounded to the same double; as offsets they
    // keep their digits, and a start at rest (c0 = 0) keeps its turning point at d = 0 exactly.
    const mp P = thetadot * thetadot + phidot * phidot * sin0 * sin0;
    const mp c0 = thetadot * thetadot * sin0 * sin0;
    const mp c1 = -beta * sin0 * sin0 - 2 * u0 * P + 2 * a * phidot * sin0 * sin0;
    const mp c2 = 2 * u0 * beta - P - a * a;
    const auto polish = [&](mp d) {
      for (int i = 0; i < 12; ++i) {
        const mp g = c0 + d * (c1 + d * (c2 + d * beta)), dg = c1 + d * (2 * c2 + 3 * beta * d);
        if (g == 0 || dg == 0) break;
        d -= g / dg;
      }
      return d;
    };
    const ExactHeavyTop start(top, m0, q0);
    const mp d1 = polish(start.nutation().d_min), d2 = polish(start.nutation().d_max);
    const mp d3 = polish(-c2 / beta - d1 - d2);
    u1 = u0 + d1;
    u2 = u0 + d2;
    u3 = u0 + d3;
    k = sqrt((u2 - u1) / (u3 - u1));
    Kc = boost::math::ellint_1(k);
    rate = sqrt(beta * (u3 - u1)) / 2;
    const mp s = sqrt(std::max(mp(0), (u0 - u1) / (u2 - u1)));
    const mp F0 = boost::math::ellint_1(k, asin(std::min(mp(1), s)));
    tau0 = thetadot > 0 ? mp(-F0) : F0;
    nodes0 = Vec3(static_cast<double>(-e3y / sin0), static_cast<double>(e3x / sin0), 0.0);
  }

  /// Pi(n; am tau | k), am continued past K by its quasi-period (am(tau + 2K) = am(tau) + pi).
  mp Pi(const mp& n, const mp& tau) const {
    const mp j = round(tau / (2 * Kc));
    const mp r = tau - 2 * Kc * j;
    mp cn, dn;
    const mp sn = boost::math::jacobi_elliptic(k, r, &cn, &dn);
    const mp am = atan2(sn, cn);
    const mp pi = boost::math::constants::pi<mp>();
    return boost::math::ellint_3(k, n, am) + 2 * j * boost::math::ellint_3(k, n, pi / 2);
  }

  FreeBodyState at(double t_s) const {
    const mp t = t_s, tau = tau0 + rate * t, du = u2 - u1;
    mp cn, dn;
    const mp sn = boost::math::jacobi_elliptic(k, tau, &cn, &dn);
    const mp u = u1 + du * sn * sn;
    const mp n_plus = du / (1 - u1), n_minus = -du / (1 + u1);
    const mp I_plus = (Pi(n_plus, tau) - Pi(n_plus, tau0)) / rate;
    const mp I_minus = (Pi(n_minus, tau) - Pi(n_minus, tau0)) / rate;
    const mp half_plus = (b - a) / (2 * (1 - u1)), half_minus = (b + a) / (2 * (1 + u1));
    const mp two_pi = 2 * boost::math::constants::pi<mp>();
    const auto reduced = [&](const mp& x) { return static_cast<double>(x - two_pi * round(x / two_pi)); };
    const mp dphi = half_plus * I_plus + half_minus * I_minus;
    const mp dpsi = (w3 - a) * t - half_plus * I_plus + half_minus * I_minus;
    const mp theta = atan2(sqrt(1 - u * u), u);
    const auto rot_z = [](double x) { return Quat(Eigen::AngleAxisd(x, Vec3::UnitZ())); };
    const Quat turn_phi = rot_z(reduced(dphi));
    FreeBodyState out;
    out.q_BtoS = (turn_phi * Quat(Eigen::AngleAxisd(static_cast<double>(theta - theta0), nodes0)) *
                  q0 * rot_z(reduced(dpsi)))
                     .normalized();
    // Rates at t: phi' = (b - a u)/(1 - u^2), psi' = w3 - u phi', theta' = -u'/sin.
    const mp phidot = (b - a * u) / (1 - u * u), psidot = w3 - u * phidot;
    const mp thetadot = -2 * du * sn * cn * dn * rate / sqrt(1 - u * u);
    // w = phi' z + theta' n + psi' e3 and w_B = R^T w, all at 50 digits: near a pole phi' and
    // psi' grow as 1/(1 -+ u) and cancel, and in double their sum's rounding (eps phi') was
    // 7e4 eps of m for a top that swings 1.6e-5 rad past hanging down.
    using M3 = std::array<std::array<mp, 3>, 3>;
    using V3 = std::array<mp, 3>;
    const auto mul = [](const M3& x, const M3& y) {
      M3 z{};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          for (int l = 0; l < 3; ++l) z[i][j] += x[i][l] * y[l][j];
      return z;
    };
    const auto about_z = [](const mp& x) {
      const mp c = cos(x), s = sin(x);
      return M3{V3{c, -s, 0}, V3{s, c, 0}, V3{0, 0, 1}};
    };
    const mp nn = sqrt(mp(nodes0.x()) * nodes0.x() + mp(nodes0.y()) * nodes0.y() +
                       mp(nodes0.z()) * nodes0.z());
    const V3 n0{nodes0.x() / nn, nodes0.y() / nn, nodes0.z() / nn};
    const mp ct = cos(theta - theta0), st = sin(theta - theta0);
    M3 about_n0{};  // Rodrigues: c I + s [n]x + (1 - c) n n^T
    const M3 cross{V3{0, -n0[2], n0[1]}, V3{n0[2], 0, -n0[0]}, V3{-n0[1], n0[0], 0}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        about_n0[i][j] = (i == j ? ct : mp(0)) + st * cross[i][j] + (1 - ct) * n0[i] * n0[j];
    const mp qw = q0.w(), qx = q0.x(), qy = q0.y(), qz = q0.z();
    const mp qn = qw * qw + qx * qx + qy * qy + qz * qz;
    const M3 start{V3{(qw * qw + qx * qx - qy * qy - qz * qz) / qn, 2 * (qx * qy - qw * qz) / qn,
                      2 * (qx * qz + qw * qy) / qn},
                   V3{2 * (qx * qy + qw * qz) / qn, (qw * qw - qx * qx + qy * qy - qz * qz) / qn,
                      2 * (qy * qz - qw * qx) / qn},
                   V3{2 * (qx * qz - qw * qy) / qn, 2 * (qy * qz + qw * qx) / qn,
                      (qw * qw - qx * qx - qy * qy + qz * qz) / qn}};
    const M3 turn = about_z(dphi);
    const M3 R = mul(mul(mul(turn, about_n0), start), about_z(dpsi));
    V3 w_S;
    for (int i = 0; i < 3; ++i) {
      const mp n_i = turn[i][0] * n0[0] + turn[i][1] * n0[1] + turn[i][2] * n0[2];
      w_S[i] = thetadot * n_i + psidot * R[i][2] + (i == 2 ? phidot : mp(0));
    }
    const auto body = [&](int j) { return R[0][j] * w_S[0] + R[1][j] * w_S[1] + R[2][j] * w_S[2]; };
    out.m_B = Vec3(static_cast<double>(I1 * body(0)), static_cast<double>(I1 * body(1)), m0.z());
    return out;
  }
};
using MpHeavyTop = MpHeavyTopAt<boost::multiprecision::cpp_bin_float_50>;

}  // namespace wobble::bench
