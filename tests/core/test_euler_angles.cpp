// Euler angles: round trips through rotation matrices for both conventions, including the
// gimbal-lock cases theta = 0 and pi (compared as orientations, not angles).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "core/euler_angles.hpp"

using namespace wobble;
using Catch::Matchers::WithinAbs;

TEST_CASE("Euler angles round-trip through rotation matrices, both conventions") {
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  for (const EulerConvention c : {EulerConvention::zyz, EulerConvention::zxz}) {
    for (const double theta : {0.0, 1e-9, 0.3, M_PI / 2, 2.9, M_PI - 1e-9, M_PI}) {
      for (const double phi : {-3.0, -0.4, 0.0, 1.2, 3.1}) {
        for (const double psi : {-2.5, 0.0, 0.7}) {
          const Mat3 R = rotation_from_euler(Vec3(phi, theta, psi), c);
          const Vec3 back = euler_from_rotation(R, c);
          INFO("phi " << phi << " theta " << theta << " psi " << psi << " -> " << back.transpose());
          // Orientations agree to a few eps (each angle is one atan2 of exact-ish entries);
          // near gimbal lock phi and psi separately are ill-defined, the rotation is not.
          REQUIRE((rotation_from_euler(back, c) - R).norm() <= 32 * kEps);
          REQUIRE(back[1] >= 0.0);
          REQUIRE(back[1] <= M_PI);
        }
      }
    }
  }
}

TEST_CASE("Euler conventions: z-y-z tilts toward x, z-x-z toward -y") {
  const Vec3 e3_zyz = rotation_from_euler(Vec3(0, 0.5, 0), EulerConvention::zyz).col(2);
  const Vec3 e3_zxz = rotation_from_euler(Vec3(0, 0.5, 0), EulerConvention::zxz).col(2);
  REQUIRE_THAT(e3_zyz.x(), WithinAbs(std::sin(0.5), 1e-15));
  REQUIRE_THAT(e3_zxz.y(), WithinAbs(-std::sin(0.5), 1e-15));
  REQUIRE_THROWS_AS(euler_convention("xyz"), std::invalid_argument);
}
