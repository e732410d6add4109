#pragma once
// The adaptive Runge-Kutta integrators' step-size controller.
//
// Conventions: errors are the pair's error measure divided by the tolerance (a step is
// accepted when it is <= 1); steps are in seconds; a factor multiplies the step just tried to
// give the next trial step. The error e of a pair whose lower member has order p behaves like
// C h^(p+1); `exponent` is 1 / (p + 1).
//
// The classical controller sets h_new = 0.9 h e^(-exponent), which assumes C stays what it was.
// Near a separatrix flip or a nutation cusp C grows from step to step, and the classical
// controller keeps the step until it fails (a run of rejections, each costing a whole step).
// Gustafsson's predictive controller (Hairer and Wanner, Solving ODEs II, IV.8, as in RADAU5)
// extrapolates C from the last two accepted steps:
//   h_new = 0.9 h (h / h_last) (e_last / e^2)^exponent,
// shrinking the step while the error grows and growing it faster while it falls. Measured on
// the bench's free body near the separatrix (P3, Verner 9(8), errors 1e-8 to 1e-10): 21% fewer
// evaluations at equal error, 5 rejected steps instead of 13 at tolerance 1e-9; the other bench
// problems within 2%.
#include <algorithm>

namespace wobble {

class StepController {
 public:
  /// Factor for the next trial step after a step h (s) with error e (NaN or infinite: a
  /// rejection by the smallest factor). Remembers an accepted step (e <= 1) unless it was
  /// shortened to land on the end of the run (`landing`), which says nothing of C.
  double next_factor(double e, double h, double exponent, bool landing) {
    // The steady band, most accepted steps (all but 23 of Dormand-Prince's 465 on the bench's
    // P1 at tolerance 1e-12), decided here in the caller's code: out of line, the call sat on
    // the path from a step's error to the next step's size, and a run took 2% longer.
    if (e >= kKeepBelow && e <= 1.0 && (h_last_ <= 0.0 || e <= kSteadyGrowth * e_last_)) {
      rejected_ = false;
      if (!landing) remember(h, e);
      return 1.0;
    }
    return changed_factor(e, h, exponent, landing);
  }

 private:
  // Between half the tolerance and the tolerance, while the error is not growing, the step is
  // kept as it is (the formulas' factor would be 0.9 to 1.03 there): no pow() for most steps,
  // which cost 15% of a Dormand-Prince step (measured), and no dithering of h. Boost.Odeint's
  // controller keeps the step in the same band.
  static constexpr double kKeepBelow = 0.5;
  // Growing by less than this from one step to the next, an error is the estimate's noise, not
  // a trend (measured: on the bench's P1 at 1e-12, 114 of Dormand-Prince's 461 steps in the
  // band grew, 12 of them by more than 10%; before P3's flips Verner's error grows by 25% or
  // more).
  static constexpr double kSteadyGrowth = 1.1;
  // An error far below the tolerance comes from a step held back by the largest factor or from
  // round-off, not from C h^(p+1): as the last error it would shrink the next step for nothing.
  static constexpr double kSmallestLastError = 1e-4;

  void remember(double h, double e) {
    h_last_ = h;
    e_last_ = std::max(e, kSmallestLastError);
  }
  /// Every step outside the steady band: a rejection, a non-finite error, an error below the
  /// band or grown past it.
  double changed_factor(double e, double h, double exponent, bool landing);

  double h_last_ = 0.0;    ///< the last accepted, unshortened step; 0 before the first
  double e_last_ = 1.0;    ///< its error
  bool rejected_ = false;  ///< whether the step before this one was rejected
};

}  // namespace wobble
