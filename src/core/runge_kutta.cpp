#include "core/runge_kutta.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "core/runge_kutta_tableaux.hpp"
#include "core/work_budget.hpp"

namespace wobble {

namespace {
// A span that is a whole number of steps up to rounding (t_end = 1, h = 0.1: 10.000000000000002
// steps) must not get one more tiny step: ratios within this of a whole number count as it.
constexpr double kStepCountSlack = 1e-12;
}  // namespace

namespace {
using namespace rk_tableau;

template <class T>
using Stages = std::array<State7, T::S>;

// Which coefficients: a row of the tableau (A[R], B, E or E3), or of DOP853's dense output (row
// R of its extra stages or of its D). Named by selector and index, not passed as a reference
// template argument: clang 14 refuses a subobject such as T::A[I] there.
enum class Coefficients { a, b, e, e3, dense_extra, dense_d };

template <class T, Coefficients W, std::size_t R, std::size_t J>
constexpr double coefficient() {
  if constexpr (W == Coefficients::a) {
    return T::A[R][J];
  } else if constexpr (W == Coefficients::b) {
    return T::B[J];
  } else if constexpr (W == Coefficients::e) {
    return T::E[J];
  } else if constexpr (W == Coefficients::e3) {
    return T::E3[J];
  } else if constexpr (W == Coefficients::dense_extra) {
    return T::kExtraA[R][J];
  } else {
    return T::D[R][J];
  }
}

// acc += c v, written out over the seven components: Eigen's assignment kernel for this was
// left as a call in a unit this large (18% of a DOP853 run with dense output in a profile).
[[gnu::always_inline]] inline void axpy(State7& acc, double c, const State7& v) {
  for (int i = 0; i < 7; ++i) acc.data()[i] += c * v.data()[i];
}

// The first j in J... with c_j nonzero, or sizeof...(J) if there is none.
template <class T, Coefficients W, std::size_t R, std::size_t... J>
constexpr std::size_t first_nonzero(std::index_sequence<J...>) {
  std::size_t first = sizeof...(J);
  ((first == sizeof...(J) && coefficient<T, W, R, J>() != 0.0 ? (void)(first = J) : (void)0), ...);
  return first;
}

// sum_j (c_j h) k[j] over the nonzero c_j, j in J..., unrolled (each c_j a constant expression;
// h = 1 leaves them as they are). The sum starts from its first term, not from zero: 0 + x is
// not x for x = -0, so the compiler keeps an addition of zero per component that starting from
// zero would cost. A step's h multiplies each coefficient, not the sum: the products c_j h are
// scalars that do not wait for the stages, while h times the sum was one more multiplication per
// component between a stage's slope and the next stage's argument, the chain every step waits
// on (measured on the bench's P1, Dormand-Prince at 1e-12: Odeint's time per evaluation 0.85x
// -> 0.80x in a side-by-side harness, the bench's ratio at equal error 1.02 -> 0.95). The sum of
// the increments is still formed before it is added to y, so that y takes one rounding per stage
// and not one per term.
template <class T, Coefficients W, std::size_t R, class Vectors, std::size_t... J>
[[gnu::always_inline]] inline State7 combine(const Vectors& k, std::index_sequence<J...> js,
                                             double h = 1.0) {
  constexpr std::size_t first = first_nonzero<T, W, R>(js);
  if constexpr (first == sizeof...(J)) {
    return State7::Zero();
  } else {
    State7 acc;
    const double c_first = coefficient<T, W, R, first>() * h;
    for (int i = 0; i < 7; ++i) acc.data()[i] = c_first * k[first].data()[i];
    ((J != first && coefficient<T, W, R, J>() != 0.0
          ? axpy(acc, coefficient<T, W, R, J>() * h, k[J])
          : (void)0),
     ...);
    return acc;
  }
}

// The stages 1 .. S-1; of a first-same-as-last pair the last is f(y_new), left to rk_step.
template <class T, std::size_t I>
void stage(const RigidBodyRhs& f, const State7& y, double h, Stages<T>& k) {
  if constexpr (I < (T::kFsal ? T::S - 1 : T::S)) {
    k[I] = f(y + combine<T, Coefficients::a, I>(k, std::make_index_sequence<I>{}, h));
    stage<T, I + 1>(f, y, h, k);
  }
}

// One step of size h. k[0] must hold f(y) already (FSAL, or computed by the caller). Returns
// the error measure max_i |err_i| * inverse_scale_i (0 for a pair without an estimate).
template <class T>
double rk_step(const RigidBodyRhs& f, const State7& y, double h, Stages<T>& k, State7& y_new,
               const State7& inverse_scale, IntegrationCost& cost) {
  stage<T, 1>(f, y, h, k);
  cost.rhs_evals += static_cast<std::int64_t>(T::S - 1);
  y_new = y + combine<T, Coefficients::b, 0>(k, std::make_index_sequence<T::S>{}, h);
  // First same as last: the last stage's argument is y_new itself (its A row is B), formed once.
  if constexpr (T::kFsal) k[T::S - 1] = f(y_new);
  const auto measure = [&](const State7& err) {
    return std::abs(h) * err.cwiseAbs().cwiseProduct(inverse_scale).maxCoeff();
  };
  if constexpr (T::kTwoEstimates) {
    // DOP853: the order-5 estimate tempered by the order-3 one (Hairer's dop853.f).
    const double e5 = measure(combine<T, Coefficients::e, 0>(k, std::make_index_sequence<T::S>{}));
    const double e3 = measure(combine<T, Coefficients::e3, 0>(k, std::make_index_sequence<T::S>{}));
    const double denominator = e5 * e5 + 0.01 * e3 * e3;
    return denominator > 0.0 ? e5 * e5 / std::sqrt(denominator) : 0.0;
  } else if constexpr (T::kEmbedded) {
    return measure(combine<T, Coefficients::e, 0>(k, std::make_index_sequence<T::S>{}));
  } else {
    return 0.0;
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

// |q|^2 from four scalar loads. Eigen's squaredNorm() loads q's components in pairs, and a pair
// that straddles two of the step's stores cannot be forwarded from them: the load waits for the
// stores to reach the cache. On the bench's P1 (Dormand-Prince, tolerance 1e-12) that load and
// the multiply after it held half the samples of the integrator's own loop in a profile; written
// out, a run went from 40.1-40.4 to 38.6-39.1 us (medians of 41, two side-by-side runs).
double quaternion_squared_norm(const State7& y) {
  const double* q = y.data() + 3;
  return q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
}

// Scales q to unit length; returns the factor. f's q part, q (0, w) / 2, scales with it and its
// m part does not depend on |q| (the torques use q / |q|): a first-same-as-last stage f(y)
// stays f of the renormalised y when its q part is multiplied by the same factor.
// Near unit length, |q|^2 = 1 + d with |d| <= 2^-18 (every dense output sample and every
// renormalisation between steps: q strays by 1e-6 at most, below), the factor 1 / sqrt(1 + d) is
// its series 1 - d/2 + 3 d^2/8: the first term left out, 5/16 |d|^3, is under 0.08 ulp of 1, and
// d = |q|^2 - 1 is exact (Sterbenz). Written out over q's four components: Eigen's norm() reads
// them in pairs just after a sample's interpolant stored them one by one, likely a stall for
// each pair. Measured per sample of Dormand-Prince's dense output (P2, 1e5 samples): 56 ns with
// norm() and a division, 49 with the series, 38 written out (28 with no renormalising at all).
constexpr double kSeriesReach = 0x1p-18;
double renormalise(State7& y) {
  double* q = y.data() + 3;
  const double squared = quaternion_squared_norm(y), d = squared - 1.0;
  const double factor =
      std::abs(d) <= kSeriesReach ? 1.0 + d * (-0.5 + 0.375 * d) : 1.0 / std::sqrt(squared);
  for (int i = 0; i < 4; ++i) q[i] *= factor;
  return factor;
}

// Between steps the quaternion may stray from unit length: the right-hand side uses the
// rotation of q / |q| and dq/dt is linear in q, so |q| never enters the motion; only the error
// control measures q's components against 1, which a share of 1e-6 leaves as it is. Renormalising
// after every step instead (a square root and a division on the path from one step to the
// next) cost a quarter of a Dormand-Prince 5(4) step (measured: 27.5 against 20.7 ns per
// evaluation on the free body).
constexpr double kUnitSlack = 1e-6;
double keep_near_unit(State7& y) {
  return std::abs(quaternion_squared_norm(y) - 1.0) > kUnitSlack ? renormalise(y) : 1.0;
}

template <class T>
void advance_fixed(const RigidBodyRhs& f, State7& y, double span, double h_max,
                   IntegrationCost& cost, std::int64_t limit) {
  const auto n =
      std::max<std::int64_t>(static_cast<std::int64_t>(std::ceil(span / h_max * (1 - kStepCountSlack))), 1);
  const double h = span / static_cast<double>(n);
  Stages<T> k;
  State7 y_new;
  const State7 no_scale = State7::Zero();
  for (std::int64_t i = 0; i < n; ++i) {
    k[0] = f(y);
    ++cost.rhs_evals;
    rk_step<T>(f, y, h, k, y_new, no_scale, cost);
    y = y_new;
    keep_near_unit(y);
    ++cost.steps;
    check_budget(cost, limit);
  }
  renormalise(y);
}

// Dense output over one accepted step [t, t + h]: y(t + x h) for 0 <= x <= 1, from the step's
// stages, so that output times need not end steps. DenseStep<T> is made for a step that holds a
// sample and lives while its samples are taken (it may keep references to the step's state and
// stages); at(x) is the interpolant at x.
template <class T>
class DenseStep;

// Dormand-Prince: Shampine's quartic in the tableau's own form, y(t + x h) = y_old + h sum_j
// w_j(x) k_j with w_j(x) = sum_p P[j][p] x^(p+1): the seven scalar polynomials side by side, then
// one weighted sum of six stages (k_2's weight is zero) per sample; nothing is built per step.
// When samples are dense enough to cost anything, most steps hold at most one (1e5 over P2's
// 186,000 steps), and then building Hairer's nested coefficients first (a Hermite part and one
// weighted sum) and evaluating them did more work (counted on P2 with 1e5 samples: 296 -> 226
// instructions per sample). With many samples in a step the two cost about the same.
template <>
class DenseStep<Dopri5> {
 public:
  DenseStep(const RigidBodyRhs&, const State7& y_old, const State7&, double h,
            const Stages<Dopri5>& k, IntegrationCost&)
      : y_old_(y_old), h_(h), k_(k) {}

  State7 at(double x) const { return sum(x, kStagesUsed); }

 private:
  // Every stage but k_2, whose row is zero.
  static constexpr std::index_sequence<0, 2, 3, 4, 5, 6> kStagesUsed{};
  static_assert(Dopri5::S == 7 && Dopri5::P[1] == std::array<double, 4>{});
  using Weights = Eigen::Matrix<double, Dopri5::S, 1>;

  // Column p of P: the weights' polynomials are evaluated side by side.
  template <std::size_t... J>
  static Weights column(std::size_t p, std::index_sequence<J...>) {
    return Weights(Dopri5::P[J][p]...);
  }

  template <std::size_t... J>
  State7 sum(double x, std::index_sequence<J...>) const {
    constexpr auto all = std::make_index_sequence<Dopri5::S>{};
    const Weights w =
        x * (column(0, all) + x * (column(1, all) + x * (column(2, all) + x * column(3, all))));
    return y_old_ + h_ * (... + (w[J] * k_[J]));
  }

  const State7& y_old_;
  double h_;
  const Stages<Dopri5>& k_;
};

// DOP853: three more stages, then seven vector coefficients c in Hairer's nested form y_old +
// x (c0 + (1-x) (c1 + x (c2 + (1-x) (c3 + ...)))): c0 = y_new - y_old, c1 and c2 from the end
// slopes (the cubic Hermite interpolant), c3 .. c6 from D; built once per step that holds a
// sample (three evaluations against the step's twelve, and seven weighted sums of 16 stages).
template <>
class DenseStep<Dop853> {
  using T = Dop853;

 public:
  DenseStep(const RigidBodyRhs& f, const State7& y_old, const State7& y_new, double h,
            const Stages<T>& k, IntegrationCost& cost)
      : y_old_(y_old) {
    std::array<State7, T::kExtended> K;
    std::copy(k.begin(), k.end(), K.begin());
    K[T::S] =
        f(y_old + combine<T, Coefficients::dense_extra, 0>(K, std::make_index_sequence<T::S>{}, h));
    K[T::S + 1] = f(y_old + combine<T, Coefficients::dense_extra, 1>(
                                K, std::make_index_sequence<T::S + 1>{}, h));
    K[T::S + 2] = f(y_old + combine<T, Coefficients::dense_extra, 2>(
                                K, std::make_index_sequence<T::S + 2>{}, h));
    cost.rhs_evals += static_cast<std::int64_t>(T::kExtraA.size());
    for (int j = 0; j < 7; ++j) {  // one pass over the components, as in axpy()
      const double dy = y_new.data()[j] - y_old.data()[j];
      const double c1 = h * k[0].data()[j] - dy;
      c_[0].data()[j] = dy;
      c_[1].data()[j] = c1;
      c_[2].data()[j] = dy - h * k[T::S - 1].data()[j] - c1;
    }
    constexpr auto all = std::make_index_sequence<T::kExtended>{};
    c_[3] = h * combine<T, Coefficients::dense_d, 0>(K, all);
    c_[4] = h * combine<T, Coefficients::dense_d, 1>(K, all);
    c_[5] = h * combine<T, Coefficients::dense_d, 2>(K, all);
    c_[6] = h * combine<T, Coefficients::dense_d, 3>(K, all);
  }

  State7 at(double x) const {
    constexpr std::size_t N = kCoefficients;
    const double x1 = 1.0 - x;  // the factor of every second level
    State7 y;
    for (int j = 0; j < 7; ++j) {  // written out, as in axpy(), for the same reason
      double acc = c_[N - 1].data()[j] * ((N - 1) % 2 == 0 ? x : x1);
      for (std::size_t i = N - 1; i-- > 0;) acc = (acc + c_[i].data()[j]) * (i % 2 == 0 ? x : x1);
      y.data()[j] = y_old_.data()[j] + acc;
    }
    return y;
  }

 private:
  static constexpr std::size_t kCoefficients = 7;
  const State7& y_old_;
  std::array<State7, kCoefficients> c_;
};
}  // namespace

int order_of(RkMethod m) {
  switch (m) {
    case RkMethod::rk4:
      return 4;
    case RkMethod::dopri5:
      return 5;
    case RkMethod::rkf78:
    case RkMethod::dop853:
      return 8;
    case RkMethod::vern9:
      break;
  }
  return 9;
}

std::string name_of(RkMethod m) {
  switch (m) {
    case RkMethod::rk4:
      return "rk4";
    case RkMethod::dopri5:
      return "dopri5";
    case RkMethod::rkf78:
      return "rkf78";
    case RkMethod::dop853:
      return "dop853";
    case RkMethod::vern9:
      break;
  }
  return "vern9";
}

RungeKutta::RungeKutta(const RigidBodyModel& model, RkMethod method, double tol_or_step,
                       double momentum_scale, bool fixed_step)
    : rhs_(model),
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
        advance_fixed<Rk4>(rhs_, y, span, tol_or_step_, cost_, limit_);
        return;
      case RkMethod::dopri5:
        advance_fixed<Dopri5>(rhs_, y, span, tol_or_step_, cost_, limit_);
        return;
      case RkMethod::rkf78:
        advance_fixed<Rkf78>(rhs_, y, span, tol_or_step_, cost_, limit_);
        return;
      case RkMethod::dop853:
        advance_fixed<Dop853>(rhs_, y, span, tol_or_step_, cost_, limit_);
        return;
      case RkMethod::vern9:
        advance_fixed<Vern9>(rhs_, y, span, tol_or_step_, cost_, limit_);
        return;
    }
  }
  const auto no_output = [](double, double, const State7&, const State7&, const auto&) {};
  switch (method_) {
    case RkMethod::dopri5:
      advance_adaptive<Dopri5>(y, t0, t1, no_output);
      return;
    case RkMethod::dop853:
      advance_adaptive<Dop853>(y, t0, t1, no_output);
      return;
    case RkMethod::vern9:
      advance_adaptive<Vern9>(y, t0, t1, no_output);
      return;
    case RkMethod::rk4:  // fixed, above
    case RkMethod::rkf78:
      advance_adaptive<Rkf78>(y, t0, t1, no_output);
      return;
  }
}

