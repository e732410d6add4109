#include "core/validity.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>
#include <limits>

namespace wobble {

namespace {
std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}
}  // namespace

void check_inertia_tensor(const Mat3& I) {
  if (!I.allFinite()) throw InvalidInertiaTensor("inertia tensor has a non-finite entry");
  const double scale = I.cwiseAbs().maxCoeff();
  const double tol = 4.0 * std::numeric_limits<double>::epsilon() * scale;
  static const char* axis = "xyz";
  for (int i = 0; i < 3; ++i) {
    for (int j = i + 1; j < 3; ++j) {
      if (std::abs(I(i, j) - I(j, i)) > tol) {
        throw InvalidInertiaTensor(std::string("inertia tensor is not symmetric: I_") + axis[i] +
                                   axis[j] + " = " + num(I(i, j)) + " but I_" + axis[j] + axis[i] +
                                   " = " + num(I(j, i)));
      }
    }
  }
  Eigen::SelfAdjointEigenSolver<Mat3> solver(I, Eigen::EigenvaluesOnly);
  const Vec3 l = solver.eigenvalues();
  if (l[0] < -tol) {
    throw InvalidInertiaTensor("inertia tensor is not positive semi-definite: principal moment " +
                               num(l[0]) + " < 0");
  }
  if (l[0] + l[1] < l[2] - tol) {
    throw InvalidInertiaTensor(
        "principal moments violate the triangle inequality: I1 + I2 = " + num(l[0]) + " + " +
        num(l[1]) + " = " + num(l[0] + l[1]) + " < I3 = " + num(l[2]));
  }
}

}  // namespace wobble
