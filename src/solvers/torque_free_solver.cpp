#include "solvers/torque_free_solver.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/torque_free_symmetric.hpp"
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

// The problem must have a [motion] table; checked before the body is built.
const Problem& with_motion(const Problem& problem) {
  if (!problem.motion) {
    throw InputError(problem.file.string() + ": motion: missing (a table { omega, alpha })");
  }
  return problem;
}

const std::string kWho = "the torque_free_symmetric solver";

struct Top : BodyContext {
  Top(const Problem& problem, const sym::Values& values);
  ex I1, I3, omega, alpha;  // exact
  SymmetricTop numeric{};   // the independent double-precision route
  bool prolate = false, oblate = false;
};

double value(const Top& t, const ex& e, const std::string& field) {
  return sym::evaluate(e, t.exact.at, field);
}

Top::Top(const Problem& p, const sym::Values& values) : BodyContext(with_motion(p), values) {
  Top& t = *this;
  const GiNaC::matrix I_cm = tensor_about_centre(t);
  require_symmetric_about_z(t, I_cm, kWho, "about the centre of mass", "asymmetric_top");
  t.I1 = I_cm(0, 0);
  t.I3 = I_cm(2, 2);
  t.omega = sym::parse_quantity(t.table, problem.motion->at("omega"), "motion.omega", "rad/s");
  // An angle, and a parameter's name: a mass named here would be no angle to expand in.
  t.alpha = sym::parse_quantity(t.table, problem.motion->at("alpha"), "motion.alpha", "rad");
  if (!GiNaC::is_a<GiNaC::symbol>(t.alpha)) {
    throw InputError("motion.alpha: must name a parameter (the series is taken in it), got \"" +
                     problem.motion->at("alpha") + "\"");
  }
  t.numeric = {value(t, t.I1, "I1"), value(t, t.I3, "I3"), value(t, t.omega, "motion.omega"),
               value(t, t.alpha, "motion.alpha")};
  if (!(t.numeric.omega_rad_s > 0.0)) {
    throw InputError(fmt::format("motion.omega: \"{}\" is {:.10g}; it must be > 0",
                                 problem.motion->at("omega"), t.numeric.omega_rad_s));
  }
  if (!(t.numeric.alpha_rad >= 0.0 && t.numeric.alpha_rad < M_PI / 2)) {
    throw InputError(
        fmt::format("motion.alpha: {:.10g} rad must lie in [0, pi/2)", t.numeric.alpha_rad));
  }
  require_rotating_body(problem.file.string(),
                        Vec3(t.numeric.I1_kgm2, t.numeric.I1_kgm2, t.numeric.I3_kgm2),
                        kWho);
  t.numeric.validate();
  t.prolate = t.numeric.I3_kgm2 < t.numeric.I1_kgm2;
  t.oblate = t.numeric.I3_kgm2 > t.numeric.I1_kgm2;
}

// |I1 - I3| exactly, with the sign known from the values.
ex moment_gap(const Top& t) {
  return t.prolate ? t.I1 - t.I3 : t.I3 - t.I1;
}
ex L_exact(const Top& t, int i) {
  const ex w[3] = {t.omega * GiNaC::sin(t.alpha), 0, t.omega * GiNaC::cos(t.alpha)};
  return sym::simplify((i == 2 ? t.I3 : t.I1) * w[i]);
}
// |L| / I1 as the root of a simplified square, taken last so no factor goes back inside it.
ex rate_space_of(const Top& t) {
  return sym::simplified_sqrt(
      sym::simplify((GiNaC::pow(L_exact(t, 0), 2) + GiNaC::pow(L_exact(t, 2), 2)) / (t.I1 * t.I1)));
}
// atan2(I1 y, I3 x) with the positive common factor divided out: atan2(y, (I3/I1) x) for an
// oblate body, atan2((I1/I3) y, x) for a prolate one, so the coefficients are >= 1.
ex atan2_moments(const Top& t, const ex& y_coefficient_I1, const ex& x_coefficient_I3,
                 const ex& extra_y = 1, const ex& extra_x = 0) {
  const ex smaller = t.prolate ? t.I3 : t.I1;
  return GiNaC::atan2(sym::simplify(t.I1 * y_coefficient_I1 * extra_y / smaller),
                      sym::simplify((t.I3 * x_coefficient_I3 + extra_x) / smaller));
}
ex angle_L_e3(const Top& t) {
  return atan2_moments(t, GiNaC::sin(t.alpha), GiNaC::cos(t.alpha));
}

