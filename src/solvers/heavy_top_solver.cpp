#include "solvers/heavy_top_solver.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "core/heavy_top.hpp"
#include "problem/values.hpp"
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

struct Top : BodyContext {
  Top(const Problem& problem, const sym::Values& values);
  ex M, l, g, I1, I3, theta, thetadot, phidot, psidot;  // exact
  ex w3, p_psi, p_phi, energy_prime;                    // exact
  HeavyTop numeric{};
  HeavyTopStart start{};
  HeavyTopConstants constants{};
  std::vector<std::string> written_in;  // "θ̇0 = 0", "θ0 = 90°": written into the exact forms
  std::vector<std::string> held;        // the parameters a nonzero one written in depends on
  std::string file() const { return problem.file.string(); }
};

double value(const Top& t, const ex& e, const std::string& field) {
  return sym::evaluate(e, t.exact.at, field);
}

// g in m/s^2, theta0 in rad, the rates in rad/s; each may carry a unit of its own.
ex motion(Top& t, const std::string& key) {
  const std::string unit = key == "g" ? "m/s^2" : key == "theta0" ? "rad" : "rad/s";
  return sym::parse_quantity(t.table, t.problem.motion->at(key), "motion." + key, unit);
}

Top::Top(const Problem& p, const sym::Values& values) : BodyContext(p, values) {
  Top& t = *this;
  const std::string who = "the heavy_top solver";
  require_mass(t, who);
  const auto& b = t.body.exact;
  require_centre_on_z(t, who);  // first: an off-axis centre also makes products of inertia
  require_symmetric_about_z(t, b.I_O, who, "about the pivot");
  M = b.mass;
  l = sym::tidy(b.r_cm[2]);
  I1 = sym::tidy(b.I_O(0, 0));
  I3 = sym::tidy(b.I_O(2, 2));
  g = motion(t, "g");
  theta = motion(t, "theta0");
  thetadot = motion(t, "thetadot0");
  phidot = motion(t, "phidot0");
  psidot = motion(t, "psidot0");
  numeric = {value(t, M, "mass"), value(t, l, "l"), value(t, g, "motion.g"), value(t, I1, "I1"),
             value(t, I3, "I3")};
  require_rotating_body(file(), Vec3(numeric.I1_kgm2, numeric.I1_kgm2, numeric.I3_kgm2),
                        "the heavy_top solver");
  if (!(numeric.l_m > 0.0)) {
    throw InputError(
        fmt::format("{}: body: the centre of mass is at z = {:.6g} m; it must be "
                    "above the pivot (z > 0)",
                    file(), numeric.l_m));
  }
  if (!(numeric.g_m_s2 > 0.0)) {
    throw InputError(fmt::format("motion.g: \"{}\" is {:.6g}; it must be > 0",
                                 problem.motion->at("g"), numeric.g_m_s2));
  }
  start = {value(t, theta, "motion.theta0"), value(t, thetadot, "motion.thetadot0"),
           value(t, phidot, "motion.phidot0"), value(t, psidot, "motion.psidot0")};
  // A rate that is zero at these values is written as 0: the key of a top released without
  // nodding or precession reads p_phi = I3 psidot0 cos(theta0), not a page of zero terms.
  for (auto [rate, name] : {std::pair<ex*, const char*>{&thetadot, "θ̇0"}, {&phidot, "φ̇0"}}) {
    if (sym::is_identically_zero(rate->subs(t.exact.at))) {
      *rate = 0;
      written_in.push_back(std::string(name) + " = 0");
    }
  }
  // A horizontal axle likewise: its key reads phidot_slow = 2 g l/(R² psidot0), the gyroscope's
  // precession, not a form in cos(theta0) that is 0 (and the fast root is gone).
  if (sym::is_identically_zero(ex(GiNaC::cos(theta)).subs(t.exact.at))) {
    for (const auto& name : t.table.names()) {
      if (theta.has(t.table.at(name))) held.push_back(name);  // the judge holds them there
    }
    theta = GiNaC::Pi / 2;
    written_in.push_back("θ0 = 90°");
  }
  if (!(start.theta >= 0.0 && start.theta <= M_PI)) {
    const std::string& typed = problem.motion->at("theta0");
    throw InputError(fmt::format(
        "motion.theta0: {:.10g} rad must lie in [0, pi]{}", start.theta,
        degrees_meant_hint(typed, start.theta <= 180.0, "theta0 = \"" + typed + "deg\"")));
  }
  constants = heavy_top_constants(numeric, start);
  const ex s = GiNaC::sin(theta), c = GiNaC::cos(theta);
  w3 = phidot * c + psidot;
  // No spin about the axle (w3 = 0: p_psi = 0) is a pendulum, not a top: phidot = p_phi /
  // (I1 sin^2) vanishes at no u_p = p_phi / p_psi, which part (b) asks for (the exact form
  // p_phi / p_psi would cancel the zero factor and read cos(theta0): "loops" for a pendulum).
  if (sym::is_identically_zero(w3.subs(t.exact.at))) {
    throw InputError(fmt::format(
        "motion.psidot0: \"{}\" is {:.10g} rad/s with phidot0 = {:.10g} rad/s: the spin about the "
        "axle, psidot0 + phidot0 cos(theta0), is 0 at these values, so p_psi = 0 and phidot "
        "vanishes at no u_p = p_phi/p_psi (a pendulum, not a top); give the axle a spin, or "
        "simulate the scene heavy-top",
        problem.motion->at("psidot0"), start.psidot, start.phidot));
  }
  p_psi = I3 * w3;
  p_phi = I1 * phidot * GiNaC::pow(s, 2) + p_psi * c;
  energy_prime = I1 / 2 * (GiNaC::pow(thetadot, 2) + GiNaC::pow(phidot * s, 2)) + M * g * l * c;
}

