#pragma once
/// @file
/// The solvers, as data. Per solver: its name, a one-line summary, the `[motion]` keys it
/// requires, and its quantities, each with its unit, kind, frame, sign convention and a one-line
/// description. Everything that needs to know the solvers reads this table: `solve`, `wobble
/// solvers`, the problem loader's checks (through solver_schemas), `solve --figure` and
/// `--cross-check`, and the README's solver section (a test compares it with
/// `wobble solvers --format markdown`).
///
/// Adding a solver: its own file with a quantity table (solvers/quantity_table.hpp) and one
/// line in registry.cpp; see README, "Adding a solver".
#include <string>
#include <vector>

#include "problem/problem.hpp"
#include "problem/solver_schema.hpp"
#include "solvers/key.hpp"
#include "solvers/sketch.hpp"
#include "symbolic/expression.hpp"

namespace wobble {

struct QuantityInfo {
  std::string name;
  std::string unit;  ///< SI, "" for dimensionless
  AnswerKind kind = AnswerKind::scalar;
  AnswerFrame frame = AnswerFrame::none;
  SignConvention sign = SignConvention::none;
  std::string description;  ///< one line, for `wobble solvers` and the README
};

struct SolverInfo {
  std::string name;
  std::string summary;                   ///< one line
  std::vector<std::string> motion_keys;  ///< all required; empty: no [motion] table
  std::vector<QuantityInfo> quantities;
  /// The key of a problem at parameter values (every parameter present, SI).
  Key (*solve)(const Problem&, const sym::Values&) = nullptr;
  /// The sketch beside the key (`solve --figure`), or nullptr: the solver draws none.
  TopSketch (*sketch)(const Problem&, const sym::Values&) = nullptr;
  /// Whether `solve --cross-check` recomputes its dynamic answers by simulation
  /// (simulate/cross_check.hpp).
  bool cross_checked_by_simulation = false;

  /// @return nullptr if the solver has no such quantity.
  const QuantityInfo* quantity(const std::string& name) const;
};

/// Every solver, in the order `wobble solvers` lists them.
const std::vector<SolverInfo>& solver_registry();

/// @throws InputError naming the solver and the known ones.
const SolverInfo& solver_info(const std::string& name);

/// What the problem loader checks a file against (problem/solver_schema.hpp).
const SolverSchemas& solver_schemas();

}  // namespace wobble
