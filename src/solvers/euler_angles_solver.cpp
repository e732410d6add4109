#include "solvers/euler_angles_solver.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>

#include "core/euler_angles.hpp"
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

// The [motion] table's keys: Taylor's angles and their rates, in that order.
const std::array<const char*, 6> kMotionKeys{"phi", "theta", "psi", "phidot", "thetadot", "psidot"};

struct Angles : BodyContext {
  Angles(const Problem& problem, const sym::Values& values);
  ex phi, theta, psi, phidot, thetadot, psidot, I1, I2, I3;  // exact
  Vec3 angles_n, rates_n;                                // at the values
  bool singular = false;                                 // sin(theta) = 0 exactly
  std::string file() const { return problem.file.string(); }
};

double value(const Angles& t, const ex& e, const std::string& field) {
  return sym::evaluate(e, t.exact.at, field);
}

Angles::Angles(const Problem& p, const sym::Values& values) : BodyContext(p, values) {
  Angles& t = *this;
  const GiNaC::matrix I = tensor_about_centre(t);
  require_symmetric_about_z(t, I, "the euler_angles solver", "about the centre of mass");
  I1 = I(0, 0);
  I2 = I(1, 1);
  I3 = I(2, 2);
  const std::array<ex*, 6> fields{&phi, &theta, &psi, &phidot, &thetadot, &psidot};
  for (std::size_t i = 0; i < 6; ++i) {
    *fields[i] =
        sym::parse_quantity(t.table, problem.motion->at(kMotionKeys[i]),
                            std::string("motion.") + kMotionKeys[i], i < 3 ? "rad" : "rad/s");
    const double v = value(t, *fields[i], std::string("motion.") + kMotionKeys[i]);
    (i < 3 ? angles_n : rates_n)[static_cast<int>(i % 3)] = v;
  }
  // The principal ranges, in which the angles read back from R are the angles given.
  const auto in = [](double x, double lo, double hi, bool lo_closed) {
    return (lo_closed ? x >= lo : x > lo) && x <= hi;
  };
  if (!in(angles_n[0], -M_PI, M_PI, false) || !in(angles_n[2], -M_PI, M_PI, false)) {
    throw InputError(
        fmt::format("motion: phi = {:.10g} and psi = {:.10g} rad must lie in (-pi, "
                    "pi]",
                    angles_n[0], angles_n[2]));
  }
  if (!in(angles_n[1], 0, M_PI, true)) {
    throw InputError(fmt::format("motion.theta: {:.10g} rad must lie in [0, pi]", angles_n[1]));
  }
  singular = sym::is_identically_zero(ex(GiNaC::sin(theta)).subs(t.exact.at));
}

void check_all(const std::string& name, const std::vector<double>& exact,
               const std::vector<double>& numeric, double ulps) {
  double scale = 0;
  for (double x : numeric) scale = std::max(scale, std::abs(x));
  for (std::size_t i = 0; i < numeric.size(); ++i) {
    check_routes_agree(exact.at(i), numeric[i], scale, ulps, name);
  }
}
void check_all(const Answer& a, const std::vector<double>& numeric, double ulps) {
  check_all(a.name, a.value.data, numeric, ulps);
}
// A rotation matrix's entries: products of a few sines and cosines, each rounded.
constexpr double kRotationUlps = 16;
// The rotation rebuilt from angles that were themselves read from a rotation: twice that.
constexpr double kRoundTripUlps = 2 * kRotationUlps;
std::vector<double> entries(const Mat3& m) {
  std::vector<double> out;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out.push_back(m(i, j));
  }
  return out;
}
std::vector<double> entries(const Vec3& v) {
  return {v[0], v[1], v[2]};
}

GiNaC::matrix Rz(const ex& a) {
  return GiNaC::matrix(
      3, 3, GiNaC::lst{GiNaC::cos(a), -GiNaC::sin(a), 0, GiNaC::sin(a), GiNaC::cos(a), 0, 0, 0, 1});
}
GiNaC::matrix Ry(const ex& a) {
  return GiNaC::matrix(
      3, 3, GiNaC::lst{GiNaC::cos(a), 0, GiNaC::sin(a), 0, 1, 0, -GiNaC::sin(a), 0, GiNaC::cos(a)});
}
GiNaC::matrix expanded(const GiNaC::matrix& m) {
  GiNaC::matrix out(m.rows(), m.cols());
  for (unsigned i = 0; i < m.rows(); ++i) {
    for (unsigned j = 0; j < m.cols(); ++j) out(i, j) = GiNaC::expand(m(i, j));
  }
  return out;
}
GiNaC::matrix R_zyz(const Angles& t) {
  return expanded(Rz(t.phi).mul(Ry(t.theta)).mul(Rz(t.psi)));
}