Step lagrangian_step() {
  return {
      "L = I1/2 (φ̇² sin²θ + θ̇²) + I3/2 (φ̇ cos θ + ψ̇)² − M g l cos θ (ω in the primed basis: "
      "(−φ̇ sin θ, θ̇, φ̇ cos θ + ψ̇)).",
      "\\mathcal{L} = \\tfrac{I_1}{2}\\left(\\dot\\phi^2\\sin^2\\theta + \\dot\\theta^2\\right) "
      "+ \\tfrac{I_3}{2}\\left(\\dot\\phi\\cos\\theta + \\dot\\psi\\right)^2 - Mgl\\cos\\theta",
      "The Lagrangian:"};
}
Step momenta_step() {
  return {
      "φ and ψ are ignorable: p_ψ = ∂L/∂ψ̇ = I3 ω3, p_φ = ∂L/∂φ̇ = I1 φ̇ sin²θ + p_ψ cos θ, "
      "both conserved, and so is E = T + M g l cos θ.",
      "p_\\psi = I_3\\,\\omega_3,\\quad p_\\phi = I_1\\dot\\phi\\sin^2\\theta + "
      "p_\\psi\\cos\\theta",
      "Conserved momenta:"};
}
Step potential_step() {
  return {
      "With φ̇ = (p_φ − p_ψ cos θ)/(I1 sin²θ): E' = E − p_ψ²/(2 I3) = I1 θ̇²/2 + V(θ), "
      "V(θ) = (p_φ − p_ψ cos θ)²/(2 I1 sin²θ) + M g l cos θ; θ turns where V(θ) = E'.",
      "V(\\theta) = \\frac{(p_\\phi - p_\\psi\\cos\\theta)^2}{2I_1\\sin^2\\theta} + "
      "Mgl\\cos\\theta = E'",
      "The effective potential:"};
}
Step cubic_step() {
  return {
      "In u = cos θ: u̇² = f(u) = (1 − u²)(α − β u) − (b − a u)², a = p_ψ/I1, b = p_φ/I1, "
      "α = 2E'/I1, β = 2Mgl/I1; f(±1) ≤ 0 ≤ f(cos θ0), so one root on each side of the start.",
      "\\dot u^2 = f(u) = (1 - u^2)(\\alpha - \\beta u) - (b - a u)^2", "The turning points:"};
}

