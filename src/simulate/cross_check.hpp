#pragma once
/// @file
/// `solve --cross-check`: the dynamic answers of a torque-free symmetric top (largest angle of
/// e3 from z, its first time, the two precession rates) recomputed by simulation, for
/// comparison with the key's closed forms.
///
/// The simulation is Fehlberg 7(8) at tolerance 1e-12 over 1.5 t_max (a general integrator,
/// not the closed form, so the comparison is independent), sampled 4001 times:
/// - max_angle, t_max: the largest sampled angle(z, e3), refined by the parabola through it
///   and its neighbours (error O(dt^3));
/// - Omega_body_rate: the turn of w about e3 in the body over the run, divided by the time;
/// - Omega_space_rate: the turn of e3 about L in space over the run, divided by the time.
/// A wobble smaller than kSmallestResolvedWobble (α = 0 among them: no wobble at all) is not
/// simulated: the angles measured would be the integrator's error, not the motion. The result
/// then has no rows and says why.
#include <string>
#include <vector>

#include "problem/problem.hpp"
#include "solvers/key.hpp"

namespace wobble {

struct CrossCheckRow {
  std::string name, unit;
  double key = 0.0, simulated = 0.0;
};

/// The smallest largest angle (rad) the cross-check compares. Why 1e-6: at tolerance 1e-12 the
/// attitude carries errors up to ~1e-10 rad over the run, so the angles and turns measured on a
/// wobble of 1e-6 rad keep four digits; below that the relative difference would be noise.
inline constexpr double kSmallestResolvedWobble = 1e-6;

/// The cross-check's run, as the header's first paragraph says: Fehlberg 7(8) at this tolerance,
/// this many samples, over this many t_max (the maximum and the half turn after it).
inline constexpr double kCrossCheckTolerance = 1e-12;
inline constexpr int kCrossCheckSamples = 4001;
inline constexpr double kCrossCheckSpan = 1.5;  ///< in units of t_max

struct CrossCheck {
  std::vector<CrossCheckRow> rows;
  std::string not_compared;  ///< why nothing was simulated (rows empty), or ""
  std::string method;  ///< what the simulation used
  std::int64_t rhs_evals = 0;
  double simulation_time_s = 0.0;
};

/// @throws InputError if the problem is not a torque-free symmetric top with a [motion] table.
CrossCheck cross_check_torque_free(const Problem& problem, const sym::Values& values,
                                   const Key& key);

}  // namespace wobble