// An angle's exact form moved into (-pi, pi] by whole turns, decided at the values.
ex wrapped(const Angles& t, ex a) {
  double v = value(t, a, "angle");
  while (v > M_PI) a -= 2 * GiNaC::Pi, v -= 2 * M_PI;
  while (v <= -M_PI) a += 2 * GiNaC::Pi, v += 2 * M_PI;
  return a;
}

std::vector<ex> omega_space(const Angles& t) {
  const ex sf = GiNaC::sin(t.phi), cf = GiNaC::cos(t.phi), st = GiNaC::sin(t.theta),
           ct = GiNaC::cos(t.theta);
  return {-t.thetadot * sf + t.psidot * st * cf, t.thetadot * cf + t.psidot * st * sf,
          t.phidot + t.psidot * ct};
}
std::vector<ex> omega_body(const Angles& t) {
  const ex st = GiNaC::sin(t.theta), ct = GiNaC::cos(t.theta), sp = GiNaC::sin(t.psi),
           cp = GiNaC::cos(t.psi);
  return {-t.phidot * st * cp + t.thetadot * sp, t.phidot * st * sp + t.thetadot * cp,
          t.phidot * ct + t.psidot};
}
std::vector<ex> omega_primed(const Angles& t) {
  return {-t.phidot * GiNaC::sin(t.theta), t.thetadot, t.phidot * GiNaC::cos(t.theta) + t.psidot};
}

// The independent route: w = phidot z + thetadot e2' + psidot e3, each axis from core's
// rotations, then projected on each basis.
struct NumericOmega {
  Vec3 space, body, primed;
};
NumericOmega numeric_omega(const Angles& t) {
  const Vec3& a = t.angles_n;
  const Mat3 R = rotation_from_euler(a, EulerConvention::zyz);
  const Mat3 Rphi = rotation_from_euler(Vec3(a[0], 0, 0), EulerConvention::zyz);
  const Mat3 Rprimed = rotation_from_euler(Vec3(a[0], a[1], 0), EulerConvention::zyz);
  NumericOmega w;
  w.space = t.rates_n[0] * Vec3::UnitZ() + t.rates_n[1] * (Rphi * Vec3::UnitY()) +
            t.rates_n[2] * (R * Vec3::UnitZ());
  w.body = R.transpose() * w.space;
  w.primed = Rprimed.transpose() * w.space;
  return w;
}

// A triple of Euler angles as Taylor (z-y-z) and Goldstein (z-x-z) name them.
const std::vector<std::string> kTaylorAngles{"φ", "θ", "ψ"};

Step rotation_step() {
  return {
      "R = Rz(φ) Ry(θ) Rz(ψ): rotate by φ about z, by θ about the new y (e2'), by ψ about "
      "the new z (e3); its columns are e1, e2, e3 in space components (v_space = R v_body).",
      "R = R_z(\\phi)\\,R_y(\\theta)\\,R_z(\\psi)", "Taylor's z-y-z rotation:"};
}