// The nutation limits: exactly when the start is a turning point (thetadot0 = 0), where the
// cubic in d = u - u0 loses its constant term and the other limit solves a quadratic.
Computed nutation_limit(const Top& t, bool upper) {
  const std::string q = upper ? "theta_max" : "theta_min";
  const Nutation n = nutation_limits(t.numeric, t.start);
  const double want = upper ? n.theta_max : n.theta_min;
  std::vector<Step> steps{potential_step(), cubic_step()};
  if (!sym::is_identically_zero(t.thetadot.subs(t.exact.at))) {
    Answer a;
    a.name = q;
    a.value = Value::scalar(want);
    a.latex = format_number(want);
    a.unit = "rad";
    a.notes.push_back(
        "Numeric: a root of the cubic f(cos θ) = 0 (TOMS 748 in its bracket); θ̇0 ≠ 0, so the "
        "start is not a turning point and no closed form is printed.");
    return {a, steps};
  }
  const ex u0 = GiNaC::cos(t.theta), s2 = GiNaC::pow(GiNaC::sin(t.theta), 2);
  const ex a = t.p_psi / t.I1, beta = 2 * t.M * t.g * t.l / t.I1;
  const ex P = GiNaC::pow(t.phidot, 2) * s2;
  const ex c1 = sym::tidy(-beta * s2 - 2 * u0 * P + 2 * a * t.phidot * s2);
  const ex c2 = sym::tidy(2 * u0 * beta - P - a * a);
  const ex root = sym::simplified_sqrt(sym::simplify(c2 * c2 - 4 * beta * c1));
  // The other limit: the root of beta d^2 + c2 d + c1 with u0 + d in [-1, 1] (the third root of
  // the cubic is beyond u = 1); which one that is, is decided at the values. Written without
  // cancellation (q = -(c2 + sign(c2) root)/2, the roots q/beta and c1/q): (-c2 +- root)/(2 beta)
  // subtracts nearly equal numbers when beta is small (g = 1e-150 lost all 40 digits), and
  // c1/q stays finite as g -> 0.
  const int c2_sign = sym::is_identically_zero(c2.subs(t.exact.at))
                          ? 1
                          : sym::sign_of(c2, t.exact.at, "the nutation limits' c₂");
  const ex q_root = -(c2 + c2_sign * root) / 2;
  const ex d_plus = q_root / beta, d_minus = c1 / q_root;
  const double u0n = std::cos(t.start.theta);
  // Named as a reader of the key knows them: d is no answer, and "d-" named nothing.
  const std::string limit =
      "the other nutation limit's d = cos θ − cos θ₀ (a root of β d² + c₂ d + c₁, as the "
      "nutation limits' steps write it)";
  const double dp = value(t, d_plus, limit), dm = value(t, d_minus, limit);
  // A root at u = +-1 (a limit at the vertical) may round a few ulps outside [-1, 1].
  constexpr double kRootSlack = 1e-12;
  const auto in_range = [&](double d) {
    return u0n + d >= -1 - kRootSlack && u0n + d <= 1 + kRootSlack;
  };
  const bool plus = in_range(dp) && (!in_range(dm) || std::abs(dp) <= std::abs(dm));
  const ex d = sym::tidy(plus ? d_plus : d_minus);
  const double dn = plus ? dp : dm;
  // The other limit at a larger cos (d > 0) is at a smaller angle: then the start is theta_max.
  const bool start_is_max = dn > 0;
  const ex e = upper == start_is_max ? t.theta : GiNaC::acos(u0 + d);
  Computed out{exact_scalar(q, e, "rad", t.exact), steps};
  // The double route rounds u = cos(theta) a few times and acos amplifies that by 1/sin(theta)
  // (near theta = 0 or pi, a fast or heavy top); and it inherits its inputs' rounding, amplified
  // by the cubic's conditioning (a near double root).
  const double acos_amplified = 4 * std::numeric_limits<double>::epsilon() / std::sin(want);
  const double moved = rounding_sensitivity(
      [&](const std::vector<double>& x) {
        const HeavyTop top{x[0], x[1], x[2], x[3], x[4]};
        const Nutation m = nutation_limits(top, {x[5], x[6], x[7], x[8]});
        return upper ? m.theta_max : m.theta_min;
      },
      {t.numeric.M_kg, t.numeric.l_m, t.numeric.g_m_s2, t.numeric.I1_kgm2, t.numeric.I3_kgm2,
       t.start.theta, t.start.thetadot, t.start.phidot, t.start.psidot});
  check_routes_agree(out.answer.value.data[0], want, 1.0, kRouteUlps, q, acos_amplified + moved);
  const std::string turning =
      "θ̇0 = 0: the start is a turning point; dividing f by (u − cos θ0) leaves β d² + c2 d + c1 "
      "= 0 in d = u − cos θ0, with";
  out.steps.push_back({turning + " c1 = " + sym::to_text(c1, t.table) +
                           ", c2 = " + sym::to_text(c2, t.table) + ".",
                       "c_1 = " + sym::to_latex(c1, t.table) +
                           ",\\qquad c_2 = " + sym::to_latex(c2, t.table),
                       turning});
  const std::string roots =
      "Its roots, written without subtracting nearly equal numbers: q/β and c1/q with q = −(c2 + "
      "sgn(c2) √(c2² − 4 β c1))/2; the one with cos θ in [−1, 1] is the other limit.";
  out.steps.push_back({roots,
                       "d = \\frac{q}{\\beta}\\ \\text{or}\\ \\frac{c_1}{q},\\quad q = "
                       "-\\tfrac12\\left(c_2 + \\operatorname{sgn}(c_2)\\sqrt{c_2^2 - 4\\beta c_1}\\right)",
                       "Its roots, without cancellation:"});
  return out;
}

