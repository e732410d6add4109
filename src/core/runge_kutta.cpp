#include "core/runge_kutta.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "core/work_budget.hpp"

namespace wobble {

namespace {
// A span that is a whole number of steps up to rounding (t_end = 1, h = 0.1: 10.000000000000002
// steps) must not get one more tiny step: ratios within this of a whole number count as it.
constexpr double kStepCountSlack = 1e-12;
}  // namespace

namespace {
// Explicit Runge-Kutta tableaux as compile-time constants: the stage loops below are unrolled
// over them and the zero coefficients drop out (a measured 20-30% of the step's time with the
// run-time tableau this replaced). A: lower triangular; B: weights of the propagated solution;
// E = B - B_hat: weights of the error estimate; kErrorOrder: order of the lower member.
template <std::size_t S>
using Row = std::array<double, S>;

struct Rk4 {
  static constexpr std::size_t S = 4;
  static constexpr std::array<Row<S>, S> A{
      {{0, 0, 0, 0}, {0.5, 0, 0, 0}, {0, 0.5, 0, 0}, {0, 0, 1, 0}}};
  static constexpr Row<S> B{1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6};
  // No embedded pair: E and the error order are there for the common shape only.
  [[maybe_unused]] static constexpr Row<S> E{0, 0, 0, 0};
  [[maybe_unused]] static constexpr int kErrorOrder = 4;
  [[maybe_unused]] static constexpr bool kFsal = false;
  static constexpr bool kEmbedded = false;
};

// Dormand and Prince (1980), the 5(4) pair of RK5(4)7M. First same as last: the seventh stage
// is evaluated at the new solution, so it is the next step's first.
struct Dopri5 {
  static constexpr std::size_t S = 7;
  static constexpr std::array<Row<S>, S> A{
      {{0, 0, 0, 0, 0, 0, 0},
       {1.0 / 5, 0, 0, 0, 0, 0, 0},
       {3.0 / 40, 9.0 / 40, 0, 0, 0, 0, 0},
       {44.0 / 45, -56.0 / 15, 32.0 / 9, 0, 0, 0, 0},
       {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729, 0, 0, 0},
       {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656, 0, 0},
       {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0}}};
  static constexpr Row<S> B{35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0};
  static constexpr Row<S> E{35.0 / 384 - 5179.0 / 57600,
                            0,
                            500.0 / 1113 - 7571.0 / 16695,
                            125.0 / 192 - 393.0 / 640,
                            -2187.0 / 6784 + 92097.0 / 339200,
                            11.0 / 84 - 187.0 / 2100,
                            -1.0 / 40};
  static constexpr int kErrorOrder = 4;
  static constexpr bool kFsal = true;
  static constexpr bool kEmbedded = true;
};

// Fehlberg (1968), the 7(8) pair, NASA TR R-287 table X; the same coefficients as
// Boost.Odeint's runge_kutta_fehlberg78.
struct Rkf78 {
  static constexpr std::size_t S = 13;
  static constexpr std::array<Row<S>, S> A{
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
        33.0 / 164, 12.0 / 41, 0, 1}}};
  static constexpr Row<S> B{0,        0,         0,         0, 0,          34.0 / 105, 9.0 / 35,
                            9.0 / 35, 9.0 / 280, 9.0 / 280, 0, 41.0 / 840, 41.0 / 840};
  static constexpr Row<S> E{-41.0 / 840, 0, 0, 0,           0,          0,         0,
                            0,           0, 0, -41.0 / 840, 41.0 / 840, 41.0 / 840};
  static constexpr int kErrorOrder = 7;
  static constexpr bool kFsal = false;
  static constexpr bool kEmbedded = true;
};

template <class T>
using Stages = std::array<State7, T::S>;

// Which row of the tableau: A[R], B or E. (A row is named by its index, not passed as a
// reference template argument: clang 14 refuses a subobject such as T::A[I] there.)
enum class Coefficients { a, b, e };

