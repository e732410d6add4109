#pragma once
/// @file
/// The principal moments and axes of a tensor as answers: exact where a closed form exists
/// (symbolic/principal_sym.hpp), numeric otherwise, always checked against core's solver, in the
/// canonical order and signs of core/principal_axes.hpp.
#include <string>
#include <vector>

#include "core/inertia.hpp"
#include "solvers/exact_answer.hpp"

namespace wobble {

struct PrincipalAnswers {
  Answer moments;  ///< ascending
  Answer axes;     ///< columns e1, e2, e3
  std::vector<Step> moment_steps;
  std::vector<Step> axis_steps;
};

/// @param I_numeric_error bound on the entries' error of I_numeric (kg m^2): a tensor moved to
///        the centre of mass carries the rounding of the larger tensor it came from
/// @throws std::logic_error if the exact and numeric routes disagree beyond rounding (a bug)
PrincipalAnswers principal_answers(const GiNaC::matrix& I_exact, const Mat3& I_numeric,
                                   double I_numeric_error,
                                   const std::string& moments_name, const std::string& axes_name,
                                   const ExactContext& ctx);

}  // namespace wobble
