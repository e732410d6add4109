#include "core/torque_free_symmetric.hpp"

#include <cmath>
#include <stdexcept>

namespace wobble {

void SymmetricTop::validate() const {
  auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (!positive(I1_kgm2) || !positive(I3_kgm2)) {
    throw std::invalid_argument("symmetric top: moments must be finite and > 0");
  }
  if (I3_kgm2 > 2.0 * I1_kgm2 * (1.0 + 4e-16)) {
    throw std::invalid_argument("symmetric top: I3 > 2 I1 violates the triangle inequality");
  }
  if (!positive(omega_rad_s)) throw std::invalid_argument("symmetric top: omega must be > 0");
  if (!std::isfinite(alpha_rad) || alpha_rad < 0.0 || alpha_rad >= M_PI / 2) {
    throw std::invalid_argument("symmetric top: alpha must lie in [0, pi/2)");
  }
}

Vec3 SymmetricTop::omega0() const {
  return omega_rad_s * Vec3(std::sin(alpha_rad), 0.0, std::cos(alpha_rad));
}

Vec3 SymmetricTop::L0() const {
  const Vec3 w = omega0();
  return {I1_kgm2 * w.x(), I1_kgm2 * w.y(), I3_kgm2 * w.z()};
}

double SymmetricTop::omega3() const {
  return omega_rad_s * std::cos(alpha_rad);
}

double SymmetricTop::angle_L_e3() const {
  return std::atan2(I1_kgm2 * std::sin(alpha_rad), I3_kgm2 * std::cos(alpha_rad));
}

double SymmetricTop::angle_omega_L() const {
  // |w x L| = w^2 |I1 - I3| sin cos, w . L = w^2 (I1 sin^2 + I3 cos^2): no difference of angles.
  const double s = std::sin(alpha_rad), c = std::cos(alpha_rad);
  return std::atan2(std::abs(I1_kgm2 - I3_kgm2) * s * c, I1_kgm2 * s * s + I3_kgm2 * c * c);
}

double SymmetricTop::omega_body_rate() const {
  return (I3_kgm2 - I1_kgm2) / I1_kgm2 * omega3();
}

double SymmetricTop::omega_space_rate() const {
  return L0().norm() / I1_kgm2;
}

double SymmetricTop::max_angle() const {
  return 2.0 * angle_L_e3();
}

double SymmetricTop::t_max() const {
  return alpha_rad == 0.0 ? 0.0 : M_PI / omega_space_rate();
}

}  // namespace wobble
