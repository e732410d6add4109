#include "core/step_controller.hpp"

#include <algorithm>
#include <cmath>

namespace wobble {

namespace {
constexpr double kSafety = 0.9;
constexpr double kMinFactor = 0.2, kMaxFactor = 5.0;
}  // namespace

double StepController::changed_factor(double e, double h, double exponent, bool landing) {
  if (!std::isfinite(e)) {
    rejected_ = true;
    return kMinFactor;
  }
  const bool accepted = e <= 1.0;
  const bool predictive = accepted && h_last_ > 0.0;
  double factor = predictive ? kSafety * (h / h_last_) * std::pow(e_last_ / (e * e), exponent)
                             : kSafety * std::pow(std::max(e, 1e-300), -exponent);
  factor = std::clamp(factor, kMinFactor, kMaxFactor);
  if (!accepted) {
    rejected_ = true;
    return factor;
  }
  // After a rejection the accepted step is not grown (Hairer's rule): the model just failed.
  if (rejected_) factor = std::min(factor, 1.0);
  rejected_ = false;
  if (!landing) remember(h, e);
  return factor;
}

}  // namespace wobble
