#include "core/euler_angles.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace wobble {

EulerConvention euler_convention(const std::string& name) {
  if (name == "zyz") return EulerConvention::zyz;
  if (name == "zxz") return EulerConvention::zxz;
  throw std::invalid_argument("unknown Euler convention '" + name + "' (expected zyz or zxz)");
}

namespace {
double wrap(double a) {  // to (-pi, pi]
  a = std::remainder(a, 2 * M_PI);
  return a <= -M_PI ? a + 2 * M_PI : a;
}
}  // namespace

Mat3 rotation_from_euler(const Vec3& a, EulerConvention c) {
  const Vec3 axis = c == EulerConvention::zyz ? Vec3::UnitY() : Vec3::UnitX();
  return (Eigen::AngleAxisd(a[0], Vec3::UnitZ()) * Eigen::AngleAxisd(a[1], axis) *
          Eigen::AngleAxisd(a[2], Vec3::UnitZ()))
      .toRotationMatrix();
}

Vec3 euler_from_rotation(const Mat3& R, EulerConvention c) {
  // z-y-z: third column (cos(phi) sin(theta), sin(phi) sin(theta), cos(theta)); the upper 2x2
  // block gives the sum and the difference of phi and psi:
  //   R00 + R11 = (1 + cos theta) cos(phi + psi),  R10 - R01 = (1 + cos theta) sin(phi + psi),
  //   R00 - R11 = (cos theta - 1) cos(phi - psi),  R10 + R01 = (cos theta - 1) sin(phi - psi).
  const double s = std::hypot(R(0, 2), R(1, 2));  // sin(theta) >= 0, accurate near 0 and pi
  const double theta = std::atan2(s, R(2, 2));
  const bool upper =
      R(2, 2) >= 0;  // theta <= pi/2: the sum is well conditioned, else the difference
  const double sum = std::atan2(R(1, 0) - R(0, 1), R(0, 0) + R(1, 1));
  const double diff = std::atan2(-(R(1, 0) + R(0, 1)), -(R(0, 0) - R(1, 1)));
  // A tilt of a few eps is rounding noise (a quaternion's product, say): phi alone would be noise
  // too, so take it as gimbal lock; the rotation changes by at most that tilt.
  constexpr double kLocked = 8 * std::numeric_limits<double>::epsilon();
  if (s <= kLocked) {
    // Gimbal lock: only phi + psi (theta = 0) or phi - psi (theta = pi) is defined; psi = 0.
    // At theta = pi the z-x-z block is [[cos, sin], [sin, -cos]] of phi - psi, not z-y-z's.
    const double phi = upper                       ? sum
                       : c == EulerConvention::zyz ? diff
                                                   : std::atan2(R(1, 0), R(0, 0));
    return Vec3(wrap(phi), theta, 0.0);
  }
  // phi from the third column (noisy when sin(theta) is tiny, but then the tilt it orients is
  // tiny too), psi from the accurate sum or difference: the rotation is right in every regime.
  double phi = std::atan2(R(1, 2), R(0, 2));
  double psi = upper ? sum - phi : phi - diff;
  if (c == EulerConvention::zxz) {
    // Rx(theta) = Rz(-pi/2) Ry(theta) Rz(pi/2): z-x-z angles are the z-y-z ones with
    // phi + pi/2 and psi - pi/2.
    phi += M_PI / 2;
    psi -= M_PI / 2;
  }
  return Vec3(wrap(phi), theta, wrap(psi));
}

}  // namespace wobble