Computed motion_kind(const Top& t) {
  const ex u_star = sym::tidy(t.p_phi / t.p_psi);
  Computed out{exact_scalar("u_phidot_zero", u_star, "", t.exact), {potential_step()}};
  const double us = out.answer.value.data[0];
  // f(u*) = (1 - u*^2)(alpha - beta u*) since b - a u* = 0: its sign places u* against the
  // limits, decided exactly where it is zero.
  const ex level = sym::tidy(2 * t.energy_prime - 2 * t.M * t.g * t.l * u_star);
  const bool zero = sym::is_identically_zero(level.subs(t.exact.at));
  const double lv = zero ? 0.0 : value(t, level, "2E' - 2 M g l u*");
  std::string kind;
  if (zero && std::abs(us) < 1) {
    kind = "u_p is a nutation limit: φ̇ = 0 there, the axis traces cusps (a top released at rest).";
  } else if (std::abs(us) < 1 && lv > 0) {
    kind = "u_p lies between the nutation limits: φ̇ changes sign, the axis traces loops.";
  } else {
    kind = "u_p lies outside the nutation limits: φ̇ keeps its sign, the axis traces waves.";
  }
  out.answer.notes.push_back(kind);
  out.steps.push_back(
      {"φ̇ = (p_φ − p_ψ u)/(I1 (1 − u²)) vanishes at u_p = p_φ/p_ψ; f(u_p) = (1 − u_p²)(α − β "
       "u_p) says whether u_p lies inside (loops), on (cusps) or outside (waves) [u_min, u_max].",
       ""});
  return out;
}

