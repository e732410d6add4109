#include "solvers/inertia_solver.hpp"

#include <fmt/format.h>

#include <functional>
#include <limits>
#include <map>
#include <optional>

#include "solvers/inertia_body.hpp"
#include "solvers/principal_answers.hpp"
#include "solvers/solve.hpp"
#include "symbolic/canonical_print.hpp"

namespace wobble {

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();

// Everything the quantities are computed from, built once per key.
struct Context : BodyContext {
  using BodyContext::BodyContext;
  // Lazily computed shared results.
  std::optional<GiNaC::matrix> I_cm_exact;
  std::optional<PrincipalAnswers> about_O, about_cm;
};

void require_mass(const Context& c, const std::string& quantity) {
  if (!c.body.has_mass) {
    throw InputError(fmt::format("{}: '{}' needs a body with mass; the tensor is given directly",
                                 c.problem.file.string(), quantity));
  }
}

// The exact tensor must match core's numeric one. Each entry of the tensor about O is a sum over
// N bodies of products carrying relative error <= 4 eps, each bounded by trace(I_O); so
// |diff| <= 4 (N+2) eps tr(I_O). The tensor about the centre of mass subtracts M (r² δ − r r)
// (trace 2 M r² <= tr(I_O)) from it: one more such term, and the bound stays in tr(I_O) even
// when the body sits far from O and the difference is small.
double numeric_tensor_error(const Context& c, int subtractions) {
  const std::size_t parts = c.problem.body.masses.size() + c.problem.body.shapes.size();
  return 4.0 * static_cast<double>(parts + 2 + subtractions) * kEps *
         std::max(c.body.numeric.I_O.trace(), 1e-300);
}

void check_against_numeric(const GiNaC::matrix& exact, const Mat3& numeric, const Context& c,
                           const std::string& name, int subtractions) {
  const double tol = numeric_tensor_error(c, subtractions);
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) {
      const double v = sym::evaluate(exact(i, j), c.exact.at, name);
      check_routes_agree(v, numeric(i, j), 0.0, 0.0, fmt::format("{}[{}][{}]", name, i, j), tol);
    }
  }
}

const GiNaC::matrix& I_cm_exact(Context& c) {
  if (!c.I_cm_exact) {
    const auto& e = c.body.exact;
    c.I_cm_exact = sym::normalized(e.I_O.sub(sym::parallel_axis_term(e.mass, e.r_cm)));
  }
  return *c.I_cm_exact;
}

Mat3 I_cm_numeric(const Context& c) {
  const auto& n = c.body.numeric;
  return shift_to_cm(n.I_O, n.mass_kg, n.r_cm_m);
}

const PrincipalAnswers& principal(Context& c, bool about_cm) {
  auto& slot = about_cm ? c.about_cm : c.about_O;
  if (!slot) {
    const std::string suffix = about_cm ? "_cm" : "";
    slot = about_cm
               ? principal_answers(I_cm_exact(c), I_cm_numeric(c), numeric_tensor_error(c, 1),
                                   "principal_moments" + suffix, "principal_axes" + suffix, c.exact)
               : principal_answers(c.body.exact.I_O, c.body.numeric.I_O,
                                   numeric_tensor_error(c, 0), "principal_moments",
                                   "principal_axes", c.exact);
  }
  return *slot;
}

Computed compute(Context& c, const std::string& quantity) {
  const auto& t = c.table;
  if (quantity == "mass") {
    require_mass(c, quantity);
    return {exact_scalar(quantity, c.body.exact.mass, "kg", c.exact),
            {{"M = Σ m = " + sym::to_text(c.body.exact.mass, t),
              "M = \\sum m = " + sym::to_latex(c.body.exact.mass, t), "Total mass:"}}};
  }
  if (quantity == "I") {
    check_against_numeric(c.body.exact.I_O, c.body.numeric.I_O, c, quantity, 0);
    Computed out{exact_matrix(quantity, c.body.exact.I_O, "kg m^2", c.exact), c.body.steps};
    out.steps.push_back({"Tensor about the origin: I = " + out.answer.symbolic,
                         "I = " + out.answer.latex, "Tensor about the origin:"});
    return out;
  }
  if (quantity == "center_of_mass") {
    require_mass(c, quantity);
    const auto& r = c.body.exact.r_cm;
    Computed out{exact_vector(quantity, {r[0], r[1], r[2]}, "m", c.exact), {}};
    out.steps.push_back(
        {"r_cm = Σ m r / Σ m = " + out.answer.symbolic,
         "r_{\\mathrm{cm}} = \\frac{\\sum_p m_p r_p}{\\sum_p m_p} = " + out.answer.latex,
         "Centre of mass:"});
    return out;
  }
  if (quantity == "I_cm") {
    require_mass(c, quantity);
    const auto& exact = I_cm_exact(c);
    check_against_numeric(exact, I_cm_numeric(c), c, quantity, 1);
    Computed out{exact_matrix(quantity, exact, "kg m^2", c.exact), {}};
    out.steps.push_back(
        {"Parallel-axis theorem, from O to the centre of mass: I_cm = I_O − M "
         "(|r_cm|² 1 − r_cm r_cmᵀ)",
         "I_{\\mathrm{cm}} = I_O - M\\left(|r_{\\mathrm{cm}}|^2\\,\\mathbf{1} - "
         "r_{\\mathrm{cm}}\\,r_{\\mathrm{cm}}^{T}\\right)",
         "Parallel-axis theorem, from O to the centre of mass:"});
    out.steps.push_back({"I_cm = " + out.answer.symbolic, "I_{\\mathrm{cm}} = " + out.answer.latex,
                         "About the centre of mass:"});
    return out;
  }
  for (const bool cm : {false, true}) {
    const std::string suffix = cm ? "_cm" : "";
    if (quantity != "principal_moments" + suffix && quantity != "principal_axes" + suffix) continue;
    if (cm) require_mass(c, quantity);
    const auto& p = principal(c, cm);
    if (quantity == "principal_moments" + suffix) return {p.moments, p.moment_steps};
    return {p.axes, p.axis_steps};
  }
  throw InputError(fmt::format(
      "{}: unknown quantity '{}' for the inertia solver (known: mass, I, center_of_mass, I_cm, "
      "principal_moments, principal_axes, principal_moments_cm, principal_axes_cm)",
      c.problem.file.string(), quantity));
}
}  // namespace

Key solve_inertia(const Problem& problem, const sym::Values& values) {
  Context c(problem, values);
  return assemble_parts(problem, [&](const std::string& q) { return compute(c, q); });
}

}  // namespace wobble
