#include "core/euler_angles.hpp"

#include <cmath>
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
  // z-y-z: third column (cos(phi) sin(theta), sin(phi) sin(theta), cos(theta)), third row
  // (-sin(theta) cos(psi), sin(theta) sin(psi), cos(theta)).
  const double s = std::hypot(R(0, 2), R(1, 2));  // sin(theta) >= 0, accurate near 0 and pi
  const double theta = std::atan2(s, R(2, 2));
  // Below this sin(theta), phi and psi are separately meaningless (only their sum or
  // difference is): a rounding-level sin(theta) would give them noise.
  constexpr double kLocked = 1e-12;
  double phi, psi = 0.0;
  if (s <= kLocked) {
    // theta = 0: R = Rz(phi + psi). theta = pi: the upper 2x2 block is Rz(phi - psi) with its
    // first column negated (z-y-z) or its second column negated (z-x-z). psi = 0 either way.
    const bool up = R(2, 2) > 0;
    phi = (up || c == EulerConvention::zxz) ? std::atan2(R(1, 0), R(0, 0))
                                            : std::atan2(-R(1, 0), -R(0, 0));
    return Vec3(wrap(phi), theta, 0.0);
  }
  phi = std::atan2(R(1, 2), R(0, 2));
  psi = std::atan2(R(2, 1), -R(2, 0));
  if (c == EulerConvention::zxz) {
    // Rx(theta) = Rz(-pi/2) Ry(theta) Rz(pi/2), so z-x-z angles are the z-y-z ones with
    // phi + pi/2 and psi - pi/2.
    phi += M_PI / 2;
    psi -= M_PI / 2;
  }
  return Vec3(wrap(phi), theta, wrap(psi));
}

}  // namespace wobble