// The fast top's steady rates, as courses teach them: M g l / (I3 ω3) for the slow one (the
// quadratic's small root, its φ̇² term dropped), I3 ω3 / (I1 cos θ) for the fast one (its M g l
// dropped). The note says how far off each is at these values; the judge names one given for
// the answer.
void add_fast_top_approximation(const Top& t, bool slow, Answer& answer) {
  const HeavyTop& n = t.numeric;
  const double spin_momentum = n.I3_kgm2 * t.constants.w3;
  const double approximate = slow ? n.M_kg * n.g_m_s2 * n.l_m / spin_momentum
                                  : spin_momentum / (n.I1_kgm2 * std::cos(t.start.theta));
  const double exact = answer.value.data.at(0);
  const double off_percent = 100 * (approximate - exact) / exact;
  const std::string formula = slow ? "M g l / (I3 ω3)" : "I3 ω3 / (I1 cos θ)";
  // A horizontal axle makes the slow root's equation linear: the approximation is the root.
  constexpr double kSameRootPercent = 1e-9;
  const std::string how_far = std::abs(off_percent) < kSameRootPercent
                                  ? std::string("the exact root itself")
                                  : fmt::format("{:.3g}% {} the exact root", std::abs(off_percent),
                                                off_percent < 0 ? "below" : "above");
  answer.notes.push_back(
      fmt::format("The {} precession: for a fast top ≈ {}, {}; here that is "
                  "{:.4g} rad/s, {}.",
                  slow ? "slow" : "fast", formula,
                  slow ? "independent of θ" : "nearly the free nutation", approximate, how_far));
  answer.approximations.push_back(
      {"the fast-top approximation " + formula,
       fmt::format("the {} rate is the root of I1 cos θ φ̇² − I3 ω3 φ̇ + M g l = 0 {} zero",
                   slow ? "slow" : "fast", slow ? "nearer" : "farther from"),
       {approximate}});
}

// How far the double route to a steady precession rate moves with the rounding of its inputs
// where it is ill-conditioned (rad/s): near a horizontal axle the fast root ~ 1/cos θ0 takes
// the rounding of θ0 (typed 1.5707963 or 89.9999999deg) amplified by tan θ0, and near the
// least spin for steady precession the root of D = (I3 ω3)² − 4 I1 M g l cos θ0 takes D's
// rounding amplified by 1/sqrt(D). Central differences would step across the pole at
// cos θ0 = 0; these are the first-order terms, by hand.
double steady_rate_sensitivity(const Top& t, bool slow) {
  const HeavyTop& n = t.numeric;
  const double eps = std::numeric_limits<double>::epsilon();
  const double theta = t.start.theta, c = std::cos(theta), s = std::sin(theta);
  const double Mgl = n.M_kg * n.g_m_s2 * n.l_m, p = n.I3_kgm2 * t.constants.w3;
  const double four_I1_Mgl_c = 4 * n.I1_kgm2 * Mgl * c;
  const double root = std::sqrt(p * p - four_I1_Mgl_c);
  const double sign = t.constants.w3 >= 0 ? 1.0 : -1.0;
  const double q = p + sign * root;
  // rate(q, c): slow = 2 M g l / q, fast = q / (2 I1 c); q(c) = p + sgn(ω3) sqrt(D(c)).
  const double drate_dq = slow ? -2 * Mgl / (q * q) : 1 / (2 * n.I1_kgm2 * c);
  const double dq_dD = sign / (2 * root);
  const double dq_dc = dq_dD * (-4 * n.I1_kgm2 * Mgl);
  const double drate_dc = drate_dq * dq_dc + (slow ? 0.0 : -q / (2 * n.I1_kgm2 * c * c));
  const double from_theta = std::abs(drate_dc * s * theta) * eps;
  const double from_D = std::abs(drate_dq * dq_dD) * (p * p + std::abs(four_I1_Mgl_c)) * eps;
  return from_theta + from_D;
}

