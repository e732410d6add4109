#include "solvers/asymmetric_top_solver.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "core/exact_free_body.hpp"
#include "solvers/body_requirements.hpp"
#include "solvers/exact_answer.hpp"
#include "solvers/inertia_body.hpp"
#include "solvers/quantity_table.hpp"
#include "solvers/solve.hpp"
#include "symbolic/canonical_print.hpp"
#include "symbolic/quantity.hpp"

namespace wobble {

namespace {
using GiNaC::ex;

// Which way w circulates: about e3 (L^2 > 2 T I2), about e1 (L^2 < 2 T I2), or neither (the
// separatrix L^2 = 2 T I2, which includes steady spin about e2).
enum class Regime { about_e3, about_e1, separatrix };

struct Elliptic {
  ex k2, kc2, lambda, period;
};

struct Asym : BodyContext {
  Asym(const Problem& problem, const sym::Values& values);
  std::array<ex, 3> I, w;  // exact
  Vec3 I_n, w_n;           // at the values, in double
  ex A1, A3, D;            // 2 T I3 - L^2, L^2 - 2 T I1, L^2 - 2 T I2, factored
  Regime regime = Regime::separatrix;
  ex spin;  // s = |w(0)|
  mutable std::optional<Elliptic> elliptic_cache;
  std::string file() const { return problem.file.string(); }
};

double value(const Asym& t, const ex& e, const std::string& field) {
  return sym::evaluate(e, t.exact.at, field);
}

const std::string kWho = "the asymmetric_top solver";

Asym::Asym(const Problem& p, const sym::Values& values) : BodyContext(p, values) {
  Asym& t = *this;
  const GiNaC::matrix Ic = tensor_about_centre(t);
  require_principal_axes_along_xyz(t, Ic, kWho, "about the centre of mass");
  for (int k = 0; k < 3; ++k) {
    const auto uk = static_cast<unsigned>(k);
    I[uk] = Ic(uk, uk);
    I_n[k] = value(t, I[uk], fmt::format("I{}", k + 1));
    const std::string key = fmt::format("w{}", k + 1);
    w[uk] = sym::parse_quantity(t.table, problem.motion->at(key), "motion." + key, "rad/s");
    w_n[k] = value(t, w[uk], "motion." + key);
  }
  require_rotating_body(file(), I_n, kWho);
  if (!(I_n[0] < I_n[1] && I_n[1] < I_n[2])) {
    const bool two_equal = I_n[0] == I_n[1] || I_n[1] == I_n[2];
    throw InputError(fmt::format(
        "{}: body: the asymmetric_top solver needs the moments about x, y, z in increasing "
        "order, I_xx < I_yy < I_zz; at these values I_xx = {:.6g}, I_yy = {:.6g}, I_zz = {:.6g} "
        "kg m^2 ({})",
        file(), I_n[0], I_n[1], I_n[2],
        two_equal ? "two are equal: a symmetric top, for the torque_free_symmetric solver"
                  : "relabel the axes so that the moments increase"));
  }
  if (w_n.norm() == 0.0) throw InputError("motion: w(0) = (w1, w2, w3) is zero: no motion");
  const auto sq = [](const ex& x) { return GiNaC::pow(x, 2); };
  // Sums of positive terms (the differences tidied, the sums left as they are): exact, readable
  // and free of cancellation when evaluated.
  const ex d21 = sym::tidy(I[1] - I[0]), d32 = sym::tidy(I[2] - I[1]), d31 = sym::tidy(I[2] - I[0]);
  A1 = I[0] * d31 * sq(w[0]) + I[1] * d32 * sq(w[1]);
  A3 = I[1] * d21 * sq(w[1]) + I[2] * d31 * sq(w[2]);
  D = sym::tidy(I[2] * d32 * sq(w[2]) - I[0] * d21 * sq(w[0]));  // a difference: factored
  spin = sym::simplified_sqrt(sym::tidy(sq(w[0]) + sq(w[1]) + sq(w[2])));
  if (sym::is_identically_zero(D.subs(t.exact.at))) {
    regime = Regime::separatrix;
  } else {
    regime = sym::sign_of(D, t.exact.at, "L^2 - 2 T I2") > 0 ? Regime::about_e3 : Regime::about_e1;
  }
}

// For spin s about e_k: (i, j) cyclic after k, Omega_i = s (I_k - I_j)/I_i, Omega_j likewise.
struct AxisSpin {
  int i, j, k;
  ex Omega_i, Omega_j, product;
  bool stable;
};
AxisSpin axis_spin(const Asym& t, int k, const ex& s) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  const auto& I = t.I;
  const auto u = [](int n) { return static_cast<unsigned>(n); };
  const ex Oi = sym::tidy(s * (I[u(k)] - I[u(j)]) / I[u(i)]);
  const ex Oj = sym::tidy(s * (I[u(k)] - I[u(i)]) / I[u(j)]);
  const ex product = sym::tidy(Oi * Oj);
  // Stable exactly when e_k is the smallest or the largest axis (the ordering is checked).
  return {i, j, k, Oi, Oj, product, k != 1};
}

std::string axis_steps_text(const AxisSpin& a) {
  return fmt::format(
      "Spin s = |w(0)| about e{k}: w{k} ≈ s, and to first order in w{i}, w{j}: dw{i}/dt = −Ω{i} "
      "w{j}, dw{j}/dt = Ω{j} w{i} with Ω{i} = s (I{k} − I{j})/I{i}, Ω{j} = s (I{k} − I{i})/I{j}; "
      "so d²w{i}/dt² = −Ω{i} Ω{j} w{i}.",
      fmt::arg("i", a.i + 1), fmt::arg("j", a.j + 1), fmt::arg("k", a.k + 1));
}

const Elliptic& elliptic(const Asym& t) {
  if (t.elliptic_cache) return *t.elliptic_cache;  // factoring these is the solver's main cost
  const auto& I = t.I;
  const ex prod = I[0] * I[1] * I[2];
  Elliptic e;
  // Products of factored pieces: GiNaC cancels common factors of a product by itself, so no
  // factoring of the whole (the solver's main cost) is needed.
  const ex d21 = sym::tidy(I[1] - I[0]), d32 = sym::tidy(I[2] - I[1]), d31 = sym::tidy(I[2] - I[0]);
  if (t.regime == Regime::about_e3) {
    e.k2 = d21 * t.A1 / (d32 * t.A3);
    e.kc2 = d31 * t.D / (d32 * t.A3);
    e.lambda = sym::simplified_sqrt(d32 * t.A3 / prod);
  } else {
    e.k2 = d32 * t.A3 / (d21 * t.A1);
    e.kc2 = -d31 * t.D / (d21 * t.A1);
    e.lambda = sym::simplified_sqrt(d21 * t.A1 / prod);
  }
  e.period = 4 * GiNaC::EllipticK(GiNaC::sqrt(e.k2)) / e.lambda;
  return *(t.elliptic_cache = e);
}

void require_period(const Asym& t, const std::string& q) {
  if (t.regime != Regime::separatrix) return;
  throw InputError(fmt::format(
      "{}: {}: w(0) lies on the separatrix L^2 = 2 T I2 (e.g. a spin exactly about e2): w(t) "
      "has no period, it reaches the intermediate axis only as t -> infinity",
      t.file(), q));
}

std::vector<Step> elliptic_steps(const Asym& t) {
  const bool e3 = t.regime == Regime::about_e3;
  return {
      {"Energy and |L| are conserved: 2T = Σ I_i w_i², L² = Σ I_i² w_i². With them Euler's "
       "equations reduce to Jacobi's elliptic functions (Landau & Lifshitz §37).",
       "2T = \\sum_i I_i\\,\\omega_i^2,\\quad L^2 = \\sum_i I_i^2\\,\\omega_i^2", "Conserved:"},
      {std::string("L² − 2 T I2 = ") + sym::to_text(t.D, t.table) +
           (e3 ? " > 0: w circulates about e3 (w3 keeps its sign)."
               : " < 0: w circulates about e1 (w1 keeps its sign)."),
       "L^2 - 2TI_2 = " + sym::to_latex(t.D, t.table), "The regime:"},
      e3 ? Step{"k² = (I2 − I1)(2TI3 − L²) / ((I3 − I2)(L² − 2TI1)), λ² = (I3 − I2)(L² − "
                "2TI1)/(I1 I2 I3), with 2TI3 − L² = I1(I3 − I1)w1² + I2(I3 − I2)w2² and L² − 2TI1 "
                "= I2(I2 − I1)w2² + I3(I3 − I1)w3² (no cancellation).",
                "k^2 = \\frac{(I_2 - I_1)(2TI_3 - L^2)}{(I_3 - I_2)(L^2 - 2TI_1)},\\quad "
                "\\lambda^2 = \\frac{(I_3 - I_2)(L^2 - 2TI_1)}{I_1 I_2 I_3}",
                "Modulus and rate:"}
         : Step{"k² = (I3 − I2)(L² − 2TI1) / ((I2 − I1)(2TI3 − L²)), λ² = (I2 − I1)(2TI3 − "
                "L²)/(I1 I2 I3), with 2TI3 − L² = I1(I3 − I1)w1² + I2(I3 − I2)w2² and L² − 2TI1 "
                "= I2(I2 − I1)w2² + I3(I3 − I1)w3² (no cancellation).",
                "k^2 = \\frac{(I_3 - I_2)(L^2 - 2TI_1)}{(I_2 - I_1)(2TI_3 - L^2)},\\quad "
                "\\lambda^2 = \\frac{(I_2 - I_1)(2TI_3 - L^2)}{I_1 I_2 I_3}",
                "Modulus and rate:"},
      {"w2 ∝ sn(λ t, k): the period of w(t) is 4 K(k) / λ, K the complete elliptic integral of "
       "the first kind.",
       "T_\\omega = \\frac{4K(k)}{\\lambda}", "The period:"},
  };
}

// A sum of three products of rounded inputs, or the square root of one: a few roundings.
constexpr double kShortRouteUlps = 8;
// The period's double route: the AGM for K and the invariants' products, a few hundred
// operations' rounding at most (the input's amplification near the separatrix is added apart).
constexpr double kPeriodRouteUlps = 256;

std::vector<ex> euler_c(const Asym& t) {
  const auto& I = t.I;
  return {sym::tidy((I[1] - I[2]) / I[0]), sym::tidy((I[2] - I[0]) / I[1]),
          sym::tidy((I[0] - I[1]) / I[2])};
}

std::vector<Step> euler_steps(const Asym& t, const std::vector<ex>& c) {
  std::vector<Step> steps{
      {"Torque-free Euler equations in the principal frame: I1 dw1/dt = (I2 − I3) w2 w3, "
       "I2 dw2/dt = (I3 − I1) w3 w1, I3 dw3/dt = (I1 − I2) w1 w2.",
       "I_1\\dot\\omega_1 = (I_2 - I_3)\\,\\omega_2\\omega_3,\\ I_2\\dot\\omega_2 = (I_3 - "
       "I_1)\\,\\omega_3\\omega_1,\\ I_3\\dot\\omega_3 = (I_1 - I_2)\\,\\omega_1\\omega_2",
       "Euler's equations:"}};
  std::vector<std::string> text;
  for (int k = 0; k < 3; ++k) {
    text.push_back(fmt::format("dw{}/dt = {:.6g} w{} w{}", k + 1,
                               value(t, c[static_cast<std::size_t>(k)], "c"), (k + 1) % 3 + 1,
                               (k + 2) % 3 + 1));
  }
  steps.push_back({"For these moments: " + text[0] + ", " + text[1] + ", " + text[2] + ".", ""});
  return steps;
}

Computed euler_coefficients(const Asym& t, const std::string& q) {
  const std::vector<ex> c = euler_c(t);
  Computed out{exact_vector(q, c, "", t.exact), euler_steps(t, c)};
  out.answer.named_entries = kEulerCoefficients;
  out.answer.notes.push_back(
      "dw1/dt = c1 w2 w3, dw2/dt = c2 w3 w1, dw3/dt = c3 w1 w2; c2 > 0 > c1, c3 for I1 < I2 "
      "< I3.");
  return out;
}

Computed dw_dt0(const Asym& t, const std::string& q) {
  const std::vector<ex> c = euler_c(t);
  const auto& w = t.w;
  const std::vector<ex> d{sym::tidy(c[0] * w[1] * w[2]), sym::tidy(c[1] * w[2] * w[0]),
                          sym::tidy(c[2] * w[0] * w[1])};
  Computed out{exact_vector(q, d, "rad/s^2", t.exact), euler_steps(t, c)};
  // As the question writes it, dω/dt (ω̇), and so a student: "dω/dt = ..", "ω̇(0) = ..".
  out.answer.step_names = {"dw/dt", "domega/dt", "wdot", "omegadot", "wdot0", "omegadot0"};
  return out;
}

// "Omega_axis2" -> 1: the axis a spin quantity is about.
int axis_of(const std::string& q) { return q.back() - '1'; }

Computed omega_pair(const Asym& t, const std::string& q) {
  const AxisSpin a = axis_spin(t, axis_of(q), t.spin);
  Computed out{exact_vector(q, {a.Omega_i, a.Omega_j}, "rad/s", t.exact),
               {{axis_steps_text(a), ""}}};
  constexpr std::array<const char*, 3> kOmega{"Ω₁", "Ω₂", "Ω₃"};
  out.answer.named_entries = {kOmega[static_cast<std::size_t>(a.i)],
                              kOmega[static_cast<std::size_t>(a.j)]};
  out.answer.notes.push_back(
      fmt::format("(Ω{}, Ω{}) for spin at s = |w(0)| about e{}.", a.i + 1, a.j + 1, a.k + 1));
  return out;
}

Computed spin_rate(const Asym& t, const std::string& q) {
  const AxisSpin a = axis_spin(t, axis_of(q), t.spin);
  const ex rate = sym::simplified_sqrt(a.stable ? a.product : sym::tidy(-a.product));
  Computed out{exact_scalar(q, rate, a.stable ? "rad/s" : "1/s", t.exact),
               {{axis_steps_text(a), ""}}};
  constexpr std::array<const char*, 3> kOmega{"Ω₁", "Ω₂", "Ω₃"}, kAxis{"e₁", "e₂", "e₃"};
  out.answer.stability = Answer::Stability{
      a.stable,
      fmt::format("the spin about {} is {} ({} {} {} 0)", kAxis[static_cast<std::size_t>(a.k)],
                  a.stable ? "stable" : "unstable", kOmega[static_cast<std::size_t>(a.i)],
                  kOmega[static_cast<std::size_t>(a.j)], a.stable ? ">" : "<")};
  const double Pn = value(t, a.product, "Omega_i Omega_j");
  check_routes_agree(out.answer.value.data[0], std::sqrt(std::abs(Pn)), out.answer.value.data[0],
                     kShortRouteUlps, q);
  out.answer.notes.push_back(
      a.stable ? fmt::format("Stable (Ω{} Ω{} > 0; e{} is the {} axis): small oscillations of "
                             "w{}, w{} at this angular frequency.",
                             a.i + 1, a.j + 1, a.k + 1, a.k == 0 ? "smallest" : "largest",
                             a.i + 1, a.j + 1)
               : fmt::format("Unstable (Ω{} Ω{} < 0; e2 is the intermediate axis): w{}, w{} "
                             "grow as exp(rate t): the tennis-racket flip.",
                             a.i + 1, a.j + 1, a.i + 1, a.j + 1));
  out.steps.push_back({a.stable ? "Ω_i Ω_j > 0: w_i, w_j oscillate at sqrt(Ω_i Ω_j)."
                                : "Ω_i Ω_j < 0: w_i, w_j grow as exp(sqrt(−Ω_i Ω_j) t).",
                       ""});
  return out;
}

Computed energy(const Asym& t, const std::string& q) {
  const auto& I = t.I;
  const auto& w = t.w;
  const ex T = sym::tidy(
      (I[0] * GiNaC::pow(w[0], 2) + I[1] * GiNaC::pow(w[1], 2) + I[2] * GiNaC::pow(w[2], 2)) / 2);
  Computed out{exact_scalar(q, T, "J", t.exact), {}};
  out.answer.step_names = {"T"};  // "2TI3 − L²", as the steps write it
  check_routes_agree(out.answer.value.data[0], 0.5 * t.I_n.dot(t.w_n.cwiseAbs2()),
                     out.answer.value.data[0], kShortRouteUlps, q);
  out.steps.push_back(
      {"T = ½ (I1 w1² + I2 w2² + I3 w3²), conserved.",
       "T = \\tfrac12\\left(I_1\\omega_1^2 + I_2\\omega_2^2 + I_3\\omega_3^2\\right)",
       "Kinetic energy:"});
  return out;
}

Computed L_magnitude(const Asym& t, const std::string& q) {
  const auto& I = t.I;
  const auto& w = t.w;
  const ex L2 = sym::tidy(GiNaC::pow(I[0] * w[0], 2) + GiNaC::pow(I[1] * w[1], 2) +
                          GiNaC::pow(I[2] * w[2], 2));
  Computed out{exact_scalar(q, sym::simplified_sqrt(L2), "kg m^2/s", t.exact), {}};
  out.answer.step_names = {"L"};
  check_routes_agree(out.answer.value.data[0], t.I_n.cwiseProduct(t.w_n).norm(),
                     out.answer.value.data[0], kShortRouteUlps, q);
  out.steps.push_back({"|L| = sqrt((I1 w1)² + (I2 w2)² + (I3 w3)²), conserved.",
                       "|L| = \\sqrt{(I_1\\omega_1)^2 + (I_2\\omega_2)^2 + (I_3\\omega_3)^2}",
                       "Angular momentum:"});
  return out;
}

// core's closed form of the motion, the independent route of the elliptic quantities; nothing
// when its doubles left the range, or when the motion is not elliptic (a spin about one axis).
std::optional<ExactFreeMotion> elliptic_route(const Asym& t) {
  auto numeric = double_route(
      [&] { return ExactFreeMotion(t.I_n, t.I_n.cwiseProduct(t.w_n), Quat::Identity()); });
  if (numeric && numeric->kind() != ExactFreeMotion::Kind::elliptic) numeric.reset();
  return numeric;
}

Computed modulus(const Asym& t, const std::string& q) {
  require_period(t, q);
  const Elliptic& e = elliptic(t);
  Computed out{exact_scalar(q, GiNaC::sqrt(e.k2), "", t.exact), elliptic_steps(t)};
  if (const auto numeric = elliptic_route(t)) {
    // Compared as k^2 against 1 - k'^2: sqrt(1 - k'^2) of a k'^2 that rounds to 1 (a spin
    // about e1 or e3, k ~ 1e-12) has no digits left, k^2 all of them within kRouteUlps of 1.
    const double k = out.answer.value.data[0];
    check_routes_agree(k * k, 1.0 - numeric->kc2(), 1.0, kRouteUlps, q);
  }
  out.answer.notes.push_back(
      "The modulus of Jacobi's functions sn(u, k), cn(u, k), dn(u, k); k² is k2 below.");
  return out;
}

Computed modulus_squared(const Asym& t, const std::string& q) {
  require_period(t, q);
  const Elliptic& e = elliptic(t);
  Computed out{exact_scalar(q, q == "k2" ? e.k2 : e.kc2, "", t.exact), elliptic_steps(t)};
  if (q == "kc2") out.answer.step_names = {"k'^2"};  // as its note writes it, k'² = 1 − k²
  if (const auto numeric = elliptic_route(t); numeric && q == "kc2")
    check_routes_agree(out.answer.value.data[0], numeric->kc2(), 1.0, kRouteUlps, q);
  // k^2 > 1/2: the turning points of w are nearer the separatrix than the axis.
  const double k2 = value(t, e.k2, "k2");
  out.answer.notes.push_back(
      q == "kc2" ? "k'² = 1 − k², from the invariants' factored forms: it keeps its digits "
                   "near the separatrix, where k → 1."
      : k2 > 0.5 ? "k near 1: w(0) is near the separatrix (a spin near e2)."
                 : "k small: w stays near the axis it circulates about (nearly the "
                   "small-oscillation motion).");
  return out;
}

Computed period(const Asym& t, const std::string& q) {
  require_period(t, q);
  const Elliptic& e = elliptic(t);
  const ex T = q == "period" ? e.period : e.period / 2;
  Computed out{exact_scalar(q, T, "s", t.exact), elliptic_steps(t)};
  if (const auto numeric = elliptic_route(t)) {
    const double part = q == "period" ? 1 : 2;
    const double Tn = numeric->period_s() / part;
    // Near the separatrix the period is ill-conditioned in the moments (k'^2 is a small
    // difference of them): the double route inherits their rounding, amplified.
    const double moved = rounding_sensitivity(
        [&](const std::vector<double>& x) {
          const Vec3 I_x{x[0], x[1], x[2]}, w_x{x[3], x[4], x[5]};
          return ExactFreeMotion(I_x, I_x.cwiseProduct(w_x), Quat::Identity()).period_s() / part;
        },
        {t.I_n[0], t.I_n[1], t.I_n[2], t.w_n[0], t.w_n[1], t.w_n[2]});
    check_routes_agree(out.answer.value.data[0], Tn, Tn, kPeriodRouteUlps, q, moved);
  }
  if (q == "flip_interval") {
    out.steps.push_back(
        {"w2 ∝ sn(λ t) changes sign every half period: started near e2, w "
         "swings from near +e2 to near −e2 and back; the body flips over.",
         ""});
    // cos 25.8°: within that cone about e2 the half-period turn is a flip of the racket.
    constexpr double kFlipCone = 0.9;
    const double near_e2 = std::abs(t.w_n[1]) / t.w_n.norm();
    out.answer.notes.push_back(
        near_e2 > kFlipCone ? fmt::format("w(0) is {:.3g}° from e2: each half period the body "
                                          "turns over (the tennis-racket flip).",
                                          std::acos(near_e2) * 180 / M_PI)
                            : "w(0) is far from e2: w2 changes sign each half period, but this "
                              "is no flip of a spin about e2.");
  }
  return out;
}

// The small-oscillation estimate about the axis w circulates about, with the lecture's rate.
Computed period_small_oscillation(const Asym& t, const std::string& q) {
  require_period(t, q);
  const Elliptic& e = elliptic(t);
  const int k = t.regime == Regime::about_e3 ? 2 : 0;
  const AxisSpin a = axis_spin(t, k, t.w[static_cast<unsigned>(k)]);
  const ex estimate = 2 * GiNaC::Pi / sym::simplified_sqrt(a.product);
  Computed out{exact_scalar(q, estimate, "s", t.exact), {{axis_steps_text(a), ""}}};
  out.steps.front().text = fmt::format(
      "Small oscillations about e{k} with s = w{k}(0) (the lecture's Ω1, Ω2 for k = 3): "
      "T ≈ 2π / sqrt(Ω_i Ω_j).",
      fmt::arg("k", k + 1));
  const double exact_T = value(t, e.period, "period");
  out.answer.notes.push_back(fmt::format(
      "The exact period is {}: the estimate is off by {:.3g}% (it is exact as w(0) → e{}).",
      format_number(exact_T), 100 * (out.answer.value.data[0] - exact_T) / exact_T, k + 1));
  return out;
}

using K = AnswerKind;
using F = AnswerFrame;
constexpr SignConvention kNoSign = SignConvention::none;

std::vector<QuantityRow<const Asym>> make_rows() {
  std::vector<QuantityRow<const Asym>> r{
      {{"euler_coefficients", "", K::vector, F::none, kNoSign,
        "c in dw1/dt = c1 w2 w3, ...: ((I2-I3)/I1, (I3-I1)/I2, (I1-I2)/I3)"},
       euler_coefficients},
      {{"dw_dt0", "rad/s^2", K::vector, F::body, kNoSign, "dw/dt at t = 0"}, dw_dt0},
  };
  for (int k = 1; k <= 3; ++k) {
    r.push_back({{fmt::format("Omega_axis{}", k), "rad/s", K::vector, F::none, kNoSign,
                  fmt::format("(Omega_i, Omega_j) of the lecture for spin s = |w(0)| about e{}", k)},
                 omega_pair});
    r.push_back({{fmt::format("rate_axis{}", k), "rad/s or 1/s", K::rate, F::none, kNoSign,
                  fmt::format("sqrt|Omega_i Omega_j| about e{}: oscillation frequency (stable) or "
                              "growth rate (unstable)",
                              k)},
                 spin_rate});
  }
  std::vector<QuantityRow<const Asym>> rest{
      {{"energy", "J", K::scalar, F::none, kNoSign, "the kinetic energy T"}, energy},
      {{"L_magnitude", "kg m^2/s", K::scalar, F::none, kNoSign, "|L|"}, L_magnitude},
      {{"k", "", K::scalar, F::none, kNoSign, "the modulus of the exact solution"}, modulus},
      {{"k2", "", K::scalar, F::none, kNoSign, "k^2"}, modulus_squared},
      {{"kc2", "", K::scalar, F::none, kNoSign, "k'^2 = 1 - k^2, without cancellation"},
       modulus_squared},
      {{"period", "s", K::scalar, F::none, kNoSign, "the period of w(t), 4 K(k) / lambda"},
       period},
      {{"flip_interval", "s", K::scalar, F::none, kNoSign,
        "half the period: w2 changes sign (the flip near e2)"},
       period},
      {{"period_small_oscillation", "s", K::scalar, F::none, kNoSign,
        "2 pi / rate about the axis w circulates about (the estimate)"},
       period_small_oscillation},
  };
  r.insert(r.end(), rest.begin(), rest.end());
  return r;
}

const std::vector<QuantityRow<const Asym>>& rows() {
  static const std::vector<QuantityRow<const Asym>> r = make_rows();
  return r;
}
}  // namespace

