#include <catch2/catch.hpp>

#include "core/validity.hpp"

using namespace wobble;

TEST_CASE("valid tensors pass, including planar and collinear limits") {
  REQUIRE_NOTHROW(check_inertia_tensor(Vec3(1.0, 2.0, 3.0).asDiagonal()));  // planar: 1 + 2 = 3
  REQUIRE_NOTHROW(check_inertia_tensor(Vec3(0.0, 2.0, 2.0).asDiagonal()));  // a line
  REQUIRE_NOTHROW(check_inertia_tensor(Mat3::Zero()));                      // a point
}

TEST_CASE("each violated condition is named") {
  REQUIRE_THROWS_WITH(check_inertia_tensor(Vec3(1.0, 1.0, 3.0).asDiagonal()),
                      Catch::Contains("triangle inequality") &&
                          Catch::Contains("I1 + I2 = 1 + 1 = 2") && Catch::Contains("< I3 = 3"));
  REQUIRE_THROWS_WITH(check_inertia_tensor(Vec3(-1.0, 2.0, 2.5).asDiagonal()),
                      Catch::Contains("not positive semi-definite") && Catch::Contains("-1"));
  Mat3 asym = Mat3::Identity();
  asym(0, 1) = 0.5;
  REQUIRE_THROWS_WITH(check_inertia_tensor(asym),
                      Catch::Contains("not symmetric") && Catch::Contains("I_xy = 0.5"));
  Mat3 nan = Mat3::Identity();
  nan(2, 2) = std::nan("");
  REQUIRE_THROWS_WITH(check_inertia_tensor(nan), Catch::Contains("non-finite"));
}

TEST_CASE("rounding of a valid tensor does not reject it") {
  // Planar body: lambda1 + lambda2 = lambda3 exactly in theory; rounding may break it by an ulp.
  REQUIRE_NOTHROW(check_inertia_tensor(Vec3(0.1, 0.2, 0.30000000000000004).asDiagonal()));
  REQUIRE_NOTHROW(check_inertia_tensor(Vec3(0.1, 0.2, 0.3).asDiagonal()));
}
