#pragma once
/// @file
/// Principal moments and axes of an exact tensor computed in 60-digit arithmetic, then rounded
/// once to double: every printed digit right even where two moments nearly coincide.
///
/// Why: in double precision an eigenvector is only as good as eps |I| over the gap to the
/// nearest moment (unit masses on the x and y axes plus 1e-9 kg elsewhere: the gap is 1e-9 of
/// |I| and the axis was wrong in the 10th digit; at 1e-12 in the 5th). The tensor is exact, so
/// it is evaluated to 60 digits and diagonalised by cyclic Jacobi rotations, which converge for
/// any gap; a gap above 1e-40 |I| leaves the axes right to double precision.
#include <ginac/ginac.h>

#include <array>

#include "core/inertia.hpp"

namespace wobble::sym {

struct RefinedPrincipal {
  Vec3 moments = Vec3::Zero();  ///< ascending, each rounded once from 60 digits
  Mat3 axes = Mat3::Identity();  ///< unit columns, in the order of the moments; signs arbitrary
};

/// @param I the exact tensor; `at` the parameter values (exact numbers).
/// @throws std::invalid_argument if an entry does not evaluate to a real number.
RefinedPrincipal refined_principal(const GiNaC::matrix& I, const GiNaC::lst& at);

}  // namespace wobble::sym
