#pragma once
/// @file
/// Work-precision of the integrators: for each method and each tolerance or step of a sweep,
/// the error reached against a reference, the invariants' errors, the right-hand-side
/// evaluations and the median run time. Peers on the same right-hand side and tolerances:
/// Boost.Odeint's controlled runge_kutta_dopri5 and runge_kutta_fehlberg78, GSL's rk8pd and
/// rkf45, SUNDIALS CVODE in Adams mode (bench/peers.hpp).
///
/// Problems:
/// - P1: free body I = (2, 1, 2/3), m0 = (cos 1.1, 0, sin 1.1), identity attitude, T = 10;
/// - P2: the same over T = 1e4 (energy and |L| errors against time);
/// - P3: near the separatrix, I = (1, 2, 3), m0 = (1e-4, 1, 1e-4), T = 200, with its measured
///   condition (how far a 1-ulp change of m0 moves m(T));
/// - P4: a heavy top.
/// References, never the method measured: the free body's m(T) and attitude at 50 digits
/// (bench/mp_reference.hpp), the heavy top's closed form at 50 digits. Exact rows: the free
/// body's and the heavy top's exact solutions (one state at T, set-up included).
/// Error: the larger of |m(T) - m_ref(T)| / |m0| and the Frobenius distance of the attitudes.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "bench/timing.hpp"
#include "core/rigid_body.hpp"

namespace wobble::bench {

struct BenchProblem {
  std::string id, description;
  RigidBodyModel model;
  Vec3 m0 = Vec3::Zero();
  Quat q0 = Quat::Identity();
  double T = 10.0;
};

std::vector<BenchProblem> bench_problems();

struct Run {
  std::string problem, method;
  bool peer = false;          ///< another library's integrator
  std::string setting;        ///< "tol 1e-08" or "h 0.01"
  double error = 0.0;         ///< at T, against the reference
  double energy_error = 0.0;  ///< relative, at T
  double L_error = 0.0;       ///< |L| (torque-free) or p_phi (gravity), relative to |m0|, at T
  std::int64_t evals = 0;     ///< right-hand-side evaluations (sub-flows for splittings)
  double time_s = 0.0;        ///< median whole-run time
};

/// The adaptive integrators of the sweeps by their names in Run::method: wobble's, and the
/// peers' (other libraries' on the same right-hand side and tolerances).
inline constexpr std::array<const char*, 4> kWobbleIntegrators{"dopri5", "rkf78", "dop853",
                                                               "vern9"};
inline constexpr std::array<const char*, 5> kPeerIntegrators{
    "odeint_dopri5", "odeint_rkf78", "gsl_rk8pd", "gsl_rkf45", "cvode_adams"};

/// Every method of wobble (and the peers) on problem p; `quick` sweeps fewer points.
std::vector<Run> work_precision(const BenchProblem& p, bool quick, const TimingPlan& plan);

/// P2 against time: the relative energy and |L| errors at t = 10, 100, 1000 (and 1e4 unless
/// quick) for the adaptive pairs at tolerance 1e-10 and the splittings at h = 0.01.
struct DriftRow {
  std::string method, setting;
  std::vector<double> times, energy_error, L_error;
};
std::vector<DriftRow> drift_table(bool quick);

/// The exact solutions' error against time: P2's free body at t = 10, 100, ..., 1e7 (1e6
/// periods) and P4's heavy top at t = 2, 20, ..., 2e6 (6e6 nutation periods):
/// |m(t) - m_50(t)| / (eps |m0|) and the attitudes' Frobenius distance / eps, the reference the
/// same motion at 50 digits from the same double inputs (bench/mp_reference.hpp).
struct ExactDriftPoint {
  std::string problem;
  double t_s = 0.0, periods = 0.0, error_eps = 0.0, attitude_eps = 0.0;
};
std::vector<ExactDriftPoint> exact_error_against_time();

/// What output times cost: one adaptive run over P2 (T = 1e4) at tolerance 1e-10, its states
/// given at 10 and at `many` (1e5; 1e4 if quick) equally spaced times (dense output where the
/// method has one, core/runge_kutta.hpp). The sink only sums a component.
struct DenseRow {
  std::string method, setting;
  std::size_t few = 10, many = 0;  ///< the two numbers of output times
  std::int64_t evals_few = 0, evals_many = 0;
  double time_few_s = 0.0, time_many_s = 0.0;
};
std::vector<DenseRow> dense_output_table(bool quick, const TimingPlan& plan);

/// The time `method` needs for error `target` on `problem`, interpolated log-log along its
/// curve's frontier (each run more accurate than every cheaper one) between the two runs that
/// bracket the target; negative if the frontier does not reach it.
double time_at_error(const std::vector<Run>& runs, const std::string& problem,
                     const std::string& method, double target);

/// The time method `a` needs for error `target` on `problem`, over the time `b` needs, each
/// interpolated log-log along its curve; negative if either curve does not reach the target.
double time_ratio_at(const std::vector<Run>& runs, const std::string& problem, const std::string& a,
                     const std::string& b, double target);

/// The condition of m(T) in m0: how far a change of eps |m0| in one component of m0 moves
/// m(T), in units of eps |m0| (the largest over the components; by the exact solution;
/// torque-free problems only, else -1).
double measured_condition(const BenchProblem& p);

}  // namespace wobble::bench