Computed steady(const Top& t, const std::string& q) {
  const ex c = GiNaC::cos(t.theta);
  const ex p = t.p_psi, Mgl = t.M * t.g * t.l;
  const auto rates = steady_precession(t.numeric, t.start.theta, t.constants.w3);
  if (!rates) {
    // No steady precession at this tilt: the key says so and gives the least spin that has one.
    const double need = 2 *
                        std::sqrt(t.numeric.I1_kgm2 * t.numeric.M_kg * t.numeric.g_m_s2 *
                                  t.numeric.l_m * std::cos(t.start.theta)) /
                        t.numeric.I3_kgm2;
    Computed none;
    none.exists = false;
    none.steps.push_back(
        {fmt::format("No steady precession at θ0 = {} rad: it needs (I3 ω3)² ≥ 4 I1 M g l cos θ0, "
                     "i.e. ω3 ≥ {} rad/s, and this top spins at ω3 = {} rad/s.",
                     format_number(t.start.theta), format_number(need),
                     format_number(t.constants.w3)),
         ""});
    return none;
  }
  const ex root = GiNaC::sqrt(sym::tidy(p * p - 4 * t.I1 * Mgl * c));
  // cos θ is 0 in the forms of a horizontal axle (Top writes θ0 = π/2 in): the root is |p|,
  // and q = p + sgn(ω3) |p| = 2p.
  const bool horizontal = c.is_zero();
  const ex qq = horizontal ? 2 * p : t.constants.w3 >= 0 ? p + root : p - root;
  const bool slow = q == "phidot_slow";
  if (!slow && horizontal) {
    // A horizontal axle: the equation is linear in φ̇, its one root the slow (gyroscope's)
    // precession; the fast root has run off to infinity.
    Computed none;
    none.exists = false;
    none.steps.push_back(
        {"θ0 = 90°: the axle is horizontal, so I1 cos θ φ̇² vanishes and the one steady "
         "precession is φ̇ = M g l/(I3 ω3) (the gyroscope's); the fast one has run off to "
         "infinity.",
         ""});
    return none;
  }
  Computed out{exact_scalar(q, slow ? 2 * Mgl / qq : qq / (2 * t.I1 * c), "rad/s", t.exact),
               {{"θ̈ = 0 at fixed θ with ω3 fixed: I1 cos θ φ̇² − I3 ω3 φ̇ + M g l = 0; the roots as "
                 "2Mgl/q and q/(2 I1 cos θ), q = I3 ω3 + sqrt((I3 ω3)² − 4 I1 M g l cos θ) (no "
                 "cancellation).",
                 "I_1\\cos\\theta\\,\\dot\\phi^2 - I_3\\omega_3\\,\\dot\\phi + Mgl = 0",
                 "Steady precession:"}}};
  const double want = slow ? rates->slow : rates->fast;
  if (std::isfinite(want)) {
    const double moved = steady_rate_sensitivity(t, slow);
    check_routes_agree(out.answer.value.data[0], want, want, kRouteUlps, q, moved);
  }
  add_fast_top_approximation(t, slow, out.answer);
  return out;
}

// The spin's and the least stable spin's double routes: a product, a square root, a quotient.
constexpr double kSpinRouteUlps = 16;

Computed lagrangian0(const Top& t, const std::string& q) {
  const ex c = GiNaC::cos(t.theta), s = GiNaC::sin(t.theta);
  const auto& k = t.constants;
  const ex L = t.I1 / 2 * (GiNaC::pow(t.phidot * s, 2) + GiNaC::pow(t.thetadot, 2)) +
               t.I3 / 2 * GiNaC::pow(t.w3, 2) - t.M * t.g * t.l * c;
  Computed out{exact_scalar(q, L, "J", t.exact), {lagrangian_step()}};
  // Its value at t = 0 as a student writes it, L(0) or L₀. Not "L" alone: in the expression of
  // another answer that is more likely l (the pivot's distance) typed in the wrong case.
  out.answer.step_names = {"L0"};
  const double Vn = t.numeric.M_kg * t.numeric.g_m_s2 * t.numeric.l_m * std::cos(t.start.theta);
  check_routes_agree(out.answer.value.data[0], k.energy - 2 * Vn, k.energy + std::abs(Vn),
                     kRouteUlps, q);
  return out;
}

