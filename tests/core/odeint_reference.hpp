#pragma once
// An independent reference for the torque-free body: Boost.Odeint's Fehlberg 7(8) on (m, q)
// with its own right-hand side, written here, not wobble's.
#include <array>
#include <boost/numeric/odeint.hpp>

#include "core/free_body.hpp"

namespace wobble::testing {

inline FreeBodyState odeint_free_body(const Vec3& I, const Vec3& m0, const Quat& q0, double T,
                                      double tol = 1e-14) {
  using State = std::array<double, 7>;
  State x{m0.x(), m0.y(), m0.z(), q0.w(), q0.x(), q0.y(), q0.z()};
  auto rhs = [&I](const State& s, State& d, double) {
    const Vec3 m(s[0], s[1], s[2]);
    const Vec3 w = m.cwiseQuotient(I);
    const Vec3 dm = m.cross(w);
    const Quat dq = Quat(s[3], s[4], s[5], s[6]) * Quat(0.0, w.x(), w.y(), w.z());
    d = {dm.x(), dm.y(), dm.z(), 0.5 * dq.w(), 0.5 * dq.x(), 0.5 * dq.y(), 0.5 * dq.z()};
  };
  namespace ode = boost::numeric::odeint;
  if (T > 0) {
    // The stepper built in place: GCC 12 at -O3 warns (-Wmaybe-uninitialized) about the copy
    // of a temporary stepper inside Boost's make_controlled, a false positive.
    ode::controlled_runge_kutta<ode::runge_kutta_fehlberg78<State>> stepper(
        ode::default_error_checker<double, ode::array_algebra, ode::default_operations>(tol, tol));
    ode::integrate_adaptive(stepper, rhs, x, 0.0, T, 1e-3);
  }
  FreeBodyState s;
  s.m_B = Vec3(x[0], x[1], x[2]);
  s.q_BtoS = Quat(x[3], x[4], x[5], x[6]).normalized();
  return s;
}

/// Distance between two attitudes as rotation matrices (Frobenius), sign-free.
inline double attitude_distance(const Quat& a, const Quat& b) {
  return (a.toRotationMatrix() - b.toRotationMatrix()).norm();
}

}  // namespace wobble::testing
