#pragma once
/// @file
/// The output columns a scene asks for, and their values at one state (see simulation.hpp for
/// the column names).
#include <string>
#include <vector>

#include "simulate/invariants.hpp"

namespace wobble {

struct Columns {
  std::vector<std::string> names, units;
};

/// "t" then each output's components, in the scene's order.
Columns output_columns(const SceneSetup& s, const std::vector<ConservedQuantity>& conserved);

/// One row at time t: t then each output; `errors` are the conserved quantities' deviations
/// at this state (for the invariant_errors output).
std::vector<double> output_row(const SceneSetup& s, const SimState& st, double t,
                               const std::vector<double>& errors);

}  // namespace wobble
