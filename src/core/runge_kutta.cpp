#include "core/runge_kutta.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace wobble {

namespace {
// An explicit Runge-Kutta tableau: a (lower triangular, row i has i entries), the weights b of
// the propagated solution, and e = b - b_hat, the weights of the error estimate.
struct Tableau {
  std::vector<double> c;
  std::vector<std::vector<double>> a;
  std::vector<double> b, e;
  int error_order;  ///< order of the lower-order member (the estimate is O(h^(p+1)))
};

const Tableau& rk4_tableau() {
  static const Tableau t{{0, 0.5, 0.5, 1},
                         {{}, {0.5}, {0, 0.5}, {0, 0, 1}},
                         {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6},
                         {},
                         4};
  return t;
}

// Dormand and Prince (1980), the 5(4) pair of RK5(4)7M.
const Tableau& dopri5_tableau() {
  static const Tableau t{
      {0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1},
      {{},
       {1.0 / 5},
       {3.0 / 40, 9.0 / 40},
       {44.0 / 45, -56.0 / 15, 32.0 / 9},
       {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
       {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
       {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}},
      {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0},
      {35.0 / 384 - 5179.0 / 57600, 0, 500.0 / 1113 - 7571.0 / 16695, 125.0 / 192 - 393.0 / 640,
       -2187.0 / 6784 + 92097.0 / 339200, 11.0 / 84 - 187.0 / 2100, -1.0 / 40},
      4};
  return t;
}

// Fehlberg (1968), the 7(8) pair, NASA TR R-287 table X; the same coefficients as
// Boost.Odeint's runge_kutta_fehlberg78.
const Tableau& rkf78_tableau() {
  static const Tableau t{
      {0, 2.0 / 27, 1.0 / 9, 1.0 / 6, 5.0 / 12, 1.0 / 2, 5.0 / 6, 1.0 / 6, 2.0 / 3, 1.0 / 3, 1, 0,
       1},
      {{},
       {2.0 / 27},
       {1.0 / 36, 1.0 / 12},
       {1.0 / 24, 0, 1.0 / 8},
       {5.0 / 12, 0, -25.0 / 16, 25.0 / 16},
       {1.0 / 20, 0, 0, 1.0 / 4, 1.0 / 5},
       {-25.0 / 108, 0, 0, 125.0 / 108, -65.0 / 27, 125.0 / 54},
       {31.0 / 300, 0, 0, 0, 61.0 / 225, -2.0 / 9, 13.0 / 900},
       {2, 0, 0, -53.0 / 6, 704.0 / 45, -107.0 / 9, 67.0 / 90, 3},
       {-91.0 / 108, 0, 0, 23.0 / 108, -976.0 / 135, 311.0 / 54, -19.0 / 60, 17.0 / 6, -1.0 / 12},
       {2383.0 / 4100, 0, 0, -341.0 / 164, 4496.0 / 1025, -301.0 / 82, 2133.0 / 4100, 45.0 / 82,
        45.0 / 164, 18.0 / 41},
       {3.0 / 205, 0, 0, 0, 0, -6.0 / 41, -3.0 / 205, -3.0 / 41, 3.0 / 41, 6.0 / 41, 0},
       {-1777.0 / 4100, 0, 0, -341.0 / 164, 4496.0 / 1025, -289.0 / 82, 2193.0 / 4100, 51.0 / 82,
        33.0 / 164, 12.0 / 41, 0, 1}},
      {0, 0, 0, 0, 0, 34.0 / 105, 9.0 / 35, 9.0 / 35, 9.0 / 280, 9.0 / 280, 0, 41.0 / 840,
       41.0 / 840},
      {-41.0 / 840, 0, 0, 0, 0, 0, 0, 0, 0, 0, -41.0 / 840, 41.0 / 840, 41.0 / 840},
      7};
  return t;
}

const Tableau& tableau(RkMethod m) {
  switch (m) {
    case RkMethod::rk4:
      return rk4_tableau();
    case RkMethod::dopri5:
      return dopri5_tableau();
    case RkMethod::rkf78:
      break;
  }
  return rkf78_tableau();
}

// One step of size h: y_new, and (for a pair) the error estimate.
void rk_step(const RigidBodyModel& model, const Tableau& t, const State7& y, double h,
             State7& y_new, State7& err, IntegrationCost& cost) {
  const std::size_t s = t.b.size();
  std::array<State7, 13> k;
  for (std::size_t i = 0; i < s; ++i) {
    State7 yi = y;
    for (std::size_t j = 0; j < i; ++j) {
      if (t.a[i][j] != 0.0) yi += (h * t.a[i][j]) * k[j];
    }
    k[i] = model.rhs(yi);
  }
  cost.rhs_evals += static_cast<std::int64_t>(s);
  y_new = y;
  err.setZero();
  for (std::size_t i = 0; i < s; ++i) {
    if (t.b[i] != 0.0) y_new += (h * t.b[i]) * k[i];
    if (!t.e.empty() && t.e[i] != 0.0) err += (h * t.e[i]) * k[i];
  }
}

void renormalise(State7& y) {
  y.tail<4>() /= y.tail<4>().norm();
}
}  // namespace

int order_of(RkMethod m) {
  switch (m) {
    case RkMethod::rk4:
      return 4;
    case RkMethod::dopri5:
      return 5;
    case RkMethod::rkf78:
      break;
  }
  return 8;
}

std::string name_of(RkMethod m) {
  switch (m) {
    case RkMethod::rk4:
      return "rk4";
    case RkMethod::dopri5:
      return "dopri5";
    case RkMethod::rkf78:
      break;
  }
  return "rkf78";
}

RungeKutta::RungeKutta(const RigidBodyModel& model, RkMethod method, double tol_or_step,
                       double momentum_scale, bool fixed_step)
    : model_(model),
      method_(method),
      tol_or_step_(tol_or_step),
      fixed_(fixed_step || method == RkMethod::rk4) {
  model.validate();
  if (!std::isfinite(tol_or_step) || !(tol_or_step > 0.0))
    throw std::invalid_argument("Runge-Kutta: step or tolerance must be finite and > 0");
  if (!std::isfinite(momentum_scale) || !(momentum_scale > 0.0))
    throw std::invalid_argument("Runge-Kutta: momentum scale must be finite and > 0");
  scale_ << momentum_scale, momentum_scale, momentum_scale, 1, 1, 1, 1;
}

void RungeKutta::advance(State7& y, double t0, double t1) {
  const Tableau& t = tableau(method_);
  State7 y_new, err;
  const double span = t1 - t0;
  if (!(span > 0.0)) return;
  if (fixed_) {
    const auto n = static_cast<std::int64_t>(std::ceil(span / tol_or_step_ * (1 - 1e-12)));
    const double h = span / static_cast<double>(std::max<std::int64_t>(n, 1));
    for (std::int64_t i = 0; i < std::max<std::int64_t>(n, 1); ++i) {
      rk_step(model_, t, y, h, y_new, err, cost_);
      y = y_new;
      renormalise(y);
      ++cost_.steps;
    }
    return;
  }
  const double tol = tol_or_step_;
  const double expo = 1.0 / (t.error_order + 1);
  if (h_ == 0.0) {
    // First trial step: a small fraction of the time the body needs to turn by one radian.
    const double rate = model_.omega_P(y.head<3>()).norm();
    h_ = std::min(span, 0.05 * std::pow(tol, expo) / std::max(rate, 1e-300) + 1e-300);
    h_ = std::min(h_, span);
  }
  double t_now = t0;
  while (t_now < t1) {
    const bool last = t_now + h_ * (1 + 1e-12) >= t1;
    const double h = last ? t1 - t_now : h_;
    rk_step(model_, t, y, h, y_new, err, cost_);
    const double e = (err.cwiseAbs().cwiseQuotient(scale_)).maxCoeff() / tol;
    const double factor = std::clamp(0.9 * std::pow(std::max(e, 1e-300), -expo), 0.2, 5.0);
    if (!std::isfinite(e)) {
      h_ = 0.2 * h;
    } else if (e <= 1.0) {
      y = y_new;
      renormalise(y);
      t_now = last ? t1 : t_now + h;
      ++cost_.steps;
      // A step shortened to land on t1 says nothing about the next: keep the longer one.
      h_ = last ? std::max(h_, h * factor) : h * factor;
    } else {
      ++cost_.rejected;
      h_ = h * factor;
    }
    if (h_ < 1e-14 * std::max(std::abs(t_now), span)) {
      throw std::runtime_error("Runge-Kutta: step size underflow at t = " + std::to_string(t_now) +
                               " s");
    }
  }
}

}  // namespace wobble
