// The bench's machinery (not its timings, which belong to `wobble bench`): the sweeps cover
// every method and peer, errors are measured against the right reference, the equal-error
// ratio interpolates correctly, and the targets are judged as stated.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "bench/components.hpp"
#include "bench/report.hpp"
#include "render/bench_output.hpp"
#include "solvers/catalog.hpp"

using namespace wobble;
using namespace wobble::bench;
using Catch::Matchers::WithinRel;

namespace {
const TimingPlan kOnce{1, 0.0};  // one run per point: these tests check values, not speed
}

TEST_CASE("the P1 sweep runs every method and every peer, and tighter is more accurate") {
  const BenchProblem p1 = bench_problems().at(0);
  const std::vector<Run> runs = work_precision(p1, true, kOnce);
  for (const std::string m :
       {"exact", "dopri5", "rkf78", "dop853", "vern9", "odeint_dopri5", "odeint_rkf78", "gsl_rk8pd",
        "gsl_rkf45", "cvode_adams", "rk4", "split2", "split4"}) {
    INFO(m);
    REQUIRE(std::any_of(runs.begin(), runs.end(), [&](const Run& r) { return r.method == m; }));
  }
  // Every run is timed, all of them after the sweep (side by side); a function whose captures
  // did not outlive the sweep's loops would show here under the sanitizers.
  for (const auto& r : runs) {
    INFO(r.method << " " << r.setting);
    CHECK(r.time_s > 0.0);
  }
  double last = 1.0;
  // The reference is m(T) at 50 digits: the exact solution is within 8 eps (1 + condition) of
  // it, as in hard case 6, and not 0 (it is not its own reference).
  const double cond = measured_condition(p1);
  for (const auto& r : runs) {
    if (r.method == "exact") {
      INFO("exact: " << r.error << ", condition " << cond);
      REQUIRE(r.error > 0.0);
      REQUIRE(r.error <= 8 * 0x1p-52 * (1 + cond));
    }
    if (r.method != "rkf78") continue;
    INFO(r.setting << ": " << r.error);
    REQUIRE(r.error < last);  // the quick sweep's tolerances fall by 1e3 or more
    last = r.error;
    REQUIRE(r.evals > 0);
  }
  // Splitting keeps |L| to round-off at every step size: 4 eps sqrt(sub-flows).
  for (const auto& r : runs) {
    if (r.method.rfind("split", 0) == 0) {
      REQUIRE(r.L_error <= 4 * 2.2e-16 * std::sqrt(static_cast<double>(r.evals)));
    }
  }
}

TEST_CASE("functions timed side by side are called in turns, warm, once each per repeat") {
  std::vector<int> calls;
  const std::vector<double> t = median_times_s(
      {[&] { calls.push_back(0); }, [&] { calls.push_back(1); }, [&] { calls.push_back(2); }},
      TimingPlan{3, 0.0});
  // With no least sample length each measurement is one call: first one call of each to find
  // that count, then three rounds, each going once around the three, each f called twice in its
  // turn (an untimed call that warms it, then the measured one).
  CHECK(calls == std::vector<int>{0, 1, 2, 0, 0, 1, 1, 2, 2, 0, 0, 1, 1, 2, 2, 0, 0, 1, 1, 2, 2});
  REQUIRE(t.size() == 3);
  for (const double ti : t) CHECK(ti >= 0.0);
  CHECK_THROWS_AS(median_times_s({[] {}}, TimingPlan{0, 0.0}), std::invalid_argument);
}

TEST_CASE("time_ratio_at interpolates log-log between the bracketing points") {
  // Curve a: error 1e-6 at 1 s, 1e-10 at 10 s -> at 1e-8, sqrt(10) s. Curve b: 2x slower.
  std::vector<Run> runs;
  for (const auto& [m, scale] : {std::pair{"a", 1.0}, std::pair{"b", 2.0}}) {
    runs.push_back({"P", m, false, "", 1e-6, 0, 0, 1, 1.0 * scale});
    runs.push_back({"P", m, false, "", 1e-10, 0, 0, 1, 10.0 * scale});
  }
  REQUIRE_THAT(time_ratio_at(runs, "P", "a", "b", 1e-8), WithinRel(0.5, 1e-12));
  REQUIRE(time_ratio_at(runs, "P", "a", "b", 1e-12) < 0);  // outside both curves
  REQUIRE(time_ratio_at(runs, "Q", "a", "b", 1e-8) < 0);   // another problem
}

TEST_CASE("time_at_error reads the frontier: a costlier run no more accurate is passed over") {
  // Errors 1e-6, 1e-8, 1e-10 at 10, 20, 40 s, then round-off: 1e-9 at 80 s. At 1e-9 the
  // frontier gives sqrt(20 * 40) s (halfway in log e between 1e-8 and 1e-10); the run at 80 s,
  // bracketing 1e-9 with the one at 40 s when sorted by error, would give 80 s.
  std::vector<Run> runs;
  for (const auto& [error, time] : {std::pair{1e-6, 10.0}, std::pair{1e-8, 20.0},
                                    std::pair{1e-10, 40.0}, std::pair{1e-9, 80.0}}) {
    runs.push_back({"P", "a", false, "", error, 0, 0, 1, time});
  }
  // The interpolation's arithmetic: a few roundings of logs and an exp.
  const double rounding = 16 * std::numeric_limits<double>::epsilon();
  REQUIRE_THAT(time_at_error(runs, "P", "a", 1e-9), WithinRel(std::sqrt(20.0 * 40.0), rounding));
  REQUIRE_THAT(time_at_error(runs, "P", "a", 1e-7), WithinRel(std::sqrt(10.0 * 20.0), rounding));
  REQUIRE(time_at_error(runs, "P", "a", 1e-11) < 0);  // beyond the frontier's best
}

