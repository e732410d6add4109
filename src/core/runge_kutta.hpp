#pragma once
/// @file
/// Runge-Kutta integrators for the rigid body (core/rigid_body.hpp): fixed-step RK4, and the
/// embedded pairs Dormand-Prince 5(4), Fehlberg 7(8), Dormand-Prince 8(5,3) (DOP853) and
/// Verner's 9(8) with step-size control. Tableaux: core/runge_kutta_tableaux.hpp.
///
/// Error control is on the whole state (momentum and attitude): a step is accepted when
/// max_i |err_i| / (tol * scale_i) <= 1, where scale is the size of the momentum for its three
/// components and 1 for the four quaternion components, so `tol` is a relative error per step.
/// The pairs propagate the higher-order solution (local extrapolation), like Boost.Odeint.
/// The quaternion is renormalised when |q|^2 strays 1e-6 from 1 and at the end of each call:
/// |q| never enters the motion (the torques use q / |q|, dq/dt is linear in q), and states
/// handed out (advance's y, sample's) are unit.
/// advance() shortens the last step to land exactly on the requested time. sample() does so
/// only at the last output time: Dormand-Prince 5(4) and DOP853 give the times between from
/// each step's dense output (continuous extensions of order 4 and 7), so many output times
/// cost little more than few; Fehlberg 7(8), Verner 9(8) and fixed steps land on every one.
#include <cstdint>
#include <functional>
#include <span>
#include <string>

#include "core/rigid_body.hpp"
#include "core/step_controller.hpp"

namespace wobble {

enum class RkMethod { rk4, dopri5, rkf78, dop853, vern9 };

struct IntegrationCost {
  std::int64_t rhs_evals = 0;
  std::int64_t steps = 0;     ///< accepted
  std::int64_t rejected = 0;  ///< adaptive methods only
};

/// Advances a state through successive output times, keeping its step size between calls.
class RungeKutta {
 public:
  /// Adaptive (dopri5, rkf78, dop853, vern9): `tol_or_step` is the relative tolerance. Fixed
  /// step (rk4, or any method with fixed_step = true, used to measure orders): it is the
  /// largest step (s).
  /// `momentum_scale` (kg m^2/s, > 0) is the size the momentum error is measured against.
  /// @throws std::invalid_argument for a non-positive or non-finite step, tolerance or scale.
  RungeKutta(const RigidBodyModel& model, RkMethod method, double tol_or_step,
             double momentum_scale, bool fixed_step = false);

  /// y(t0) -> y(t1), t1 > t0. @throws std::runtime_error if the step size underflows.
  void advance(State7& y, double t0, double t1);

  /// y(t0) -> y(times.back()), calling at(k, y(times[k])) for each output time in turn (times
  /// in increasing order; those <= t0 get y(t0)). The states given are unit-quaternion states.
  /// @throws std::invalid_argument if the times are not in increasing order.
  using SampleSink = std::function<void(std::size_t k, const State7& y)>;
  void sample(State7& y, double t0, std::span<const double> times, const SampleSink& at);

  const IntegrationCost& cost() const { return cost_; }
  RkMethod method() const { return method_; }

  /// Right-hand-side evaluations allowed from now on (unlimited by default): past them advance()
  /// throws WorkLimitReached. Each step also polls for an interrupt (core/work_budget.hpp).
  void set_evaluation_limit(std::int64_t evaluations) { limit_ = cost_.rhs_evals + evaluations; }

 private:
  RigidBodyRhs rhs_;  ///< the model's right-hand side, prepared
  RkMethod method_;
  double tol_or_step_;
  bool fixed_;
  // `output(t_old, t_new, y_old, y_new, stages)` sees each accepted step before y_new is
  // renormalised.
  template <class Tableau, class Output>
  void advance_adaptive(State7& y, double t0, double t1, const Output& output);
  template <class Tableau>
  void sample_dense(State7& y, double t0, std::span<const double> times, std::size_t next,
                    const SampleSink& at);

  State7 inverse_scale_;
  double h_ = 0.0;  ///< next trial step (adaptive), 0 until the first call
  StepController controller_;
  IntegrationCost cost_;
  std::int64_t limit_ = INT64_MAX;
  // First same as last (Dormand-Prince): f at the end of the last accepted step.
  bool fsal_valid_ = false;
  State7 fsal_y_, fsal_k_;
};

/// The theoretical order of the propagated solution.
int order_of(RkMethod m);
std::string name_of(RkMethod m);

}  // namespace wobble
