#pragma once
/// @file
/// The methods `wobble simulate` can use, and the automatic choice among them.
///
/// auto picks, in order: the closed form (torque-free, axially symmetric), the exact elliptic
/// solution (torque-free), else the adaptive pair that costs least at the requested tolerance
/// for the effects present. Measured on the free-body test (core tests, numerics notes),
/// Fehlberg 7(8) needs fewer right-hand-side evaluations than Dormand-Prince 5(4) at every
/// tolerance from 1e-6 to 1e-14 (195 vs 231 at 1e-6, 676 vs 3304 at 1e-12); Dormand-Prince is
/// kept for tolerances looser than 1e-6, where its lower order costs less per step.
#include <string>
#include <vector>

#include "simulate/scene_setup.hpp"

namespace wobble {

enum class SimMethod { closed_form, exact, rk4, dopri5, rkf78, split2, split4 };

struct MethodChoice {
  SimMethod method = SimMethod::exact;
  std::string reason;
  double step_s = 0.0;  ///< fixed-step methods: the step used
};

std::string name_of(SimMethod m);
/// Every method name, in the order above, with a one-line description.
const std::vector<std::pair<std::string, std::string>>& simulation_method_names();

/// `requested` is "auto" or a method name, from `field` ("--method" or "run.method", for
/// messages). @throws InputError for an unknown name, or a
/// method that cannot apply to this scene (the exact solver or a splitting with a torque, the
/// closed form for an asymmetric body), saying why and what would.
MethodChoice choose_method(const SceneSetup& s, const std::string& requested,
                           const std::string& field = "--method");

}  // namespace wobble
