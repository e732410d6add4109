#pragma once
/// @file
/// The methods `wobble simulate` can use, and the automatic choice among them.
///
/// auto picks, in order: the closed form (torque-free, axially symmetric), the exact elliptic
/// solution (torque-free, or a heavy symmetric top: gravity alone on a top pivoted on its
/// axle, core/exact_heavy_top.hpp), else the adaptive pair that costs least for the effects
/// present: Verner 9(8). Measured by `wobble bench` on the heavy top (P4), at equal error it
/// takes 0.66-0.85x Fehlberg 7(8)'s time for errors from 1e-8 to 1e-12, and is level with it
/// and DOP853 at 1e-5 and 1e-6 (Dormand-Prince 5(4) 2.4-7x); on the braked wheel (the
/// wheel-brake scene, errors against Fehlberg at tolerance/100) 0.81-0.95x Fehlberg's
/// evaluations.
#include <optional>
#include <string>
#include <vector>

#include "core/heavy_top.hpp"
#include "core/runge_kutta.hpp"
#include "simulate/scene_setup.hpp"

namespace wobble {

enum class SimMethod { closed_form, exact, rk4, dopri5, rkf78, dop853, vern9, split2, split4 };

struct MethodChoice {
  SimMethod method = SimMethod::exact;
  std::string reason;
  double step_s = 0.0;  ///< fixed-step methods: the step used
};

std::string name_of(SimMethod m);
/// The Runge-Kutta method behind m (rk4, dopri5, rkf78, dop853, vern9); none for the closed
/// form, the exact solution and the splittings.
std::optional<RkMethod> runge_kutta_of(SimMethod m);

/// The scene as the heavy symmetric top the exact solution serves, when it is one: gravity and
/// no torque, I1 == I2 (within the degeneracy rule of core/principal_axes.hpp; their mean is
/// used), the centre of mass on +e3 (off it by no more than that rule's share of |d|; scene
/// setup turns a top's e3 toward it, simulate/scene_setup.hpp), and not
/// started with the axle vertical and moving (theta is no coordinate there) nor tilted by less
/// than 1.5e-154 rad but not 0 (the square of that tilt underflows).
std::optional<HeavyTop> exact_heavy_top(const SceneSetup& s);
/// The relative rounding error the exact heavy top would carry over the run (its Euler
/// angles' phases: core/exact_heavy_top.hpp, euler_rate_bound); auto takes it only when this
/// is within the scene's tolerance (infinite when the scene is no such top).
double exact_heavy_top_rounding(const SceneSetup& s);
/// Every method name, in the order above, with a one-line description.
const std::vector<std::pair<std::string, std::string>>& simulation_method_names();

/// `requested` is "auto" or a method name, from `field` ("--method" or "run.method", for
/// messages). @throws InputError for an unknown name, or a
/// method that cannot apply to this scene (the exact solver or a splitting with a torque, the
/// closed form for an asymmetric body), saying why and what would.
MethodChoice choose_method(const SceneSetup& s, const std::string& requested,
                           const std::string& field = "--method");

/// The work a run takes, estimated before it starts: right-hand-side evaluations (or sub-flows,
/// or evaluations of the solution) of both runs, the samples' and the error estimate's. For the
/// adaptive pairs, steps ~ 0.1 (rate t_end) tol^(-1/p), fitted to the heavy top from 1e-4 to
/// 1e-12 (it slightly underestimates: the estimate refuses only what would surely run long).
struct WorkEstimate {
  double evaluations = 0;
  std::string basis;  ///< how it was reckoned, for the message
};
WorkEstimate estimate_work(const SceneSetup& s, const MethodChoice& choice);

/// @throws InputError when the estimate exceeds `limit`, naming the estimate, its basis and
///         `option`, which raises the limit.
void require_within_budget(const WorkEstimate& w, double limit, const std::string& option);

/// The tolerance of the tighter run that estimates a simulation's error: a hundred times
/// tighter (two more digits, enough to measure the first two of the error), never tighter than
/// any scene may ask (kMinSceneTolerance: the steps' own rounding is larger below it).
double reference_tolerance(const SceneSetup& s);

}  // namespace wobble
