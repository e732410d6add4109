#pragma once
/// @file
/// The other libraries' integrators, on wobble's right-hand side (RigidBodyRhs, prepared once, the
/// state y = (m_P, q_PtoS)) and the bench's tolerances, for the work-precision tables:
/// - GSL's gsl_odeiv2 driver with rk8pd (Prince-Dormand 8(7)) and rkf45 (Fehlberg 4(5)),
///   error control eps_abs = eps_rel = tol (GSL's "y" scaling);
/// - SUNDIALS CVODE in Adams mode (variable order up to 12, fixed-point iteration: the
///   non-stiff setting), rtol = atol = tol.
/// Neither renormalises the quaternion (the caller does, once, at T).
#include <cstdint>

#include "core/rigid_body.hpp"

namespace wobble::bench {

struct PeerRun {
  State7 y;
  std::int64_t evals = 0;
};

enum class GslMethod { rk8pd, rkf45 };

/// y(0) -> y(T). @throws std::runtime_error if the peer reports a failure.
PeerRun run_gsl(const RigidBodyModel& model, const State7& y0, double T, double tol, GslMethod m);
PeerRun run_cvode_adams(const RigidBodyModel& model, const State7& y0, double T, double tol);

}  // namespace wobble::bench
