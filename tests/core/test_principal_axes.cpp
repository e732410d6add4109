// Principal axes: eigen residual, orthonormality, handedness, canonical signs, degeneracy.
#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <limits>

#include "core/principal_axes.hpp"

using namespace wobble;
using Catch::Matchers::WithinAbs;

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();

Mat3 rotation() {
  return (Eigen::AngleAxisd(0.9, Vec3(0.3, -1.0, 0.5).normalized()) *
          Eigen::AngleAxisd(2.1, Vec3::UnitZ()))
      .toRotationMatrix();
}

Mat3 rotated_diag(double l1, double l2, double l3) {
  const Mat3 R = rotation();
  return R * Vec3(l1, l2, l3).asDiagonal() * R.transpose();
}

// The properties every result must have, whatever the tensor.
void require_canonical(const Mat3& I, const PrincipalAxes& p) {
  const double n = 3.0;
  const double scale = I.norm();
  // Eigen residual bound 8 n eps |I| (Eigen's own test criterion for SelfAdjointEigenSolver),
  // applied to non-degenerate tensors; a snapped degenerate pair moves by at most its tolerance.
  const double residual_tol = 8 * n * kEps * scale + 2 * p.degeneracy_tolerance;
  for (int k = 0; k < 3; ++k) {
    const Vec3 r = I * p.axes.col(k) - p.moments[k] * p.axes.col(k);
    REQUIRE(r.norm() <= residual_tol);
  }
  REQUIRE(p.moments[0] <= p.moments[1]);
  REQUIRE(p.moments[1] <= p.moments[2]);
  REQUIRE(((p.axes.transpose() * p.axes) - Mat3::Identity()).norm() <= 8 * n * kEps);
  REQUIRE_THAT(p.axes.determinant(), WithinAbs(1.0, 8 * n * kEps));
  for (int k = 0; k < 2; ++k) {
    const Vec3 e = p.axes.col(k);
    Eigen::Index i = 0;
    e.cwiseAbs().maxCoeff(&i);
    REQUIRE(e[i] > 0.0);
  }
}
}  // namespace

TEST_CASE("separated moments: canonical axes of a rotated diagonal tensor") {
  const Mat3 I = rotated_diag(1.0, 2.0, 3.5);
  const PrincipalAxes p = principal_axes(I);
  require_canonical(I, p);
  REQUIRE(p.degeneracy == Degeneracy::none);
  for (int k = 0; k < 3; ++k) {
    REQUIRE_THAT(p.moments[k],
                 WithinAbs(std::vector<double>{1.0, 2.0, 3.5}[k], 8 * 3 * kEps * 3.5));
    // Each axis is the rotated coordinate axis, up to sign.
    REQUIRE_THAT(std::abs(p.axes.col(k).dot(rotation().col(k))), WithinAbs(1.0, 64 * kEps));
  }
}

TEST_CASE("a diagonal tensor gives the coordinate axes") {
  Mat3 I = Vec3(3.0, 1.0, 2.0).asDiagonal();
  const PrincipalAxes p = principal_axes(I);
  require_canonical(I, p);
  REQUIRE(p.moments == Vec3(1.0, 2.0, 3.0));
  REQUIRE(p.axes.col(0) == Vec3::UnitY());
  REQUIRE(p.axes.col(1) == Vec3::UnitZ());
  REQUIRE(p.axes.col(2) == Vec3::UnitX());
}

TEST_CASE("exactly degenerate pair: snapped, flagged, fixed basis, independent of rotation") {
  for (const auto& [l, which] : {std::pair{Vec3(1.0, 1.0, 3.0), Degeneracy::pair12},
                                 std::pair{Vec3(1.0, 3.0, 3.0), Degeneracy::pair23}}) {
    const Mat3 I = rotated_diag(l[0], l[1], l[2]);
    const PrincipalAxes p = principal_axes(I);
    require_canonical(I, p);
    REQUIRE(p.degeneracy == which);
    if (which == Degeneracy::pair12) REQUIRE(p.moments[0] == p.moments[1]);
    if (which == Degeneracy::pair23) REQUIRE(p.moments[1] == p.moments[2]);
    // The unique axis is the rotated one; the pair spans the plane perpendicular to it.
    const int unique = which == Degeneracy::pair12 ? 2 : 0;
    REQUIRE_THAT(std::abs(p.axes.col(unique).dot(rotation().col(unique))),
                 WithinAbs(1.0, 64 * kEps));
  }
}

