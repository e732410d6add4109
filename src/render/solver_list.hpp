#pragma once
/// @file
/// The solver registry as text (`wobble list --solvers`, and the README's table of quantities,
/// which is that output, checked by the README test): per solver its summary, its `[motion]`
/// keys, and one line per quantity with its kind, frame, unit and meaning.
#include <string>
#include <vector>

#include "solvers/registry.hpp"

namespace wobble {

std::string solver_list_text(const std::vector<SolverInfo>& solvers);

}  // namespace wobble
