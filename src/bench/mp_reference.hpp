#pragma once
/// @file
/// A 50-digit reference for the exact torque-free solution (bench and hard-case tests).
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "core/inertia.hpp"

namespace wobble::bench {

// The exact solution's m(t) evaluated again at 50 digits, from the same formulas (for a body
// with ascending moments circling its third axis): sn, cn, dn and F by Boost.Math in
// multiprecision, where k = sqrt(1 - k'^2) keeps k'^2 = 1e-16.
/// Valid for ascending moments I1 < I2 < I3 and m circling e3 (m3^2 (I3-I2)/I3 > m1^2 (I2-I1)/I1).
struct MpMotion {
  using mp = boost::multiprecision::cpp_bin_float_50;
  mp a1, a2, a3, lambda, u0, k, s1, s2, s3;
  MpMotion(const Vec3& I, const Vec3& m0) {
    const mp J1 = I[0], J2 = I[1], J3 = I[2], m1 = m0[0], m2 = m0[1], m3 = m0[2];
    const mp d21 = J2 - J1, d31 = J3 - J1, d32 = J3 - J2;
    const mp B = m2 * m2 * d21 / J2 + m3 * m3 * d31 / J3;
    const mp D = m3 * m3 * d32 / J3 - m1 * m1 * d21 / J1;
    a1 = sqrt(m1 * m1 + m2 * m2 * J1 * d32 / (J2 * d31));
    a2 = sqrt(m1 * m1 * J2 * d31 / (J1 * d32) + m2 * m2);
    a3 = sqrt(m2 * m2 * J3 * d21 / (J2 * d31) + m3 * m3);
    lambda = sqrt(d32 * B / (J1 * J2 * J3));
    k = sqrt(1 - d31 * D / (d32 * B));
    s1 = m1 < 0 ? -1 : 1;
    s3 = m3 < 0 ? -1 : 1;
    s2 = s1 * s3;
    u0 = boost::math::ellint_1(k, atan2(s2 * m2 / a2, abs(m1) / a1));
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

}  // namespace wobble::bench
