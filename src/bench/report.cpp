#include "bench/report.hpp"

#include <algorithm>
#include <cmath>

#include "core/free_body.hpp"

namespace wobble::bench {

LongRun long_splitting_run(bool quick) {
  const BenchProblem p = bench_problems().at(1);  // P2
  const FreeBody body{p.model.I_P};
  FreeBodyState s{p.m0, p.q0};
  const double h = 0.01, E0 = body.energy(p.m0);
  LongRun out;
  out.steps = quick ? 100000 : 1000000;
  for (std::int64_t k = 1; k <= out.steps; ++k) {
    split_free_body(body, s, h, 1, SplittingOrder::strang2);
    const double e = std::abs(body.energy(s.m_B) - E0) / E0;
    if (static_cast<double>(k) * h <= 10.0) out.energy_error_10 = std::max(out.energy_error_10, e);
    out.energy_error_1e4 = std::max(out.energy_error_1e4, e);
  }
  out.L_error_end = std::abs(s.m_B.norm() - p.m0.norm()) / p.m0.norm();
  return out;
}

namespace {
double component_ns(const Report& r, const std::string& method) {
  for (const auto& c : r.components) {
    if (c.method == method) return c.ns_per_call;
  }
  return -1.0;
}
}  // namespace

void evaluate_targets(Report& r) {
  r.targets.clear();
  // P1: wobble's best adaptive method at error 1e-12 against each peer.
  for (const auto& [peer, limit] :
       {std::pair{"odeint_dopri5", 0.5}, std::pair{"odeint_rkf78", 1.0}}) {
    double best = -1.0;
    for (const char* mine : {"dopri5", "rkf78"}) {
      const double ratio = time_ratio_at(r.runs, "P1", mine, peer, 1e-12);
      if (ratio > 0 && (best < 0 || ratio < best)) best = ratio;
    }
    r.targets.push_back(
        {std::string("P1: best adaptive / ") + peer + " time at error 1e-12", best, limit, "x"});
  }
  const double w = component_ns(r, "wobble exact w(t) (m(t) / I)");
  const double boost = component_ns(r, "Boost.Math jacobi_elliptic(k, u), default policy");
  r.targets.push_back({"exact w(t) / one Boost jacobi_elliptic call",
                       w > 0 && boost > 0 ? w / boost : -1, 0.25, "x"});
  for (const auto& c : r.components) {
    if (c.method == "wobble exact w(t) (m(t) / I)") {
      r.targets.push_back(
          {"exact w(t) relative error, k'^2 to 1e-16, t until u = K", c.max_error, 4.0, "eps"});
    }
  }
  r.targets.push_back(
      {"P2: splitting |L| relative error after the run", r.long_run.L_error_end, 1e-13, ""});
  r.targets.push_back({"P2: splitting energy error over [0, 1e4] / over [0, 10]",
                       r.long_run.energy_error_10 > 0
                           ? r.long_run.energy_error_1e4 / r.long_run.energy_error_10
                           : -1,
                       2.0, "x"});
  double slowest_solve = -1.0;
  for (const auto& c : r.components) {
    if (c.group == "process" && c.method.rfind("wobble solve", 0) == 0)
      slowest_solve = std::max(slowest_solve, c.ns_per_call * 1e-6);
    if (c.method == "wobble keys --check")
      r.targets.push_back(
          {"wobble keys --check, whole process", c.ns_per_call * 1e-6, 1000.0, "ms"});
  }
  r.targets.push_back({"slowest wobble solve, whole process", slowest_solve, 50.0, "ms"});
}

}  // namespace wobble::bench