TEST_CASE("targets are judged as the bench states them") {
  Report r;
  r.components.push_back({"elliptic", "wobble exact w(t) (m(t) / I)", "", 2.0, "eps", 50});
  r.components.push_back(
      {"elliptic", "Boost.Math jacobi_elliptic(k, u), default policy", "", 1e15, "eps", 1000});
  r.components.push_back({"process", "wobble solve x", "", -1, "", 60e6});  // 60 ms
  r.long_run = {1e-14, 1e-5, 1.5e-5, 1000000};
  // P4: Fehlberg 7(8) reaches 1e-12 at sqrt(100 * 300) us (log-log halfway); the closed form
  // takes 5 us at error 1e-15 (4.5 eps); a peer only reaches 1e-10.
  const auto run = [](const char* method, double error, double time_s) {
    Run x;
    x.problem = "P4";
    x.method = method;
    x.error = error;
    x.time_s = time_s;
    return x;
  };
  r.runs = {run("rkf78", 1e-10, 100e-6), run("rkf78", 1e-14, 300e-6), run("exact", 1e-15, 5e-6),
            run("odeint_rkf78", 1e-8, 10e-6), run("odeint_rkf78", 1e-10, 20e-6)};
  evaluate_targets(r);
  const auto find = [&](const std::string& start) {
    for (const auto& t : r.targets) {
      if (t.what.rfind(start, 0) == 0) return t;
    }
    throw std::logic_error("no target " + start);
  };
  REQUIRE(find("exact w(t) / one Boost").met());                   // 50 / 1000 = 0.05 <= 0.25
  REQUIRE(find("exact w(t) relative error").met());                // 2 <= 4 eps
  REQUIRE(find("P2: splitting |L|").met());                        // 1e-14 <= 1e-13
  REQUIRE(find("P2: splitting energy").met());                     // 1.5 <= 2
  REQUIRE_FALSE(find("slowest wobble solve").met());               // 60 ms > 25 ms
  REQUIRE_FALSE(find("P1: dopri5 / odeint_dopri5").met());         // not measured
  // At 1e-10 Fehlberg takes 100 us, the peer 20 us: 5x, not met.
  REQUIRE_THAT(find("P4: best wobble integrator / best peer").measured, WithinRel(5.0, 1e-12));
  REQUIRE_THAT(find("P4: exact heavy top / best integrator").measured,
               WithinRel(5.0 / std::sqrt(100.0 * 300.0), 1e-12));
  REQUIRE(find("P4: exact heavy top / best integrator").met());   // 0.029 <= 0.05
  REQUIRE_THAT(find("P4: exact heavy top error").measured, WithinRel(1e-15 / 0x1p-52, 1e-12));
  REQUIRE(find("P4: exact heavy top error").met());  // 4.5 <= 16 eps
  REQUIRE_THAT(render_bench(r, "markdown"), Catch::Contains("| target | measured | limit |"));
}

TEST_CASE("P2 against time: Runge-Kutta energy error drifts, splitting's does not") {
  const std::vector<DriftRow> rows = drift_table(true);  // t = 10, 100, 1000
  for (const auto& d : rows) {
    INFO(d.method << ": " << d.energy_error[0] << " -> " << d.energy_error[2]);
    REQUIRE(d.energy_error.size() == 3);
    if (d.method == "dopri5" || d.method == "rkf78") {
      REQUIRE(d.energy_error[2] >= 10 * d.energy_error[0]);  // 100x the time: linear growth
    } else {
      REQUIRE(d.energy_error[2] <= 10 * d.energy_error[0]);  // bounded oscillation
      REQUIRE(d.L_error[2] <= 1e-13);                        // |L| to round-off
    }
  }
}

TEST_CASE("process timings run the program on every problem and keys --check, each run exiting 0") {
  const std::vector<ComponentRow> rows = process_bench(WOBBLE_EXE, 1);
  const std::vector<Problem> catalog = load_catalog();
  REQUIRE(rows.size() == catalog.size() + 1);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    INFO(rows[i].method);
    CHECK(rows[i].method == (i < catalog.size() ? "wobble solve " + catalog[i].id
                                                : std::string("wobble keys --check")));
    CHECK(rows[i].ns_per_call > 0);  // a failed run would time as -1 s
  }
}

TEST_CASE("a program that cannot run times as failed, not as fast") {
  const std::vector<ComponentRow> rows = process_bench("/nonexistent/wobble", 1);
  REQUIRE(rows.size() == load_catalog().size() + 1);
  for (const ComponentRow& row : rows) {
    INFO(row.method);
    CHECK(row.ns_per_call < 0);
  }
}
