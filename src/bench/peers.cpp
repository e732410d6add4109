#include "bench/peers.hpp"

#include <cvode/cvode.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <nvector/nvector_serial.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <stdexcept>
#include <string>

namespace wobble::bench {

namespace {
struct Rhs {
  RigidBodyRhs f;  // prepared, as wobble's integrators evaluate it
  std::int64_t evals = 0;
  void operator()(const double* y, double* dydt) {
    Eigen::Map<State7> out(dydt);
    out = f(Eigen::Map<const State7>(y));
    ++evals;
  }
};

int gsl_rhs(double, const double y[], double dydt[], void* params) {
  (*static_cast<Rhs*>(params))(y, dydt);
  return GSL_SUCCESS;
}

int cvode_rhs(realtype, N_Vector y, N_Vector ydot, void* user_data) {
  (*static_cast<Rhs*>(user_data))(N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
  return 0;
}

void require(bool ok, const std::string& what) {
  if (!ok) throw std::runtime_error("bench peer: " + what);
}
}  // namespace

PeerRun run_gsl(const RigidBodyModel& model, const State7& y0, double T, double tol, GslMethod m) {
  Rhs rhs{RigidBodyRhs(model)};
  gsl_odeiv2_system sys{gsl_rhs, nullptr, 7, &rhs};
  const gsl_odeiv2_step_type* type = m == GslMethod::rk8pd ? gsl_odeiv2_step_rk8pd : gsl_odeiv2_step_rkf45;
  // The first trial step as Boost.Odeint's runs get it: T / 1000.
  gsl_odeiv2_driver* d = gsl_odeiv2_driver_alloc_y_new(&sys, type, T / 1000, tol, tol);
  require(d != nullptr, "gsl_odeiv2_driver_alloc_y_new failed");
  PeerRun out;
  out.y = y0;
  double t = 0.0;
  const int status = gsl_odeiv2_driver_apply(d, &t, T, out.y.data());
  gsl_odeiv2_driver_free(d);
  require(status == GSL_SUCCESS, std::string("gsl_odeiv2_driver_apply: ") + gsl_strerror(status));
  out.evals = rhs.evals;
  return out;
}

PeerRun run_cvode_adams(const RigidBodyModel& model, const State7& y0, double T, double tol) {
  Rhs rhs{RigidBodyRhs(model)};
  SUNContext ctx = nullptr;
  require(SUNContext_Create(nullptr, &ctx) == 0, "SUNContext_Create failed");
  N_Vector y = N_VNew_Serial(7, ctx);
  Eigen::Map<State7> start(N_VGetArrayPointer(y));
  start = y0;
  void* mem = CVodeCreate(CV_ADAMS, ctx);
  SUNNonlinearSolver fixed_point = SUNNonlinSol_FixedPoint(y, 0, ctx);
  int status = CVodeInit(mem, cvode_rhs, 0.0, y);
  if (status == CV_SUCCESS) status = CVodeSStolerances(mem, tol, tol);
  if (status == CV_SUCCESS) status = CVodeSetUserData(mem, &rhs);
  if (status == CV_SUCCESS) status = CVodeSetNonlinearSolver(mem, fixed_point);
  if (status == CV_SUCCESS) status = CVodeSetMaxNumSteps(mem, 100000000L);
  // Stop exactly at T, as the other peers do (CV_NORMAL alone may step past and interpolate).
  if (status == CV_SUCCESS) status = CVodeSetStopTime(mem, T);
  double t = 0.0;
  if (status == CV_SUCCESS) status = CVode(mem, T, y, &t, CV_NORMAL);
  PeerRun out;
  out.y = Eigen::Map<const State7>(N_VGetArrayPointer(y));
  out.evals = rhs.evals;
  CVodeFree(&mem);
  SUNNonlinSolFree(fixed_point);
  N_VDestroy(y);
  SUNContext_Free(&ctx);
  require(status >= 0, "CVODE failed with flag " + std::to_string(status));
  return out;
}

}  // namespace wobble::bench
