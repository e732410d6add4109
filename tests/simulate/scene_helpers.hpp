#pragma once
// Small helpers of the scene tests: a run by method name, a column by name.
#include <stdexcept>
#include <string>

#include "simulate/simulation.hpp"

namespace wobble {

inline SimulationResult run(const SceneSetup& s, const std::string& method) {
  return simulate(s, choose_method(s, method));
}

inline std::size_t column(const SimulationResult& r, const std::string& name) {
  for (std::size_t j = 0; j < r.columns.size(); ++j) {
    if (r.columns[j] == name) return j;
  }
  throw std::logic_error("no column " + name);
}

}  // namespace wobble