std::string shape_word(const Top& t) {
  return t.prolate ? "prolate (I3 < I1)" : t.oblate ? "oblate (I3 > I1)" : "spherical (I3 = I1)";
}

Computed quantity_I(const Top& t, bool I0_only) {
  const ex ratio = sym::simplify(t.I1 / t.I3);
  ex I0 = t.I1, p = 1, q = sym::simplify(t.I3 / t.I1);
  if (GiNaC::is_a<GiNaC::numeric>(ratio) && GiNaC::ex_to<GiNaC::numeric>(ratio).is_rational()) {
    const auto r = GiNaC::ex_to<GiNaC::numeric>(ratio);
    I0 = sym::simplify(t.I3 / r.denom());
    p = r.numer();
    q = r.denom();
  }
  std::vector<Step> steps = t.body.steps;
  GiNaC::matrix diag(3, 3);
  diag(0, 0) = diag(1, 1) = p;
  diag(2, 2) = q;
  steps.push_back({"About the centre of mass I = I0 diag(" + sym::to_text(p, t.table) + ", " +
                       sym::to_text(p, t.table) + ", " + sym::to_text(q, t.table) +
                       "), I0 = " + sym::to_text(I0, t.table),
                   "I = I_0\\,\\operatorname{diag}(" + sym::to_latex(p, t.table) + ", " +
                       sym::to_latex(p, t.table) + ", " + sym::to_latex(q, t.table) +
                       "),\\quad I_0 = " + sym::to_latex(I0, t.table),
                   "About the centre of mass:"});
  if (I0_only) return {exact_scalar("I0", I0, "kg m^2", t.exact), steps};
  GiNaC::matrix I(3, 3);
  I(0, 0) = I(1, 1) = t.I1;
  I(2, 2) = t.I3;
  Computed out{exact_matrix("I", I, "kg m^2", t.exact), {}};
  out.answer.notes.push_back("Body frame: e1, e2, e3 along x, y, z; the body is " + shape_word(t) +
                             ".");
  return out;
}

Computed inertia(const Top& t, const std::string& q) { return quantity_I(t, q == "I0"); }

Computed L0(const Top& t, const std::string& q) {
  const double scale_L = t.numeric.L0().norm();
  const std::vector<ex> L{L_exact(t, 0), 0, L_exact(t, 2)};
  Computed out{exact_vector(q, L, "kg m^2/s", t.exact), {}};
  for (int i = 0; i < 3; ++i)
    check_routes_agree(out.answer.value.data[static_cast<std::size_t>(i)], t.numeric.L0()[i],
                       scale_L, kRouteUlps, q);
  out.steps.push_back({"L = I w with w(0) = w (sin α, 0, cos α): L = (I1 w sin α, 0, I3 w cos α)",
                       "L = I\\,\\omega = \\left(I_1\\,\\omega\\sin\\alpha,\\ 0,\\ "
                       "I_3\\,\\omega\\cos\\alpha\\right)",
                       "Angular momentum at t = 0:"});
  out.answer.notes.push_back(
      q == "L0_space"
          ? "Stays valid for all t: no torque acts, so L is constant in space."
          : "Valid at t = 0 only: in the body, L (with w) precesses about e3 at Omega_body.");
  return out;
}

Computed body_cone(const Top& t, const std::string& q) {
  Computed out{exact_scalar(q, t.alpha, "rad", t.exact), {}};
  out.steps.push_back(
      {"w(0) makes the angle α with e3 = z; in the body w stays on the cone of "
       "half angle α about e3 (w3 is constant).",
       ""});
  return out;
}

