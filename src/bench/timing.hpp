#pragma once
/// @file
/// Timing for benchmarks: the median over repeats of a whole run, each repeat long enough for
/// the clock (a fast call is looped, and the time divided by the count) and started warm (one
/// untimed call before it).
#include <functional>
#include <vector>

namespace wobble::bench {

struct TimingPlan {
  int repeats = 15;            ///< medians over this many measurements
  double min_sample_s = 2e-4;  ///< each measurement lasts at least this long
};

/// Median wall time of one call of f, in seconds.
double median_time_s(const std::function<void()>& f, const TimingPlan& plan);

/// Median wall time of one call of each f, in seconds, measured side by side: each repeat times
/// every f in turn, so that a change of the machine's speed during the measurement (the
/// README's machine, a virtual one, changed by a third from one minute to the next) falls on all
/// of them alike, not on whichever happened to run then. The times compared in a ratio belong
/// in one call.
std::vector<double> median_times_s(const std::vector<std::function<void()>>& fs,
                                   const TimingPlan& plan);

}  // namespace wobble::bench