template <class T, Coefficients W, std::size_t R>
constexpr const Row<T::S>& row() {
  if constexpr (W == Coefficients::a) {
    return T::A[R];
  } else if constexpr (W == Coefficients::b) {
    return T::B;
  } else {
    return T::E;
  }
}

// sum_j c[j] k[j] over the nonzero c[j], j < N, unrolled (c is a constant expression).
template <class T, Coefficients W, std::size_t R, std::size_t... J>
State7 combine(const Stages<T>& k, std::index_sequence<J...>) {
  constexpr const Row<T::S>& C = row<T, W, R>();
  State7 acc = State7::Zero();
  ((C[J] != 0.0 ? (void)(acc += C[J] * k[J]) : (void)0), ...);
  return acc;
}

// The stages 1 .. S-1; of a first-same-as-last pair the last is f(y_new), left to rk_step.
template <class T, std::size_t I>
void stage(const RigidBodyModel& model, const State7& y, double h, Stages<T>& k) {
  if constexpr (I < (T::kFsal ? T::S - 1 : T::S)) {
    k[I] = model.rhs(y + h * combine<T, Coefficients::a, I>(k, std::make_index_sequence<I>{}));
    stage<T, I + 1>(model, y, h, k);
  }
}

// One step of size h. k[0] must hold f(y) already (FSAL, or computed by the caller).
template <class T>
void rk_step(const RigidBodyModel& model, const State7& y, double h, Stages<T>& k, State7& y_new,
             State7& err, IntegrationCost& cost) {
  stage<T, 1>(model, y, h, k);
  cost.rhs_evals += static_cast<std::int64_t>(T::S - 1);
  y_new = y + h * combine<T, Coefficients::b, 0>(k, std::make_index_sequence<T::S>{});
  // First same as last: the last stage's argument is y_new itself (its A row is B), formed once.
  if constexpr (T::kFsal) k[T::S - 1] = model.rhs(y_new);
  if constexpr (T::kEmbedded) {
    err = h * combine<T, Coefficients::e, 0>(k, std::make_index_sequence<T::S>{});
  }
}

// Once per step: cheap (a relaxed load and a comparison).
void check_budget(const IntegrationCost& cost, std::int64_t limit) {
  throw_if_interrupted();
  if (cost.rhs_evals > limit) {
    throw WorkLimitReached("the run needed more than " + std::to_string(limit) +
                           " right-hand-side evaluations");
  }
}

void renormalise(State7& y) {
  y.tail<4>() *= 1.0 / y.tail<4>().norm();
}

template <class T>
void advance_fixed(const RigidBodyModel& model, State7& y, double span, double h_max,
                   IntegrationCost& cost, std::int64_t limit) {
  const auto n =
      std::max<std::int64_t>(static_cast<std::int64_t>(std::ceil(span / h_max * (1 - kStepCountSlack))), 1);
  const double h = span / static_cast<double>(n);
  Stages<T> k;
  State7 y_new, err;
  for (std::int64_t i = 0; i < n; ++i) {
    k[0] = model.rhs(y);
    ++cost.rhs_evals;
    rk_step<T>(model, y, h, k, y_new, err, cost);
    y = y_new;
    renormalise(y);
    ++cost.steps;
    check_budget(cost, limit);
  }
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
  inverse_scale_ << 1 / momentum_scale, 1 / momentum_scale, 1 / momentum_scale, 1, 1, 1, 1;
}

void RungeKutta::advance(State7& y, double t0, double t1) {
  const double span = t1 - t0;
  if (!(span > 0.0)) return;
  if (fixed_) {
    switch (method_) {
      case RkMethod::rk4:
        advance_fixed<Rk4>(model_, y, span, tol_or_step_, cost_, limit_);
        return;
      case RkMethod::dopri5:
        advance_fixed<Dopri5>(model_, y, span, tol_or_step_, cost_, limit_);
        return;
      case RkMethod::rkf78:
        advance_fixed<Rkf78>(model_, y, span, tol_or_step_, cost_, limit_);
        return;
    }
  }
  if (method_ == RkMethod::dopri5) {
    advance_adaptive<Dopri5>(y, t0, t1);
  } else {
    advance_adaptive<Rkf78>(y, t0, t1);
  }
}