Computed angle_L(const Top& t, const std::string& q) {
  Computed out{exact_scalar(q, angle_L_e3(t), "rad", t.exact), {}};
  check_routes_agree(out.answer.value.data[0], t.numeric.angle_L_e3(), 1.0, kRouteUlps, q);
  out.steps.push_back({"tan θ_L = L1/L3 = (I1/I3) tan α",
                       "\\theta_L = \\operatorname{atan2}(I_1\\sin\\alpha,\\ I_3\\cos\\alpha)",
                       "The angle of L from e3:"});
  out.answer.step_names = {"theta_L"};
  std::string where = t.numeric.alpha_rad == 0.0 ? "α = 0: e3, w and L all lie along z."
                      : t.prolate ? "Prolate: L lies beyond w; w lies between e3 and L (θ_L > α)."
                      : t.oblate  ? "Oblate: L lies between w and e3 (θ_L < α)."
                                  : "I1 = I3: L is parallel to w.";
  out.answer.notes.push_back(where + " All three are coplanar (the x-z plane at t = 0).");
  return out;
}

Computed space_cone(const Top& t, const std::string& q) {
  const ex s = GiNaC::sin(t.alpha), c = GiNaC::cos(t.alpha);
  const ex smaller = t.prolate ? t.I3 : t.I1;
  const ex angle = GiNaC::atan2(sym::simplify(moment_gap(t) * s * c / smaller),
                                sym::simplify((t.I1 * s * s + t.I3 * c * c) / smaller));
  Computed out{exact_scalar(q, angle, "rad", t.exact), {}};
  check_routes_agree(out.answer.value.data[0], t.numeric.angle_omega_L(), 1.0, kRouteUlps, q);
  out.steps.push_back(
      {"Angle between w and L from |w × L| and w · L (no difference of angles): "
       "w and e3 precess about the fixed L, w on the space cone.",
       "\\tan\\theta_{\\omega L} = \\frac{|I_1 - I_3|\\sin\\alpha\\cos\\alpha}{I_1\\sin^2\\alpha "
       "+ I_3\\cos^2\\alpha}",
       "The space cone, about L through w:"});
  return out;
}

Computed precession_body(const Top& t, const std::string& q) {
  const ex rate_body = sym::simplify((t.I3 - t.I1) / t.I1 * t.omega * GiNaC::cos(t.alpha));
  Computed out{q == "Omega_body" ? exact_vector(q, {0, 0, rate_body}, "rad/s", t.exact)
                                 : exact_scalar(q, rate_body, "rad/s", t.exact),
               {}};
  check_routes_agree(sym::evaluate(rate_body, t.exact.at, q), t.numeric.omega_body_rate(),
                     t.numeric.omega_rad_s, kRouteUlps, q);
  out.steps.push_back(
      {"Euler's equations with I1 = I2: dw1/dt = −Ω w2, dw2/dt = Ω w1, w3 constant, "
       "so w and L turn about e3 at Ω = (I3 − I1) w3 / I1 in the body.",
       "\\Omega_{\\mathrm{body}} = \\frac{I_3 - I_1}{I_1}\\,\\omega_3\\,e_3",
       "Euler's equations with I1 = I2 give"});
  out.answer.notes.push_back(t.prolate  ? "Along −e3: against the spin (prolate body); seen in "
                                          "the body, w and L turn backwards."
                             : t.oblate ? "Along +e3: with the spin (oblate body)."
                                        : "Zero: I1 = I3, no precession.");
  return out;
}

