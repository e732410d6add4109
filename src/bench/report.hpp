#pragma once
/// @file
/// Everything one `wobble bench` run measured, and the performance targets checked against it
/// (benchmarks report; they never fail a build: CI machines are noisy).
#include <string>
#include <vector>

#include "bench/components.hpp"
#include "bench/work_precision.hpp"

namespace wobble::bench {

/// P2's long run: Strang splitting at h = 0.01 for 1e6 steps (T = 1e4).
struct LongRun {
  double L_error_end = 0.0;       ///< | |m(T)| - |m0| | / |m0|
  double energy_error_10 = 0.0;   ///< largest relative energy error over [0, 10]
  double energy_error_1e4 = 0.0;  ///< over [0, 1e4]
  std::int64_t steps = 0;
};
LongRun long_splitting_run(bool quick);

struct Target {
  std::string what;
  double measured = 0.0, limit = 0.0;  ///< met when measured <= limit (measured < 0: not measured)
  std::string unit;
  bool met() const { return measured >= 0.0 && measured <= limit; }
};

struct Report {
  std::string machine;
  bool quick = false;
  std::vector<BenchProblem> problems;
  std::vector<Run> runs;
  std::vector<ComponentRow> components;
  std::vector<DriftRow> drift;  ///< P2: errors against time
  std::vector<DenseRow> dense;  ///< P2: the cost of many output times
  std::vector<ExactDriftPoint> exact_drift;  ///< P2, P4: the exact solutions' error against t
  LongRun long_run;
  std::vector<Target> targets;
};

/// Fills report.targets from its measurements.
void evaluate_targets(Report& report);

}  // namespace wobble::bench
