// Core identities of inertia tensors, with tolerances derived from the scale of the problem.
#include <Eigen/Geometry>
#include <catch2/catch.hpp>
#include <limits>

#include "core/inertia.hpp"
#include "core/shapes.hpp"

using namespace wobble;
using Catch::Matchers::WithinAbs;

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();

// Fixed, irregular point set (no randomness): masses in kg, positions in m.
std::vector<PointMass> sample_masses() {
  return {{1.5, {0.3, -1.2, 0.7}},
          {0.25, {2.0, 0.4, -0.9}},
          {3.0, {-0.6, 0.8, 1.1}},
          {0.8, {0.1, 0.1, -2.3}}};
}

// Tensors from sums of products of O(1) numbers: entries carry errors of a few eps * trace.
double tol_for(const Mat3& I, int terms) {
  return 4.0 * terms * kEps * I.trace();
}

void require_close(const Mat3& a, const Mat3& b, double tol) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) REQUIRE_THAT(a(i, j), WithinAbs(b(i, j), tol));
  }
}
}  // namespace

TEST_CASE("a single point mass has the tensor m (r^2 1 - r r^T)") {
  const Mat3 I = inertia_of_point_masses({{2.0, {1.0, 2.0, 3.0}}});
  // By hand: r^2 = 14; I_xx = 2 (4 + 9) = 26, I_xy = -2*1*2 = -4, ...
  Mat3 expected;
  expected << 26, -4, -6, -4, 20, -12, -6, -12, 10;
  require_close(I, expected, 0.0);
}

TEST_CASE("composition is additive") {
  const auto all = sample_masses();
  const std::vector<PointMass> first(all.begin(), all.begin() + 2),
      second(all.begin() + 2, all.end());
  const MassProperties whole = mass_properties(all);
  const MassProperties combined = combine({mass_properties(first), mass_properties(second)});
  REQUIRE_THAT(combined.mass_kg, WithinAbs(whole.mass_kg, 4 * kEps * whole.mass_kg));
  require_close(combined.I_O, whole.I_O, tol_for(whole.I_O, 4));
  REQUIRE((combined.r_cm_m - whole.r_cm_m).norm() <= 8 * kEps * whole.r_cm_m.norm() + 8 * kEps);
}

TEST_CASE("parallel-axis shift to the centre of mass and back is the identity") {
  const MassProperties p = mass_properties(sample_masses());
  const Mat3 I_cm = shift_to_cm(p.I_O, p.mass_kg, p.r_cm_m);
  const Mat3 back = shift_from_cm(I_cm, p.mass_kg, p.r_cm_m);
  require_close(back, p.I_O, tol_for(p.I_O, 8));
  // The tensor about the centre of mass equals the tensor of the masses moved to it.
  std::vector<PointMass> centred = sample_masses();
  for (auto& m : centred) m.r_O_m -= p.r_cm_m;
  require_close(I_cm, inertia_of_point_masses(centred), tol_for(p.I_O, 8));
}

TEST_CASE("rotating the body rotates the tensor: I' = R I R^T") {
  const Mat3 R =
      (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()) * Eigen::AngleAxisd(-1.3, Vec3::UnitX()))
          .toRotationMatrix();
  std::vector<PointMass> rotated = sample_masses();
  for (auto& m : rotated) m.r_O_m = R * m.r_O_m;
  const Mat3 I = inertia_of_point_masses(sample_masses());
  // R carries a rounding of ~eps per entry; two products with R add ~6 eps * |I|.
  require_close(inertia_of_point_masses(rotated), R * I * R.transpose(), tol_for(I, 12));
}

TEST_CASE("bad point masses are rejected") {
  REQUIRE_THROWS_AS(inertia_of_point_masses({{-1.0, {1, 0, 0}}}), std::invalid_argument);
  REQUIRE_THROWS_AS(inertia_of_point_masses({{std::nan(""), {1, 0, 0}}}), std::invalid_argument);
  REQUIRE_THROWS_AS(inertia_of_point_masses({{1.0, {INFINITY, 0, 0}}}), std::invalid_argument);
  REQUIRE_THROWS_AS(mass_properties({{0.0, {1, 0, 0}}}), std::invalid_argument);
}

TEST_CASE("shape tensors agree with a fine cloud of point masses (midpoint rule)") {
  // A box of n^3 equal masses at cell centres. The midpoint rule integrates x*y exactly and
  // x^2 with a deficit of h^2/12 per axis, so I_xx(cloud) = I_xx - M (h_y^2 + h_z^2)/12 exactly
  // (up to rounding of the n^3-term sums).
  const double M = 2.5, a = 0.4, b = 1.1, c = 0.7;
  const int n = 30;
  std::vector<PointMass> cloud;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        cloud.push_back(
            {M / (n * n * n),
             {a * ((i + 0.5) / n - 0.5), b * ((j + 0.5) / n - 0.5), c * ((k + 0.5) / n - 0.5)}});
      }
    }
  }
  const Mat3 I_cloud = inertia_of_point_masses(cloud);
  const Mat3 I_box = shape_inertia_about_cm(ShapeKind::box, M, {a, b, c});
  const Vec3 h2 = Vec3(a * a, b * b, c * c) / (n * n);
  Mat3 deficit = Mat3::Zero();
  deficit.diagonal() << M * (h2.y() + h2.z()) / 12, M * (h2.x() + h2.z()) / 12,
      M * (h2.x() + h2.y()) / 12;
  require_close(I_cloud, I_box - deficit, 4.0 * n * n * n * kEps * I_box.trace());
}

TEST_CASE("shape sizes are validated") {
  REQUIRE_THROWS_AS(shape_inertia_about_cm(ShapeKind::box, 1.0, {1.0, 2.0}), std::invalid_argument);
  REQUIRE_THROWS_AS(shape_inertia_about_cm(ShapeKind::disc, 1.0, {-1.0}), std::invalid_argument);
  REQUIRE_THROWS_AS(shape_inertia_about_cm(ShapeKind::sphere, 0.0, {1.0}), std::invalid_argument);
  REQUIRE_THROWS_WITH(shape_kind_from_name("cube"), Catch::Contains("known: box"));
  // The names people use for a shape the table names otherwise, each with what to write.
  REQUIRE_THROWS_WITH(shape_kind_from_name("disk"), Catch::EndsWith("; write disc"));
  REQUIRE_THROWS_WITH(shape_kind_from_name("Box"), Catch::EndsWith("; write box"));
  REQUIRE_THROWS_WITH(shape_kind_from_name("hoop"), Catch::EndsWith("; write ring"));
  REQUIRE_THROWS_WITH(shape_kind_from_name("cube"),
                      Catch::EndsWith("; a cube is a box of three equal sizes"));
  REQUIRE_THROWS_WITH(shape_kind_from_name("blob"), Catch::EndsWith("cone, ring, shell)"));
}