// One turn of w about e3 as seen on the body: Euler's free-wobble period (the Earth's pole).
Computed precession_period(const Top& t, const std::string& q) {
  Computed out{{}, {{"Seen on the body, w turns about e3 once in T = 2π / |Ω_body| = "
                     "2π I1 / (|I3 − I1| ω cos α).",
                     "T = \\frac{2\\pi}{|\\Omega_{\\mathrm{body}}|} = \\frac{2\\pi I_1}{|I_3 - "
                     "I_1|\\,\\omega\\cos\\alpha}",
                     "The period of the body-frame precession:"}}};
  if (!t.prolate && !t.oblate) {
    out.exists = false;
    out.steps.push_back({"I1 = I3: w does not move on the body; there is no period.", ""});
    return out;
  }
  const ex T = 2 * GiNaC::Pi * sym::simplify(t.I1 / moment_gap(t)) / (t.omega * GiNaC::cos(t.alpha));
  out.answer = exact_scalar(q, T, "s", t.exact);
  const double want = 2 * M_PI / std::abs(t.numeric.omega_body_rate());
  // I3 - I1 of rounded moments: a nearly round body (the Earth: 1/305) amplifies their rounding.
  const double moved = rounding_sensitivity(
      [](const std::vector<double>& x) {
        return 2 * M_PI / std::abs(SymmetricTop{x[0], x[1], x[2], x[3]}.omega_body_rate());
      },
      {t.numeric.I1_kgm2, t.numeric.I3_kgm2, t.numeric.omega_rad_s, t.numeric.alpha_rad});
  check_routes_agree(out.answer.value.data[0], want, want, kRouteUlps, q, moved);
  constexpr double kSecondsPerDay = 86400.0;
  out.answer.notes.push_back(
      fmt::format("{} days; in turns of the spin, I1 / |I3 − I1| / cos α = {}.",
                  format_number(out.answer.value.data[0] / kSecondsPerDay),
                  format_number(out.answer.value.data[0] * t.numeric.omega_rad_s / (2 * M_PI))));
  return out;
}

Computed precession_space(const Top& t, const std::string& q) {
  const ex rate_space = rate_space_of(t);
  std::vector<ex> v{sym::simplify(L_exact(t, 0) / t.I1), 0, sym::simplify(L_exact(t, 2) / t.I1)};
  Computed out{q == "Omega_space" ? exact_vector(q, v, "rad/s", t.exact)
                                  : exact_scalar(q, rate_space, "rad/s", t.exact),
               {}};
  check_routes_agree(sym::evaluate(rate_space, t.exact.at, q), t.numeric.omega_space_rate(),
                     t.numeric.omega_rad_s, kRouteUlps, q);
  out.steps.push_back({"In space e3 and w precess about the fixed L at Ω_space = L / I1.",
                       "\\Omega_{\\mathrm{space}} = \\frac{L}{I_1},\\quad "
                       "|\\Omega_{\\mathrm{space}}| = \\frac{|L|}{I_1}",
                       "In space:"});
  out.answer.notes.push_back("Along L, in the sense of the spin.");
  if (q == "Omega_space_rate") {
    const double ratio = t.numeric.omega_space_rate() / t.numeric.omega_rad_s;
    // Equal rates only for a sphere (I1 = I3); a ratio this close to 1 is that case rounded.
    constexpr double kSameRate = 1e-9;
    out.answer.notes.push_back(
        fmt::format("Ω_space / ω = {:.4g}: the wobble is {} than the spin.", ratio,
                    std::abs(ratio - 1.0) < kSameRate ? "as fast"
                    : ratio > 1.0                     ? "faster"
                                                      : "slower"));
  }
  return out;
}

Computed identity_residual(const Top& t, const std::string& q) {
  // Independently computed vectors, in double precision: Omega_space from L, Omega_body from
  // the rate along e3, w from its definition.
  const Vec3 Os = t.numeric.L0() / t.numeric.I1_kgm2;
  const Vec3 Ob(0.0, 0.0, t.numeric.omega_body_rate());
  const Vec3 w = t.numeric.omega0();
  const Vec3 r = Os - Ob - w;
  Computed out{
      numeric_vector(q, r, "rad/s",
                     "Numeric check in double precision; exactly 0 by the algebra in the steps."),
      {}};
  out.answer.value = Value::scalar(r.norm());
  out.answer.latex = format_number(r.norm());
  const char* axis = "xyz";
  // A negative term after a minus in parentheses: "− (-4.83)", never "− -4.83".
  const auto subtracted = [](double x) {
    return x < 0 ? "(" + format_number(x) + ")" : format_number(x);
  };
  for (int i = 0; i < 3; ++i) {
    out.steps.push_back(
        {fmt::format("{}: Ω_space − Ω_body − w = {} − {} − {} = {}", axis[i], format_number(Os[i]),
                     subtracted(Ob[i]), subtracted(w[i]), format_number(r[i])),
         ""});
  }
  out.steps.push_back(
      {"Exactly: x: I1 w sin α / I1 − 0 − w sin α = 0; z: I3 w3/I1 − (I3 − I1) w3/I1 − w3 = 0.",
       "\\frac{I_3\\omega_3}{I_1} - \\frac{(I_3 - I_1)\\,\\omega_3}{I_1} - \\omega_3 = 0",
       "Exactly, the z component:"});
  return out;
}

