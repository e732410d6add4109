#include "solvers/asymmetric_top_solver.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "core/exact_free_body.hpp"
#include "solvers/exact_answer.hpp"
#include "solvers/inertia_body.hpp"
#include "solvers/solve.hpp"
#include "symbolic/canonical_print.hpp"

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

GiNaC::matrix tensor_about_centre(const Asym& t) {
  const auto& e = t.body.exact;
  if (!t.body.has_mass) return sym::normalized(e.I_O);
  return sym::normalized(e.I_O.sub(sym::parallel_axis_term(e.mass, e.r_cm)));
}

Asym::Asym(const Problem& p, const sym::Values& values) : BodyContext(p, values) {
  Asym& t = *this;
  const GiNaC::matrix Ic = tensor_about_centre(t);
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = i + 1; j < 3; ++j) {
      if (!sym::is_identically_zero(Ic(i, j))) {
        throw InputError(fmt::format(
            "{}: body: the asymmetric-top solver needs the principal axes along x, y, z, but "
            "I_{}{} = {}",
            file(), "xyz"[i], "xyz"[j], sym::to_text(Ic(i, j), t.table)));
      }
    }
  }
  for (int k = 0; k < 3; ++k) {
    const auto uk = static_cast<unsigned>(k);
    I[uk] = Ic(uk, uk);
    I_n[k] = value(t, I[uk], fmt::format("I{}", k + 1));
    const std::string key = fmt::format("w{}", k + 1);
    w[uk] = t.table.parse(problem.motion->at(key), "motion." + key);
    w_n[k] = value(t, w[uk], "motion." + key);
  }
  require_rotating_body(file(), I_n, "the asymmetric_top solver");
  if (!(I_n[0] < I_n[1] && I_n[1] < I_n[2])) {
    const bool two_equal = I_n[0] == I_n[1] || I_n[1] == I_n[2];
    throw InputError(fmt::format(
        "{}: body: the asymmetric-top solver needs the moments about x, y, z in increasing "
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

Computed quantity(const Asym& t, const std::string& q) {
  const auto& I = t.I;
  const auto& w = t.w;
  if (q == "euler_coefficients" || q == "dw_dt0") {
    const std::vector<ex> c{sym::tidy((I[1] - I[2]) / I[0]), sym::tidy((I[2] - I[0]) / I[1]),
                            sym::tidy((I[0] - I[1]) / I[2])};
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
    if (q == "euler_coefficients") {
      Computed out{exact_vector(q, c, "", t.exact), steps};
      out.answer.notes.push_back(
          "dw1/dt = c1 w2 w3, dw2/dt = c2 w3 w1, dw3/dt = c3 w1 w2; c2 > 0 > c1, c3 for I1 < I2 "
          "< I3.");
      return out;
    }
    const std::vector<ex> d{sym::tidy(c[0] * w[1] * w[2]), sym::tidy(c[1] * w[2] * w[0]),
                            sym::tidy(c[2] * w[0] * w[1])};
    return {exact_vector(q, d, "rad/s^2", t.exact), steps};
  }
  for (int k = 0; k < 3; ++k) {
    const std::string suffix = fmt::format("_axis{}", k + 1);
    if (q != "Omega" + suffix && q != "rate" + suffix) continue;
    const AxisSpin a = axis_spin(t, k, t.spin);
    std::vector<Step> steps{{axis_steps_text(a), ""}};
    if (q == "Omega" + suffix) {
      Computed out{exact_vector(q, {a.Omega_i, a.Omega_j}, "rad/s", t.exact), steps};
      out.answer.notes.push_back(
          fmt::format("(Ω{}, Ω{}) for spin at s = |w(0)| about e{}.", a.i + 1, a.j + 1, a.k + 1));
      return out;
    }
    const ex rate = sym::simplified_sqrt(a.stable ? a.product : sym::tidy(-a.product));
    Computed out{exact_scalar(q, rate, a.stable ? "rad/s" : "1/s", t.exact), steps};
    const double Pn = value(t, a.product, "Omega_i Omega_j");
    check_routes_agree(out.answer.value.data[0], std::sqrt(std::abs(Pn)), out.answer.value.data[0],
                       8, q);
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
  const auto numeric = double_route(
      [&] { return ExactFreeMotion(t.I_n, t.I_n.cwiseProduct(t.w_n), Quat::Identity()); });
  if (q == "energy") {
    const ex T = sym::tidy(
        (I[0] * GiNaC::pow(w[0], 2) + I[1] * GiNaC::pow(w[1], 2) + I[2] * GiNaC::pow(w[2], 2)) / 2);
    Computed out{exact_scalar(q, T, "J", t.exact), {}};
    check_routes_agree(out.answer.value.data[0], 0.5 * t.I_n.dot(t.w_n.cwiseAbs2()),
                       out.answer.value.data[0], 8, q);
    out.steps.push_back(
        {"T = ½ (I1 w1² + I2 w2² + I3 w3²), conserved.",
         "T = \\tfrac12\\left(I_1\\omega_1^2 + I_2\\omega_2^2 + I_3\\omega_3^2\\right)",
         "Kinetic energy:"});
    return out;
  }
  if (q == "L_magnitude") {
    const ex L2 = sym::tidy(GiNaC::pow(I[0] * w[0], 2) + GiNaC::pow(I[1] * w[1], 2) +
                            GiNaC::pow(I[2] * w[2], 2));
    Computed out{exact_scalar(q, sym::simplified_sqrt(L2), "kg m^2/s", t.exact), {}};
    check_routes_agree(out.answer.value.data[0], t.I_n.cwiseProduct(t.w_n).norm(),
                       out.answer.value.data[0], 8, q);
    out.steps.push_back({"|L| = sqrt((I1 w1)² + (I2 w2)² + (I3 w3)²), conserved.",
                         "|L| = \\sqrt{(I_1\\omega_1)^2 + (I_2\\omega_2)^2 + (I_3\\omega_3)^2}",
                         "Angular momentum:"});
    return out;
  }
  if (q == "k" || q == "k2" || q == "kc2" || q == "period" || q == "flip_interval" ||
      q == "period_small_oscillation") {
    require_period(t, q);
    const Elliptic& e = elliptic(t);
    const bool elliptic_numeric = numeric && numeric->kind() == ExactFreeMotion::Kind::elliptic;
    if (q == "k") {
      Computed out{exact_scalar(q, GiNaC::sqrt(e.k2), "", t.exact), elliptic_steps(t)};
      if (elliptic_numeric) {
        // Compared as k^2 against 1 - k'^2: sqrt(1 - k'^2) of a k'^2 that rounds to 1 (a spin
        // about e1 or e3, k ~ 1e-12) has no digits left, k^2 all of them within 64 eps of 1.
        const double k = out.answer.value.data[0];
        check_routes_agree(k * k, 1.0 - numeric->kc2(), 1.0, 64, q);
      }
      out.answer.notes.push_back(
          "The modulus of Jacobi's functions sn(u, k), cn(u, k), dn(u, k); k² is k2 below.");
      return out;
    }
    if (q == "k2" || q == "kc2") {
      Computed out{exact_scalar(q, q == "k2" ? e.k2 : e.kc2, "", t.exact), elliptic_steps(t)};
      if (elliptic_numeric && q == "kc2")
        check_routes_agree(out.answer.value.data[0], numeric->kc2(), 1.0, 64, q);
      const double k2 = value(t, e.k2, "k2");
      out.answer.notes.push_back(
          q == "kc2" ? "k'² = 1 − k², from the invariants' factored forms: it keeps its digits "
                       "near the separatrix, where k → 1."
          : k2 > 0.5 ? "k near 1: w(0) is near the separatrix (a spin near e2)."
                     : "k small: w stays near the axis it circulates about (nearly the "
                       "small-oscillation motion).");
      return out;
    }
    if (q == "period" || q == "flip_interval") {
      const ex T = q == "period" ? e.period : e.period / 2;
      Computed out{exact_scalar(q, T, "s", t.exact), elliptic_steps(t)};
      if (elliptic_numeric) {
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
        check_routes_agree(out.answer.value.data[0], Tn, Tn, 256, q, moved);
      }
      if (q == "flip_interval") {
        out.steps.push_back(
            {"w2 ∝ sn(λ t) changes sign every half period: started near e2, w "
             "swings from near +e2 to near −e2 and back; the body flips over.",
             ""});
        const double near_e2 = std::abs(t.w_n[1]) / t.w_n.norm();
        out.answer.notes.push_back(
            near_e2 > 0.9 ? fmt::format("w(0) is {:.3g}° from e2: each half period the body "
                                        "turns over (the tennis-racket flip).",
                                        std::acos(near_e2) * 180 / M_PI)
                          : "w(0) is far from e2: w2 changes sign each half period, but this "
                            "is no flip of a spin about e2.");
      }
      return out;
    }
    // The small-oscillation estimate about the axis w circulates about, with the lecture's rate.
    const int k = t.regime == Regime::about_e3 ? 2 : 0;
    const AxisSpin a = axis_spin(t, k, w[static_cast<unsigned>(k)]);
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
  throw InputError(
      fmt::format("{}: unknown quantity '{}' for the asymmetric_top solver", t.file(), q));
}
}  // namespace

Key solve_asymmetric_top(const Problem& problem, const sym::Values& values) {
  const Asym t(problem, values);
  return assemble_parts(problem, [&](const std::string& q) { return quantity(t, q); });
}

}  // namespace wobble
