#pragma once
/// @file
/// Physical validity of an inertia tensor (conventions of inertia.hpp).
///
/// A tensor is a possible inertia tensor if it is symmetric, positive semi-definite, and its
/// principal moments satisfy the triangle inequalities lambda_i + lambda_j >= lambda_k (equality:
/// a planar body for the largest; lambda1 = 0 with lambda2 = lambda3: collinear masses).
/// Every test uses the tolerance 4 * eps * scale, scale = the largest |entry| (Drake's choice for
/// rotational inertia), so rounding of a valid tensor never rejects it.
#include <stdexcept>
#include <string>

#include "core/inertia.hpp"

namespace wobble {

/// An impossible inertia tensor; what() says which condition fails, with the numbers.
struct InvalidInertiaTensor : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// @throws InvalidInertiaTensor naming the first failed condition: non-finite entry, asymmetry
///         (which pair), a negative principal moment, or the triangle inequality that fails.
void check_inertia_tensor(const Mat3& I);

}  // namespace wobble