template <class T>
void RungeKutta::advance_adaptive(State7& y, double t0, double t1) {
  const double span = t1 - t0, tol = tol_or_step_;
  constexpr double expo = 1.0 / (T::kErrorOrder + 1);
  if (h_ == 0.0) {
    // First trial step: a small fraction of the time the body needs to turn by one radian.
    const double rate = model_.omega_P(y.head<3>()).norm();
    h_ = std::min(span, 0.05 * std::pow(tol, expo) / std::max(rate, 1e-300) + 1e-300);
  }
  Stages<T> k;
  State7 y_new, err;
  // First same as last: f(y) from the previous accepted step, if y is still that step's end.
  bool k0_valid = T::kFsal && fsal_valid_ && y == fsal_y_;
  if (k0_valid) k[0] = fsal_k_;
  double t_now = t0;
  while (t_now < t1) {
    const bool last = t_now + h_ * (1 + kStepCountSlack) >= t1;  // no sliver of a last step
    const double h = last ? t1 - t_now : h_;
    if (!k0_valid) {  // f(y) once per accepted state, however many tries the step takes
      k[0] = model_.rhs(y);
      ++cost_.rhs_evals;
      k0_valid = true;
    }
    rk_step<T>(model_, y, h, k, y_new, err, cost_);
    const double e = (err.cwiseAbs().cwiseProduct(inverse_scale_)).maxCoeff() / tol;
    // Between half the tolerance and the tolerance the step is kept as it is (the formula's
    // factor would be 0.9 to 1.03 there): no pow() for most steps, which cost 15% of a
    // Dormand-Prince step (measured), and no dithering of h. Boost.Odeint's controller does the same.
    constexpr double kKeepBelow = 0.5;
    const double factor = e >= kKeepBelow && e <= 1.0
                              ? 1.0
                              : std::clamp(0.9 * std::pow(std::max(e, 1e-300), -expo), 0.2, 5.0);
    if (!std::isfinite(e)) {
      h_ = 0.2 * h;
    } else if (e <= 1.0) {
      y = y_new;
      renormalise(y);
      t_now = last ? t1 : t_now + h;
      ++cost_.steps;
      // A step shortened to land on t1 says nothing about the next: keep the longer one.
      h_ = last ? std::max(h_, h * factor) : h * factor;
      if constexpr (T::kFsal) {
        k[0] = k[T::S - 1];  // f at the new y (before renormalising: |q| - 1 ~ tol, linear in q)
      } else {
        k0_valid = false;
      }
    } else {
      ++cost_.rejected;
      h_ = h * factor;
    }
    check_budget(cost_, limit_);
    // Steps below this share of the time change t by a few ulps: the time cannot resolve them.
    constexpr double kSmallestStepShare = 1e-14;
    if (h_ < kSmallestStepShare * std::max(std::abs(t_now), span)) {
      // The motion changes faster than the time can be resolved (a singular or overflowing
      // scene): the input's doing, said in its terms.
      char at[32];
      std::snprintf(at, sizeof at, "%.6g", t_now);
      char share[32];
      std::snprintf(share, sizeof share, "%.0e", kSmallestStepShare);
      throw InputError(std::string("the motion changes too fast to follow at t = ") + at +
                       " s (the integrator's step fell below " + share +
                       " of the time); the scene may be singular there: look at its values, or "
                       "shorten the run");
    }
  }
  if constexpr (T::kFsal) {
    fsal_valid_ = true;
    fsal_y_ = y;
    fsal_k_ = k[0];
  }
}

}  // namespace wobble