Computed momentum(const Top& t, const std::string& q) {
  const auto& k = t.constants;
  Computed out{exact_scalar(q, q == "p_phi" ? t.p_phi : t.p_psi, "kg m^2/s", t.exact),
               {lagrangian_step(), momenta_step()}};
  const double want = q == "p_phi" ? k.p_phi : k.p_psi;
  check_routes_agree(out.answer.value.data[0], want, std::abs(k.p_psi) + std::abs(k.p_phi),
                     kRouteUlps, q);
  return out;
}

Computed energy(const Top& t, const std::string& q) {
  const auto& k = t.constants;
  const ex E = q == "energy" ? t.energy_prime + t.I3 / 2 * GiNaC::pow(t.w3, 2) : t.energy_prime;
  Computed out{exact_scalar(q, E, "J", t.exact), {lagrangian_step(), momenta_step()}};
  if (q == "energy_prime") out.steps.push_back(potential_step());
  // "E = T + M g l cos θ", as the steps write; the level E′, as the question does.
  out.answer.step_names = {q == "energy" ? "E" : "E'"};
  const double Vn = t.numeric.M_kg * t.numeric.g_m_s2 * t.numeric.l_m;
  check_routes_agree(out.answer.value.data[0], q == "energy" ? k.energy : k.energy_prime,
                     std::abs(k.energy) + Vn, kRouteUlps, q);
  return out;
}

Computed nutation(const Top& t, const std::string& q) {
  const bool upper = q == "theta_max";
  Computed out = nutation_limit(t, upper);
  out.answer.bound = upper ? AnswerBound::upper : AnswerBound::lower;  // θ_min ≤ θ ≤ θ_max
  return out;
}
Computed kind_of_motion(const Top& t, const std::string&) { return motion_kind(t); }

Computed spin(const Top& t, const std::string& q) {
  const auto& k = t.constants;
  const ex w_min = sym::simplified_sqrt(sym::tidy(4 * t.M * t.g * t.l * t.I1 / (t.I3 * t.I3)));
  const Step sleeping{
      "The vertical (sleeping) top: small tilts stay small when p_ψ² ≥ 4 M g l I1, i.e. "
      "ω3 ≥ 2 sqrt(M g l I1)/I3.",
      "p_\\psi^2 \\ge 4MglI_1 \\iff \\omega_3 \\ge \\frac{2\\sqrt{MglI_1}}{I_3}",
      "Sleeping top:"};
  Computed out{exact_scalar(q, q == "omega3" ? t.w3 : w_min, "rad/s", t.exact), {sleeping}};
  const bool stable = sleeping_top_is_stable(k.p_psi, t.numeric.M_kg, t.numeric.g_m_s2,
                                             t.numeric.l_m, t.numeric.I1_kgm2);
  if (q == "omega3_min") {
    out.answer.bound = AnswerBound::lower;  // the top sleeps for ω3 ≥ omega3_min
    const double wn =
        2 * std::sqrt(t.numeric.M_kg * t.numeric.g_m_s2 * t.numeric.l_m * t.numeric.I1_kgm2) /
        t.numeric.I3_kgm2;
    check_routes_agree(out.answer.value.data[0], wn, wn, kSpinRouteUlps, q);
    out.answer.notes.push_back(fmt::format(
        "This top's spin ω3 = {} rad/s is {} the minimum: stood vertical, it would {}.",
        format_number(k.w3), stable ? "at least" : "below",
        stable ? "sleep (stay up)" : "fall away from the vertical"));
  } else {
    check_routes_agree(out.answer.value.data[0], k.w3, std::abs(k.w3), kSpinRouteUlps, q);
  }
  return out;
}

