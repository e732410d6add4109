#include "bench/timing.hpp"

#include <algorithm>
#include <chrono>
#include <vector>

namespace wobble::bench {

namespace {
double seconds_of(const std::function<void()>& f, long count) {
  const auto start = std::chrono::steady_clock::now();
  for (long i = 0; i < count; ++i) f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

double median_time_s(const std::function<void()>& f, const TimingPlan& plan) {
  // How many calls make one measurement: double until the sample is long enough.
  long count = 1;
  while (seconds_of(f, count) < plan.min_sample_s && count < (1L << 30)) count *= 2;
  std::vector<double> t;
  for (int r = 0; r < plan.repeats; ++r)
    t.push_back(seconds_of(f, count) / static_cast<double>(count));
  std::nth_element(t.begin(), t.begin() + static_cast<long>(t.size() / 2), t.end());
  return t[t.size() / 2];
}

}  // namespace wobble::bench
