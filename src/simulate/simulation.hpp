#pragma once
/// @file
/// Running a scene: the sampled outputs, the errors of the conserved quantities, and the cost.
///
/// Samples are at t_k = k t_end / (samples - 1). Columns are "t" (s) then, per output, its
/// components: vectors as NAME_x/_y/_z (body-frame vectors along the body axes B of the file),
/// Euler angles as NAME_phi/_theta/_psi, scalars as NAME, invariant errors as err_QUANTITY.
/// Conserved quantities checked (largest deviation from t = 0 over the samples):
/// - torque-free (also in free flight): kinetic energy, |L|, L in space (largest component);
/// - gravity about a pivot: total energy, p_phi = L_z in space, and p_psi = L along the symmetry
///   axis when the body is symmetric about the axis through pivot and centre of mass;
/// - a constant torque in space (no gravity): L_space - (L_space(0) + tau t).
/// The samples of an integrator are also compared with a second, more accurate run, which says
/// how many digits they have (near a separatrix far fewer than the tolerance suggests).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "simulate/invariants.hpp"
#include "simulate/method.hpp"
#include "simulate/row_store.hpp"

namespace wobble {

struct InvariantError {
  std::string name, unit;
  double max_abs = 0.0;  ///< largest |value(t) - value(0)| over the samples
  double scale = 1.0;    ///< the size it is relative to (its value at 0, or the problem's scale)
  double relative() const { return max_abs / scale; }
};

struct SimulationResult {
  MethodChoice choice;
  std::vector<std::string> notes;  ///< facts of the motion (kind, period) for the header
  std::vector<std::string> columns, units;
  RowStore rows;  ///< one row per sample (in a temporary file past a few MiB)
  std::vector<InvariantError> invariants;
  std::string cost_label;  ///< "right-hand-side evaluations", "sub-flows" or "evaluations"
  std::int64_t cost = 0;
  std::int64_t steps = 0, rejected = 0;
  double run_time_s = 0.0;
  /// Integrators only: the largest difference from a more accurate run (the exact solution when
  /// torque-free, else rkf78 at tolerance/100), relative to each column's largest value; -1 if
  /// no more accurate run exists (rkf78, dop853 or vern9 at 1e-14 already).
  double error_estimate = -1.0;
  std::string error_reference;     ///< what it was compared with; "exact" for exact methods
  std::int64_t estimate_cost = 0;  ///< the evaluations of that second run
};

/// `progress` (if set) is called with the fraction done, at most ~100 times.
/// @throws std::runtime_error if an adaptive integrator's step underflows.
SimulationResult simulate(const SceneSetup& s, const MethodChoice& choice,
                          const std::function<void(double)>& progress = {});

/// Each state at `times` (ascending, from 0) by the given method, handed to `at_sample` as it
/// is computed (nothing kept). Adds the cost to `result`.
void propagate_each(const SceneSetup& s, const MethodChoice& choice,
                    const std::vector<double>& times, SimulationResult& result,
                    const std::function<void(std::size_t k, const SimState& state)>& at_sample,
                    const std::function<void(double)>& progress = {});

/// The state at each of `times` (ascending, from 0) by the given method, without outputs;
/// used by simulate and by `solve --cross-check`. Adds the cost to `result`.
std::vector<SimState> propagate(const SceneSetup& s, const MethodChoice& choice,
                                const std::vector<double>& times, SimulationResult& result,
                                const std::function<void(double)>& progress = {});

}  // namespace wobble