Computed angles_back(const Angles& t, bool zxz) {
  const std::string q = zxz ? "angles_back_zxz" : "angles_back_zyz";
  const Mat3 R = rotation_from_euler(t.angles_n, EulerConvention::zyz);
  std::vector<ex> a;
  std::vector<Step> steps{rotation_step()};
  steps.push_back(zxz ? Step{"z-x-z from R: θ = acos(R33), φ = atan2(R13, −R23), ψ = atan2(R31, "
                             "R32) (sin θ > 0).",
                             "\\theta = \\arccos R_{33},\\ \\phi = \\operatorname{atan2}(R_{13}, "
                             "-R_{23}),\\ \\psi = \\operatorname{atan2}(R_{31}, R_{32})",
                             "Reading back (z-x-z):"}
                      : Step{"z-y-z from R: θ = acos(R33), φ = atan2(R23, R13), ψ = atan2(R32, "
                             "−R31) (sin θ > 0).",
                             "\\theta = \\arccos R_{33},\\ \\phi = \\operatorname{atan2}(R_{23}, "
                             "R_{13}),\\ \\psi = \\operatorname{atan2}(R_{32}, -R_{31})",
                             "Reading back (z-y-z):"});
  const double theta_n = t.angles_n[1];
  if (t.singular) {
    // theta = 0: R = Rz(phi + psi); theta = pi: R = Rz(phi - psi) Ry(pi) = Rz(phi - psi + pi/2)
    // Rx(pi) Rz(-pi/2)... only one combination of phi and psi is defined; psi is set to 0.
    const bool up = theta_n < 1;
    ex turn = up ? t.phi + t.psi : t.phi - t.psi;
    if (zxz && !up) turn += GiNaC::Pi;
    a = {wrapped(t, turn), up ? ex(0) : ex(GiNaC::Pi), 0};
    steps.push_back(
        {up ? "θ = 0: R = Rz(φ + ψ), a turn about z alone; only φ + ψ is defined (gimbal lock). "
              "Convention: ψ = 0 and φ takes the whole turn."
            : std::string("θ = π: R = Rz(φ − ψ) Ry(π); only φ − ψ is defined (gimbal lock). "
                          "Convention: ψ = 0 and φ takes the whole turn") +
                  (zxz ? " (in z-x-z, φ − ψ + π)." : "."),
         ""});
  } else if (zxz) {
    a = {wrapped(t, t.phi + GiNaC::Pi / 2), t.theta, wrapped(t, t.psi - GiNaC::Pi / 2)};
  } else {
    a = {t.phi, t.theta, t.psi};
  }
  Computed out{exact_vector(q, a, "rad", t.exact), steps};
  out.answer.named_entries = kTaylorAngles;
  // The angles must give R back (to rounding), and match core's reading where that is well
  // conditioned (sin(theta) not tiny).
  const EulerConvention c = zxz ? EulerConvention::zxz : EulerConvention::zyz;
  const Vec3 got(out.answer.value.data[0], out.answer.value.data[1], out.answer.value.data[2]);
  check_all(q, entries(rotation_from_euler(got, c)), entries(R), kRoundTripUlps);
  // Near gimbal lock the reading's angles move by eps / sin(theta): no comparison below this.
  constexpr double kWellConditionedSin = 1e-6;
  if (std::sin(theta_n) > kWellConditionedSin) {
    // Core's reading, up to whole turns (at +-pi rounding may land on either end).
    const Vec3 core = euler_from_rotation(R, c);
    for (int i = 0; i < 3; ++i) {
      check_routes_agree(std::remainder(got[i] - core[i], 2 * M_PI), 0.0, M_PI, kRouteUlps, q);
    }
  }
  out.answer.notes.push_back(t.singular ? "Gimbal lock: only one combination of φ and ψ is "
                                          "defined; ψ = 0 by convention."
                                        : "φ, ψ in (−π, π], θ in [0, π]: within these ranges "
                                          "the reading is unique.");
  return out;
}

Mat3 rotation_n(const Angles& t) { return rotation_from_euler(t.angles_n, EulerConvention::zyz); }

Computed rotation(const Angles& t, const std::string& q) {
  const Mat3 R = rotation_n(t);
  const GiNaC::matrix Rs = R_zyz(t);
  const bool phy = q == "R_phy711";
  Computed out{exact_matrix(q, phy ? Rs.transpose() : Rs, "", t.exact), {rotation_step()}};
  check_all(out.answer, entries(phy ? Mat3(R.transpose()) : R), kRotationUlps);
  if (phy) {
    out.steps.push_back(
        {"PHY 711 (the convention of most quantum-mechanics texts): the same three turns, "
         "α = φ about z, β = θ about the new y, γ = ψ about the new z, but R(α, β, γ) acts on "
         "components: v_body = R(α, β, γ) v_inertial, so it is the transpose of Taylor's R.",
         "R(\\alpha,\\beta,\\gamma) = R_z(\\gamma)^T R_y(\\beta)^T R_z(\\alpha)^T = "
         "R_{zyz}^T",
         "PHY 711's matrix:"});
  }
  return out;
}

Computed angles_phy711(const Angles& t, const std::string& q) {
  Computed out{exact_vector(q, {t.phi, t.theta, t.psi}, "rad", t.exact),
               {{"α = φ, β = θ, γ = ψ: both are z-y-z sequences of the same turns; they differ "
                 "in what the matrix acts on (frames against components), not in the angles.",
                 ""}}};
  out.answer.notes.push_back(
      "The lectures' warning is about most classical-mechanics texts (Goldstein: z-x-z), whose "
      "angles differ: see angles_zxz.");
  out.answer.named_entries = {"α", "β", "γ"};  // PHY 711's names
  return out;
}

