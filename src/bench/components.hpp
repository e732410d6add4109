#pragma once
/// @file
/// Component benchmarks: the elliptic functions and the exact w(t) against Boost.Math's default
/// jacobi_elliptic, principal axes against Eigen's compute() and computeDirect(), and the
/// whole-process time of the command line.
#include <string>
#include <vector>

#include "bench/timing.hpp"

namespace wobble::bench {

struct ComponentRow {
  std::string group;       ///< "elliptic", "principal axes", "process"
  std::string method;      ///< what was timed
  std::string cases;       ///< on what
  double max_error = 0.0;  ///< the measure is said in `error_kind`; < 0: not measured
  std::string error_kind;
  double ns_per_call = 0.0;
};

/// sn, cn, dn at k'^2 = 0.5 ... 1e-16 and u across [0, K] (with points next to K), against
/// Boost.Math at 50 digits: wobble's jacobi_sncndn, Boost's default policy, and the exact
/// solution's w(t).
std::vector<ComponentRow> elliptic_bench(const TimingPlan& plan);

/// Separated, exactly degenerate, nearly degenerate and badly scaled tensors R diag(l) R^T.
std::vector<ComponentRow> principal_axes_bench(const TimingPlan& plan);

/// `wobble solve ID` for each problem and `wobble keys --check`, whole process, median of
/// `repeats` runs of the executable `exe`.
std::vector<ComponentRow> process_bench(const std::string& exe, int repeats);

/// The machine: CPU model and count (from /proc/cpuinfo), for the results' header.
std::string machine_description();

}  // namespace wobble::bench
