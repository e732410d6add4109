#include "bench/timing.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
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
  return median_times_s({f}, plan).front();
}

std::vector<double> median_times_s(const std::vector<std::function<void()>>& fs,
                                   const TimingPlan& plan) {
  if (plan.repeats < 1) throw std::invalid_argument("timing: repeats must be >= 1");
  // How many calls make one measurement of each f: double until the sample is long enough.
  std::vector<long> counts;
  for (const auto& f : fs) {
    long count = 1;
    while (seconds_of(f, count) < plan.min_sample_s && count < (1L << 30)) count *= 2;
    counts.push_back(count);
  }
  std::vector<std::vector<double>> t(fs.size());
  for (int r = 0; r < plan.repeats; ++r) {
    for (std::size_t i = 0; i < fs.size(); ++i) {
      // One untimed call first, so that each measurement starts warm: side by side, every other
      // f ran since this one's last measurement and evicted its code and data from the caches
      // and its branches from the predictors, a cost that fell on some f more than on others
      // (wobble's Dormand-Prince on P1 at 1e-12: 77 us a run measured cold-started in fours,
      // 67 us warm; Odeint's 60.5 us either way).
      fs[i]();
      t[i].push_back(seconds_of(fs[i], counts[i]) / static_cast<double>(counts[i]));
    }
  }
  std::vector<double> medians;
  for (auto& ti : t) {
    std::nth_element(ti.begin(), ti.begin() + static_cast<long>(ti.size() / 2), ti.end());
    medians.push_back(ti[ti.size() / 2]);
  }
  return medians;
}

}  // namespace wobble::bench
