#include "solvers/registry.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/input_error.hpp"
#include "solvers/asymmetric_top_solver.hpp"
#include "solvers/euler_angles_solver.hpp"
#include "solvers/heavy_top_solver.hpp"
#include "solvers/inertia_solver.hpp"
#include "solvers/torque_free_solver.hpp"

namespace wobble {

const QuantityInfo* SolverInfo::quantity(const std::string& q) const {
  for (const auto& info : quantities) {
    if (info.name == q) return &info;
  }
  return nullptr;
}

const std::vector<SolverInfo>& solver_registry() {
  // One line per solver.
  static const std::vector<SolverInfo> solvers{
      inertia_solver(),
      torque_free_symmetric_solver(),
      asymmetric_top_solver(),
      heavy_top_solver(),
      euler_angles_solver(),
  };
  return solvers;
}

const SolverInfo& solver_info(const std::string& name) {
  std::vector<std::string> known;
  for (const auto& s : solver_registry()) {
    if (s.name == name) return s;
    known.push_back(s.name);
  }
  throw InputError(
      fmt::format("solver: unknown solver '{}' (known: {})", name, fmt::join(known, ", ")));
}

const SolverSchemas& solver_schemas() {
  static const SolverSchemas schemas = [] {
    SolverSchemas out;
    for (const auto& s : solver_registry()) {
      SolverSchema schema{s.name, s.motion_keys, {}};
      for (const auto& q : s.quantities) schema.quantities.push_back(q.name);
      out.push_back(schema);
    }
    return out;
  }();
  return schemas;
}

}  // namespace wobble
