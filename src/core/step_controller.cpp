#include "core/step_controller.hpp"

#include <algorithm>
#include <cmath>

namespace wobble {

namespace {
constexpr double kSafety = 0.9;
constexpr double kMinFactor = 0.2, kMaxFactor = 5.0;
// Between half the tolerance and the tolerance, while the error is not growing, the step is
// kept as it is (the formulas' factor would be 0.9 to 1.03 there): no pow() for most steps,
// which cost 15% of a Dormand-Prince step (measured), and no dithering of h. Boost.Odeint's
// controller keeps the step in the same band.
constexpr double kKeepBelow = 0.5;
// Growing by less than this from one step to the next, an error is the estimate's noise, not a
// trend (measured: on the bench's P1 at 1e-12, 114 of Dormand-Prince's 461 steps in the band
// grew, 12 of them by more than 10%; before P3's flips Verner's error grows by 25% or more).
constexpr double kSteadyGrowth = 1.1;
// An error far below the tolerance comes from a step held back by kMaxFactor or from
// round-off, not from C h^(p+1): as the last error it would shrink the next step for nothing.
constexpr double kSmallestLastError = 1e-4;
}  // namespace

double StepController::next_factor(double e, double h, double exponent, bool landing) {
  if (!std::isfinite(e)) {
    rejected_ = true;
    return kMinFactor;
  }
  const bool accepted = e <= 1.0;
  const bool predictive = accepted && h_last_ > 0.0;
  const bool steady =
      accepted && e >= kKeepBelow && (!predictive || e <= kSteadyGrowth * e_last_);
  double factor = 1.0;  // the steady band keeps the step
  if (!steady) {
    factor = predictive ? kSafety * (h / h_last_) * std::pow(e_last_ / (e * e), exponent)
                        : kSafety * std::pow(std::max(e, 1e-300), -exponent);
    factor = std::clamp(factor, kMinFactor, kMaxFactor);
  }
  if (!accepted) {
    rejected_ = true;
    return factor;
  }
  // After a rejection the accepted step is not grown (Hairer's rule): the model just failed.
  if (rejected_) factor = std::min(factor, 1.0);
  rejected_ = false;
  if (!landing) {
    h_last_ = h;
    e_last_ = std::max(e, kSmallestLastError);
  }
  return factor;
}

}  // namespace wobble