void RungeKutta::sample(State7& y, double t0, std::span<const double> times,
                        const SampleSink& at) {
  if (!std::is_sorted(times.begin(), times.end()))
    throw std::invalid_argument("Runge-Kutta: output times must be in increasing order");
  std::size_t next = 0;
  for (; next < times.size() && times[next] <= t0; ++next) at(next, y);
  if (next == times.size()) return;
  if (fixed_ || !(method_ == RkMethod::dopri5 || method_ == RkMethod::dop853)) {
    double t = t0;  // no dense output: the steps land on each time
    for (; next < times.size(); ++next) {
      advance(y, t, times[next]);
      t = times[next];
      at(next, y);
    }
    return;
  }
  if (method_ == RkMethod::dopri5) {
    sample_dense<Dopri5>(y, t0, times, next, at);
  } else {
    sample_dense<Dop853>(y, t0, times, next, at);
  }
}

template <class T>
void RungeKutta::sample_dense(State7& y, double t0, std::span<const double> times,
                              std::size_t next, const SampleSink& at) {
  // Times inside a step come from its interpolant; one at its end is the new state itself.
  const auto output = [&](double t_old, double t_new, const State7& y_old, const State7& y_new,
                          const Stages<T>& k) {
    if (next < times.size() && times[next] < t_new) {
      const DenseStep<T> step(rhs_, y_old, y_new, t_new - t_old, k, cost_);
      for (; next < times.size() && times[next] < t_new; ++next) {
        State7 s = step.at((times[next] - t_old) / (t_new - t_old));
        renormalise(s);
        at(next, s);
      }
    }
    for (; next < times.size() && times[next] == t_new; ++next) {
      State7 s = y_new;
      renormalise(s);
      at(next, s);
    }
  };
  advance_adaptive<T>(y, t0, times.back(), output);
}