TEST_CASE("degenerate pair basis is the documented one") {
  // Moments (1, 2, 2): the unique axis e1 = z. Of x, y (tied, both perpendicular to z) x is
  // first, so e2 = x, and e3 = e1 x e2 = z x x = y.
  Mat3 I = Vec3(2.0, 2.0, 1.0).asDiagonal();
  const PrincipalAxes p = principal_axes(I);
  REQUIRE(p.degeneracy == Degeneracy::pair23);
  REQUIRE(p.moments == Vec3(1.0, 2.0, 2.0));
  REQUIRE_THAT(p.axes.col(0).z(), WithinAbs(1.0, 4 * kEps));
  REQUIRE_THAT(p.axes.col(1).x(), WithinAbs(1.0, 4 * kEps));
  REQUIRE_THAT(p.axes.col(2).y(), WithinAbs(1.0, 4 * kEps));
}

TEST_CASE("all three equal: identity axes") {
  const Mat3 I = 2.5 * Mat3::Identity();
  const PrincipalAxes p = principal_axes(I);
  REQUIRE(p.degeneracy == Degeneracy::all);
  REQUIRE(p.axes == Mat3::Identity());
  const Mat3 nearly = rotated_diag(2.5, 2.5 * (1 + kEps), 2.5 * (1 - kEps));
  REQUIRE(principal_axes(nearly).degeneracy == Degeneracy::all);
}

TEST_CASE("nearly degenerate beyond the tolerance: not snapped, still orthonormal") {
  for (double split : {1e-6, 1e-10, 1e-13}) {
    const Mat3 I = rotated_diag(1.0, 1.0 + split, 3.0);
    const PrincipalAxes p = principal_axes(I);
    require_canonical(I, p);
    REQUIRE(p.degeneracy == Degeneracy::none);
    REQUIRE_THAT(p.moments[1] - p.moments[0], WithinAbs(split, 8 * 3 * kEps * 3.0));
  }
}

TEST_CASE("badly scaled tensors keep their small moments to relative accuracy of the largest") {
  for (double small : {1e-12, 1e-8}) {
    const Mat3 I = rotated_diag(small, 1.0, 1.0 + small);  // a needle
    const PrincipalAxes p = principal_axes(I);
    require_canonical(I, p);
    REQUIRE_THAT(p.moments[0], WithinAbs(small, 8 * 3 * kEps * 1.0));
  }
}

TEST_CASE("collinear masses: the smallest moment is zero and the tensor is accepted") {
  // Two masses on the line through (1, 1, 0): I = m r^2 (1 - u u^T) summed.
  const Vec3 u = Vec3(1, 1, 0).normalized();
  const Mat3 I = 3.0 * (Mat3::Identity() - u * u.transpose());
  const PrincipalAxes p = principal_axes(I);
  require_canonical(I, p);
  REQUIRE(p.moments[0] <= p.degeneracy_tolerance);
  REQUIRE(p.degeneracy == Degeneracy::pair23);
  REQUIRE_THAT(std::abs(p.axes.col(0).dot(u)), WithinAbs(1.0, 64 * kEps));
}

TEST_CASE("ties in the sign rule are decided by the first component") {
  REQUIRE(canonical_sign(Vec3(0.0, -1.0, 1.0)) == Vec3(0.0, 1.0, -1.0));
  REQUIRE(canonical_sign(Vec3(0.0, 1.0, -1.0)) == Vec3(0.0, 1.0, -1.0));
  REQUIRE(canonical_sign(Vec3(-0.2, 0.1, -0.9)) == Vec3(0.2, -0.1, 0.9));
}

TEST_CASE("non-finite tensors are rejected") {
  Mat3 I = Mat3::Identity();
  I(1, 2) = I(2, 1) = std::nan("");
  REQUIRE_THROWS_AS(principal_axes(I), std::invalid_argument);
}