Computed max_angle(const Top& t, const std::string& q) {
  Computed out{exact_scalar(q, 2 * angle_L_e3(t), "rad", t.exact), {}};
  out.answer.bound = AnswerBound::upper;  // the angle (z, e3) stays at or below it
  check_routes_agree(out.answer.value.data[0], t.numeric.max_angle(), 1.0, kRouteUlps, q);
  out.steps.push_back(
      {"e3 stays at the angle θ_L from the fixed L; z = e3(0) is on that cone, so "
       "the angle (z, e3) is largest, 2 θ_L, when e3 is opposite z across L.",
       "\\theta_{\\max} = 2\\,\\theta_L = 2\\operatorname{atan2}(I_1\\sin\\alpha,\\ "
       "I_3\\cos\\alpha)",
       "The largest angle:"});
  if (t.numeric.alpha_rad == 0.0) out.answer.notes.push_back("α = 0: w along the axis, no wobble.");
  return out;
}

Computed max_angle_series(const Top& t, const std::string& q) {
  const GiNaC::symbol& a = GiNaC::ex_to<GiNaC::symbol>(t.alpha);
  const ex exact =
      2 * GiNaC::atan(sym::simplify(t.I1 / t.I3) * GiNaC::tan(a));  // = 2 theta_L on [0, pi/2)
  const ex poly = GiNaC::series_to_poly(exact.series(a == 0, 4));
  ex leading = 0;
  for (int k = 1; k < 4 && leading.is_zero(); ++k)
    leading = sym::simplify(poly.coeff(a, k)) * GiNaC::pow(a, k);
  Computed out{exact_scalar(q, leading, "rad", t.exact), {}};
  out.steps.push_back({"Series of 2 atan((I1/I3) tan α) about α = 0 (GiNaC): " +
                           sym::to_text(sym::simplify(poly), t.table) + " + O(α⁴)",
                       "\\theta_{\\max} = " + sym::to_latex(sym::simplify(poly), t.table) +
                           " + O(\\alpha^4)",
                       "Series in α:"});
  return out;
}

Computed time_of_max(const Top& t, const std::string& q) {
  const bool still = t.numeric.alpha_rad == 0.0;
  Computed out{still ? exact_scalar(q, 0, "s", t.exact)
                     : exact_scalar(q, GiNaC::Pi / rate_space_of(t), "s", t.exact),
               {}};
  if (!still)
    check_routes_agree(out.answer.value.data[0], t.numeric.t_max(), t.numeric.t_max(), kRouteUlps,
                       q);
  out.steps.push_back({"Half a precession about L: t = π / |Ω_space| = π I1 / |L|.",
                       "t_{\\max} = \\frac{\\pi}{|\\Omega_{\\mathrm{space}}|} = \\frac{\\pi I_1}{|L|}",
                       "The first time:"});
  if (still) out.answer.notes.push_back("α = 0: no wobble; the angle is 0 at all times.");
  return out;
}

using K = AnswerKind;
using F = AnswerFrame;
constexpr SignConvention kNoSign = SignConvention::none;
constexpr SignConvention kSense = SignConvention::sense_of_precession;