Key solve_asymmetric_top(const Problem& problem, const sym::Values& values) {
  const Asym t(problem, values);
  Key key =
      assemble_parts(problem, [&](const std::string& q) { return compute_quantity(rows(), t, q); });
  // The steps write the principal moments I1, I2, I3 and the rate λ of sn's argument (the period
  // is 4 K(k) / λ); so may a student. λ only where a part needed the elliptic solution (its
  // factoring is the solver's main cost).
  const std::array<const char*, 3> axis{"e₁", "e₂", "e₃"};
  for (std::size_t k = 0; k < 3; ++k) {
    key.defined_names.push_back({fmt::format("I{}", k + 1), sym::to_text(t.I[k], t.table),
                                 fmt::format("the principal moment about {}", axis[k])});
  }
  if (t.elliptic_cache) {
    key.defined_names.push_back({"lambda", sym::to_text(t.elliptic_cache->lambda, t.table),
                                 "the rate of sn's argument, sn(λt, k)"});
  }
  return key;
}

SolverInfo asymmetric_top_solver() {
  SolverInfo s;
  s.name = "asymmetric_top";
  s.summary = "a body with I1 < I2 < I3 along x, y, z, spun at w(0), no torque: Euler's "
              "equations, stability, the exact elliptic period";
  s.motion_keys = {"w1", "w2", "w3"};
  s.quantities = quantity_infos(rows());
  s.solve = solve_asymmetric_top;
  return s;
}

}  // namespace wobble