Computed angles_zxz(const Angles& t, const std::string& q) {
  const std::vector<ex> a{wrapped(t, t.phi + GiNaC::Pi / 2), t.theta,
                          wrapped(t, t.psi - GiNaC::Pi / 2)};
  Computed out{exact_vector(q, a, "rad", t.exact),
               {{"Ry(θ) = Rz(π/2) Rx(θ) Rz(−π/2), so Rz(φ) Ry(θ) Rz(ψ) = Rz(φ + π/2) Rx(θ) "
                 "Rz(ψ − π/2): Goldstein's angles are (φ + π/2, θ, ψ − π/2), each kept in "
                 "(−π, π].",
                 "\\phi_x = \\phi + \\tfrac{\\pi}{2},\\ \\theta_x = \\theta,\\ \\psi_x = \\psi - "
                 "\\tfrac{\\pi}{2}",
                 "To z-x-z:"}}};
  out.answer.named_entries = kTaylorAngles;  // Goldstein's names too
  const Vec3 got(out.answer.value.data[0], out.answer.value.data[1], out.answer.value.data[2]);
  check_all(q, entries(rotation_from_euler(got, EulerConvention::zxz)), entries(rotation_n(t)),
            kRoundTripUlps);
  return out;
}

Computed angular_velocity(const Angles& t, const std::string& q) {
  const NumericOmega n = numeric_omega(t);
  const bool space = q == "omega_space", body = q == "omega_body";
  std::vector<ex> w = space ? omega_space(t) : body ? omega_body(t) : omega_primed(t);
  Computed out{exact_vector(q, w, "rad/s", t.exact),
               {{"w = φ̇ z + θ̇ e2' + ψ̇ e3: the three turns' angular velocities add (each about "
                 "its own axis at that instant).",
                 "\\omega = \\dot\\phi\\,\\hat z + \\dot\\theta\\,\\hat e_2' + "
                 "\\dot\\psi\\,\\hat e_3",
                 "Angular velocity:"}}};
  out.steps.push_back(
      space ? Step{"In the space basis: e2' = (−sin φ, cos φ, 0), e3 = (sin θ cos φ, sin θ sin "
                   "φ, cos θ).",
                   ""}
      : body ? Step{"In the body basis: z = (−sin θ cos ψ, sin θ sin ψ, cos θ), e2' = (sin ψ, "
                    "cos ψ, 0).",
                    ""}
             : Step{"In the primed basis (after the turns by φ and θ, before ψ; e3' = e3): z = "
                    "(−sin θ, 0, cos θ), e2' = (0, 1, 0).",
                    ""});
  check_all(out.answer, entries(space ? n.space : body ? n.body : n.primed), kRouteUlps);
  if (!space) {
    out.answer.notes.push_back(body ? "Components along e1, e2, e3 (they turn with the body)."
                                    : "Components along e1', e2', e3' = e3: the basis of choice "
                                      "for a symmetric top (it does not spin with ψ).");
  }
  return out;
}

// L in the primed basis, numerically: the independent route of L_primed and the energy.
Vec3 L_primed_n(const Angles& t, const NumericOmega& n) {
  const double I1n = value(t, t.I1, "I1"), I3n = value(t, t.I3, "I3");
  return {I1n * n.primed[0], I1n * n.primed[1], I3n * n.primed[2]};
}

Computed L_primed(const Angles& t, const std::string& q) {
  const auto w = omega_primed(t);
  Computed out{exact_vector(q, {t.I1 * w[0], t.I1 * w[1], t.I3 * w[2]}, "kg m^2/s", t.exact),
               {{"L = (I1 w1', I1 w2', I3 w3'): with I1 = I2 the tensor is diag(I1, I1, I3) "
                 "in the primed basis too.",
                 "L = \\left(-I_1\\dot\\phi\\sin\\theta,\\ I_1\\dot\\theta,\\ "
                 "I_3(\\dot\\phi\\cos\\theta + \\dot\\psi)\\right)",
                 "Angular momentum:"}}};
  check_all(out.answer, entries(L_primed_n(t, numeric_omega(t))), kRouteUlps);
  return out;
}

Computed kinetic_energy(const Angles& t, const std::string& q) {
  const auto w = omega_primed(t);
  const NumericOmega n = numeric_omega(t);
  const Vec3 Ln = L_primed_n(t, n);
  const ex T =
      t.I1 / 2 * (GiNaC::pow(t.phidot * GiNaC::sin(t.theta), 2) + GiNaC::pow(t.thetadot, 2)) +
      t.I3 / 2 * GiNaC::pow(w[2], 2);
  Computed out{exact_scalar(q, T, "J", t.exact),
               {{"T = ½ w · L = ½ I1 (φ̇² sin²θ + θ̇²) + ½ I3 (φ̇ cos θ + ψ̇)².",
                 "T = \\tfrac{I_1}{2}\\left(\\dot\\phi^2\\sin^2\\theta + "
                 "\\dot\\theta^2\\right) + \\tfrac{I_3}{2}\\left(\\dot\\phi\\cos\\theta + "
                 "\\dot\\psi\\right)^2",
                 "Kinetic energy:"}}};
  check_routes_agree(out.answer.value.data[0], 0.5 * n.primed.dot(Ln),
                     0.5 * n.primed.norm() * Ln.norm(), kRouteUlps, q);
  return out;
}