const std::vector<QuantityRow<const Top>>& rows() {
  static const std::vector<QuantityRow<const Top>> r{
      {{"I0", "kg m^2", K::scalar, F::none, kNoSign,
        "I0 in I = I0 diag(p, p, q) about the centre of mass (smallest whole p, q if I1/I3 is "
        "rational)"},
       inertia},
      {{"I", "kg m^2", K::tensor, F::body, kNoSign, "the tensor diag(I1, I1, I3) about the centre of mass"},
       inertia},
      {{"L0_body", "kg m^2/s", K::vector, F::body, kNoSign, "L at t = 0, body components"}, L0},
      {{"L0_space", "kg m^2/s", K::vector, F::space, kNoSign, "L (constant), space components"},
       L0},
      {{"angle_omega_e3", "rad", K::angle, F::none, kNoSign, "the angle of w from e3"},
       body_cone},
      {{"body_cone_half_angle", "rad", K::angle, F::none, kNoSign,
        "the body cone's half angle (w, e3)"},
       body_cone},
      {{"angle_L_e3", "rad", K::angle, F::none, kNoSign, "the angle of L from e3"}, angle_L},
      {{"space_cone_half_angle", "rad", K::angle, F::none, kNoSign,
        "the space cone's half angle (w, L)"},
       space_cone},
      {{"Omega_body", "rad/s", K::vector, F::body, kSense,
        "the precession of w and L about e3 seen in the body"},
       precession_body},
      {{"Omega_body_rate", "rad/s", K::rate, F::none, kSense,
        "Omega_body's component along e3 (signed)"},
       precession_body},
      {{"precession_period_body", "s", K::scalar, F::none, kNoSign,
        "2 pi / |Omega_body|: one turn of w about e3 seen on the body (Euler's period)"},
       precession_period},
      {{"Omega_space", "rad/s", K::vector, F::space, kNoSign,
        "the precession of e3 and w about L in space, at t = 0"},
       precession_space},
      {{"Omega_space_rate", "rad/s", K::rate, F::none, kNoSign, "|Omega_space| = |L| / I1"},
       precession_space},
      {{"identity_residual", "rad/s", K::rate, F::none, kNoSign,
        "|Omega_space - Omega_body - w| in double precision (exactly 0)"},
       identity_residual},
      {{"max_angle", "rad", K::angle, F::none, kNoSign, "the largest angle between z and e3"},
       max_angle},
      {{"max_angle_small_alpha", "rad", K::angle, F::none, kNoSign,
        "the leading term of max_angle's series in alpha"},
       max_angle_series},
      {{"t_max", "s", K::scalar, F::none, kNoSign, "the first time max_angle is reached"},
       time_of_max},
  };
  return r;
}
}  // namespace

TopSketch top_sketch(const Problem& problem, const sym::Values& values) {
  const Top t(problem, values);
  const SymmetricTop& n = t.numeric;
  TopSketch s;
  s.title = fmt::format("{}: α = {:.4g}°, θ_L = {:.4g}°", problem.title, n.alpha_rad * 180 / M_PI,
                        n.angle_L_e3() * 180 / M_PI);
  s.e3 = Vec3::UnitZ();
  s.omega = n.omega0().normalized();
  s.L = n.L0().normalized();
  s.body_half_angle = n.alpha_rad;
  s.space_half_angle = n.angle_omega_L();
  s.body_rate = n.omega_body_rate();
  s.space_rate = n.omega_space_rate();
  s.kind = t.prolate ? "prolate" : t.oblate ? "oblate" : "spherical";
  return s;
}

Key solve_torque_free_symmetric(const Problem& problem, const sym::Values& values) {
  const Top t(problem, values);
  return assemble_parts(problem,
                        [&](const std::string& q) { return compute_quantity(rows(), t, q); });
}

SolverInfo torque_free_symmetric_solver() {
  SolverInfo s;
  s.name = "torque_free_symmetric";
  s.summary =
      "a body symmetric about z, spun at omega at the angle alpha from z, no torque: the body "
      "and space cones";
  s.motion_keys = {"omega", "alpha"};
  s.quantities = quantity_infos(rows());
  s.solve = solve_torque_free_symmetric;
  s.sketch = top_sketch;
  s.cross_checked_by_simulation = true;
  return s;
}

}  // namespace wobble