template <class T, class Output>
void RungeKutta::advance_adaptive(State7& y, double t0, double t1, const Output& output) {
  const double span = t1 - t0, tol = tol_or_step_;
  // The error is multiplied by 1 / tol, not divided by tol: a division's latency, on the path
  // from a step's last stage to the next step's size, showed in the time of a whole run.
  const double inverse_tol = 1 / tol;
  constexpr double expo = 1.0 / (T::kErrorOrder + 1);
  if (h_ == 0.0) {
    // First trial step: a small fraction of the time the body needs to turn by one radian.
    const double rate = rhs_.model().omega_P(y.head<3>()).norm();
    h_ = std::min(span, 0.05 * std::pow(tol, expo) / std::max(rate, 1e-300) + 1e-300);
  }
  Stages<T> k;
  State7 y_new;
  // First same as last: f(y) from the previous accepted step, if y is still that step's end.
  bool k0_valid = T::kFsal && fsal_valid_ && y == fsal_y_;
  if (k0_valid) k[0] = fsal_k_;
  double t_now = t0;
  while (t_now < t1) {
    const bool last = t_now + h_ * (1 + kStepCountSlack) >= t1;  // no sliver of a last step
    // h rounded so that t_now + h is exact (Sterbenz's lemma, once t_now >= h): the motion then
    // advances by exactly the time's advance. Otherwise the roundings of t_now + h, each up to
    // half an ulp of t, add up over the run, and near a separatrix the motion magnifies the
    // drift (measured on P3, Verner 9(8) at tolerances 1e-12 to 1e-14: errors 0.5-2e-10 before,
    // 3-5e-11 after).
    const double h = last ? t1 - t_now : (t_now + h_) - t_now;
    if (!k0_valid) {  // f(y) once per accepted state, however many tries the step takes
      k[0] = rhs_(y);
      ++cost_.rhs_evals;
      k0_valid = true;
    }
    const double e = rk_step<T>(rhs_, y, h, k, y_new, inverse_scale_, cost_) * inverse_tol;
    const double factor = controller_.next_factor(e, h, expo, last);
    if (e <= 1.0) {
      const double t_new = last ? t1 : t_now + h;
      output(t_now, t_new, y, y_new, k);  // before y_new is renormalised: the stages saw it so
      y = y_new;
      const double q_factor = keep_near_unit(y);
      t_now = t_new;
      ++cost_.steps;
      // A step shortened to land on t1 says nothing about the next: keep the longer one.
      h_ = last ? std::max(h_, h * factor) : h * factor;
      if constexpr (T::kFsal) {
        k[0] = k[T::S - 1];  // f at the new y
        if (q_factor != 1.0) k[0].template tail<4>() *= q_factor;
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
  // The caller gets a unit quaternion (and a first-same-as-last stage to match it).
  const double q_factor = renormalise(y);
  if constexpr (T::kFsal) {
    fsal_valid_ = true;
    fsal_y_ = y;
    fsal_k_ = k[0];
    fsal_k_.tail<4>() *= q_factor;
  }
}

}  // namespace wobble
