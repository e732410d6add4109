#pragma once
/// @file
/// Timing for benchmarks: the median over repeats of a whole run, each repeat long enough for
/// the clock (a fast call is looped, and the time divided by the count).
#include <functional>

namespace wobble::bench {

struct TimingPlan {
  int repeats = 15;            ///< medians over this many measurements
  double min_sample_s = 2e-4;  ///< each measurement lasts at least this long
};

/// Median wall time of one call of f, in seconds.
double median_time_s(const std::function<void()>& f, const TimingPlan& plan);

}  // namespace wobble::bench
