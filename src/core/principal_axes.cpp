#include "core/principal_axes.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace wobble {

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();

// Index of the coordinate axis least aligned with u (smallest |u_i|, first on ties).
int least_aligned_axis(const Vec3& u) {
  int best = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::abs(u[i]) < std::abs(u[best]) - kSignTieTolerance) best = i;
  }
  return best;
}

// A fixed unit vector perpendicular to the unit vector u.
Vec3 fixed_perpendicular(const Vec3& u) {
  const Vec3 axis = Vec3::Unit(least_aligned_axis(u));
  return (axis - axis.dot(u) * u).normalized();
}

Mat3 right_handed(const Vec3& e1, const Vec3& e2) {
  Mat3 axes;
  axes.col(0) = canonical_sign(e1);
  axes.col(1) = canonical_sign(e2);
  axes.col(2) = axes.col(0).cross(axes.col(1));
  return axes;
}
}  // namespace

Vec3 canonical_sign(const Vec3& v) {
  const double largest = v.cwiseAbs().maxCoeff();
  for (int i = 0; i < 3; ++i) {
    if (std::abs(v[i]) >= largest * (1.0 - kSignTieTolerance)) return v[i] < 0.0 ? Vec3(-v) : v;
  }
  return v;
}

Degeneracy degeneracy_of(const Vec3& m, double scale) {
  const double tolerance = kDegeneracyEps * kEps * scale;
  const bool eq12 = m[1] - m[0] <= tolerance;
  const bool eq23 = m[2] - m[1] <= tolerance;
  if (eq12 && eq23) return Degeneracy::all;
  if (eq12) return Degeneracy::pair12;
  return eq23 ? Degeneracy::pair23 : Degeneracy::none;
}

PrincipalAxes principal_axes(const Mat3& I) {
  if (!I.allFinite()) throw std::invalid_argument("principal_axes: tensor has a non-finite entry");
  const Mat3 sym = I.selfadjointView<Eigen::Lower>();
  Eigen::SelfAdjointEigenSolver<Mat3> solver;
  solver.compute(sym, Eigen::ComputeEigenvectors);
  if (solver.info() != Eigen::Success) {
    throw std::runtime_error("principal_axes: eigen solver did not converge");
  }
  PrincipalAxes out;
  out.moments = solver.eigenvalues();  // Eigen returns them ascending
  const Mat3 v = solver.eigenvectors();
  const double scale = std::max(std::abs(out.moments[2]), sym.cwiseAbs().maxCoeff());
  out.degeneracy_tolerance = kDegeneracyEps * kEps * scale;
  const Degeneracy d = degeneracy_of(out.moments, scale);
  const bool eq12 = d == Degeneracy::all || d == Degeneracy::pair12;
  const bool eq23 = d == Degeneracy::all || d == Degeneracy::pair23;

  if (eq12 && eq23) {
    out.degeneracy = Degeneracy::all;
    out.moments.setConstant(out.moments.mean());
    out.axes = Mat3::Identity();
  } else if (eq12) {
    out.degeneracy = Degeneracy::pair12;
    const double mean = 0.5 * (out.moments[0] + out.moments[1]);
    out.moments[0] = out.moments[1] = mean;
    const Vec3 unique = v.col(2).normalized();
    const Vec3 first = fixed_perpendicular(unique);
    out.axes = right_handed(first, unique.cross(first));
  } else if (eq23) {
    out.degeneracy = Degeneracy::pair23;
    const double mean = 0.5 * (out.moments[1] + out.moments[2]);
    out.moments[1] = out.moments[2] = mean;
    const Vec3 unique = v.col(0).normalized();
    out.axes = right_handed(unique, fixed_perpendicular(unique));
  } else {
    out.axes = right_handed(v.col(0), v.col(1));
  }
  return out;
}

}  // namespace wobble