Computed reading_back(const Angles& t, const std::string& q) {
  return angles_back(t, q == "angles_back_zxz");
}

using K = AnswerKind;
using F = AnswerFrame;
constexpr SignConvention kNoSign = SignConvention::none;

const std::vector<QuantityRow<const Angles>>& rows() {
  static const std::vector<QuantityRow<const Angles>> r{
      {{"R_zyz", "", K::matrix, F::none, kNoSign,
        "Taylor's Rz(phi) Ry(theta) Rz(psi): body components to space components"},
       rotation},
      {{"R_phy711", "", K::matrix, F::none, kNoSign,
        "PHY 711's R(alpha, beta, gamma): inertial components to body ones (R_zyz transposed)"},
       rotation},
      {{"angles_phy711", "rad", K::vector, F::none, kNoSign,
        "(alpha, beta, gamma) = (phi, theta, psi)"},
       angles_phy711},
      {{"angles_zxz", "rad", K::vector, F::none, kNoSign,
        "Goldstein's z-x-z angles of the same rotation"},
       angles_zxz},
      {{"omega_space", "rad/s", K::vector, F::space, kNoSign, "w in the space basis"},
       angular_velocity},
      {{"omega_body", "rad/s", K::vector, F::body, kNoSign, "w in the body basis"},
       angular_velocity},
      {{"omega_primed", "rad/s", K::vector, F::primed, kNoSign,
        "w in the primed basis (after the turns by phi and theta, before psi)"},
       angular_velocity},
      {{"L_primed", "kg m^2/s", K::vector, F::primed, kNoSign,
        "a symmetric top's L in the primed basis"},
       L_primed},
      {{"kinetic_energy", "J", K::scalar, F::none, kNoSign, "a symmetric top's T"},
       kinetic_energy},
      {{"angles_back_zyz", "rad", K::vector, F::none, kNoSign,
        "the z-y-z angles read back from R (gimbal lock: psi = 0)"},
       reading_back},
      {{"angles_back_zxz", "rad", K::vector, F::none, kNoSign,
        "the z-x-z angles read back from R (gimbal lock: psi = 0)"},
       reading_back},
  };
  return r;
}
}  // namespace

Key solve_euler_angles(const Problem& problem, const sym::Values& values) {
  const Angles t(problem, values);
  Key key =
      assemble_parts(problem, [&](const std::string& q) { return compute_quantity(rows(), t, q); });
  // PHY 711's α, β, γ are Taylor's φ, θ, ψ: a student relating the two may write either.
  for (const std::string name : kMotionKeys) {
    const std::string& given = problem.motion->at(name);
    if (given != name && !t.table.contains(name) && t.table.contains(given))
      key.convention_names.push_back({name, given});
  }
  key.convention = "Taylor's";
  // The steps write L as (I1 w1', I1 w2', I3 w3'), with I1 = I2: so may a student. A name that
  // is the problem's own symbol (I1 here) stays the symbol (the checker reads it first).
  const std::vector<ex> w = omega_primed(t);
  const std::array<const char*, 3> axes{"e₁′", "e₂′", "e₃′ = e₃"};
  key.defined_names = {{"I1", sym::to_text(t.I1, t.table), "the moment about e₁"},
                       {"I2", sym::to_text(t.I2, t.table), "the moment about e₂, equal to I₁"},
                       {"I3", sym::to_text(t.I3, t.table), "the moment about e₃"}};
  for (std::size_t k = 0; k < 3; ++k) {
    key.defined_names.push_back({fmt::format("omega{}'", k + 1), sym::to_text(w[k], t.table),
                                 fmt::format("ω's component along {}", axes[k])});
  }
  // e3' = e3: the spin about the axis is w3 in either basis, as Taylor writes it.
  key.defined_names.push_back({"omega3", sym::to_text(w[2], t.table), "ω's component along e₃"});
  return key;
}

SolverInfo euler_angles_solver() {
  SolverInfo s;
  s.name = "euler_angles";
  s.summary = "Euler angles and their rates: the rotation in three conventions, w in three "
              "bases, a symmetric top's L and T, the angles read back";
  s.motion_keys = {kMotionKeys.begin(), kMotionKeys.end()};
  s.quantities = quantity_infos(rows());
  s.solve = solve_euler_angles;
  return s;
}

}  // namespace wobble