using K = AnswerKind;
using F = AnswerFrame;
constexpr SignConvention kNoSign = SignConvention::none;

const std::vector<QuantityRow<const Top>>& rows() {
  static const std::vector<QuantityRow<const Top>> r{
      {{"lagrangian0", "J", K::scalar, F::none, kNoSign,
        "L = I1/2 (phidot^2 sin^2 + thetadot^2) + I3/2 w3^2 - M g l cos(theta) at t = 0"},
       lagrangian0},
      {{"p_phi", "kg m^2/s", K::scalar, F::none, kNoSign, "the conserved momentum of phi"},
       momentum},
      {{"p_psi", "kg m^2/s", K::scalar, F::none, kNoSign,
        "the conserved momentum of psi, I3 w3"},
       momentum},
      {{"energy", "J", K::scalar, F::none, kNoSign, "E = T + M g l cos(theta)"}, energy},
      {{"energy_prime", "J", K::scalar, F::none, kNoSign,
        "E' = E - p_psi^2/(2 I3), the level of the effective potential"},
       energy},
      {{"theta_min", "rad", K::angle, F::none, kNoSign, "the upper nutation limit (least tilt)"},
       nutation},
      {{"theta_max", "rad", K::angle, F::none, kNoSign, "the lower nutation limit (most tilt)"},
       nutation},
      {{"u_phidot_zero", "", K::scalar, F::none, kNoSign,
        "p_phi / p_psi, where phidot = 0: against the limits, waves, cusps or loops"},
       kind_of_motion},
      {{"omega3", "rad/s", K::rate, F::none, kNoSign, "the spin w3 = phidot cos(theta) + psidot"},
       spin},
      {{"omega3_min", "rad/s", K::rate, F::none, kNoSign,
        "the sleeping top's least stable spin 2 sqrt(M g l I1)/I3"},
       spin},
      {{"phidot_slow", "rad/s", K::rate, F::none, kNoSign,
        "the slow steady precession at theta0 with this spin"},
       steady},
      {{"phidot_fast", "rad/s", K::rate, F::none, kNoSign,
        "the fast steady precession at theta0 with this spin"},
       steady},
  };
  return r;
}

// "a", "a and b", "a, b and c".
std::string listed(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    out += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
  }
  return out;
}

// Every answer of a top whose rates are zero says so first: the forms are written without them.
Computed quantity(const Top& t, const std::string& q) {
  Computed out = compute_quantity(rows(), t, q);
  if (!t.written_in.empty()) {
    out.steps.insert(out.steps.begin(),
                     {fmt::format("At these values {}: the exact forms are written with {}.",
                                  listed(t.written_in), t.written_in.size() == 1 ? "it" : "them"),
                      ""});
  }
  return out;
}
}  // namespace

Key solve_heavy_top(const Problem& problem, const sym::Values& values) {
  const Top t(problem, values);
  Key key = assemble_parts(problem, [&](const std::string& q) { return quantity(t, q); });
  key.held = t.held;
  // The steps write the answers in I1, I3 and ω3, as the lecture does; so may a student.
  key.defined_names = {
      {"I1", sym::to_text(t.I1, t.table), "the moment about a transverse axis through the pivot"},
      {"I3", sym::to_text(t.I3, t.table), "the moment about the axle"},
      {"omega3", sym::to_text(t.w3, t.table), "the spin about the axle"}};
  return key;
}

SolverInfo heavy_top_solver() {
  SolverInfo s;
  s.name = "heavy_top";
  s.summary = "a symmetric top on a pivot under gravity: conserved momenta, energy, nutation "
              "limits, the kind of motion, sleeping and steady precession";
  s.motion_keys = {"g", "theta0", "thetadot0", "phidot0", "psidot0"};
  s.quantities = quantity_infos(rows());
  s.solve = solve_heavy_top;
  return s;
}

}  // namespace wobble
