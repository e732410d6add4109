#include "solvers/inertia_solver.hpp"

#include <fmt/format.h>

#include <functional>
#include <limits>
#include <map>
#include <optional>

#include "solvers/body_requirements.hpp"
#include "solvers/inertia_body.hpp"
#include "solvers/principal_answers.hpp"
#include "solvers/quantity_table.hpp"
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

// A mass and a centre: not a tensor given directly (body_requirements.hpp).
void require_mass(const Context& c, const std::string& quantity) {
  wobble::require_mass(c, "the quantity '" + quantity + "'");
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
  if (!c.I_cm_exact) c.I_cm_exact = tensor_about_centre(c);
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

Computed mass(Context& c, const std::string& quantity) {
  require_mass(c, quantity);
  return {exact_scalar(quantity, c.body.exact.mass, "kg", c.exact),
          {{"M = Σ m = " + sym::to_text(c.body.exact.mass, c.table),
            "M = \\sum m = " + sym::to_latex(c.body.exact.mass, c.table), "Total mass:"}}};
}

Computed tensor_about_origin(Context& c, const std::string& quantity) {
  check_against_numeric(c.body.exact.I_O, c.body.numeric.I_O, c, quantity, 0);
  Computed out{exact_matrix(quantity, c.body.exact.I_O, "kg m^2", c.exact), c.body.steps};
  out.steps.push_back({"Tensor about the origin: I = " + out.answer.symbolic,
                       "I = " + out.answer.latex, "Tensor about the origin:"});
  return out;
}

Computed center_of_mass(Context& c, const std::string& quantity) {
  require_mass(c, quantity);
  const auto& r = c.body.exact.r_cm;
  Computed out{exact_vector(quantity, {r[0], r[1], r[2]}, "m", c.exact), {}};
  out.answer.step_names = {"r_cm"};  // as the step below writes it
  out.steps.push_back(
      {"r_cm = Σ m r / Σ m = " + out.answer.symbolic,
       "r_{\\mathrm{cm}} = \\frac{\\sum_p m_p r_p}{\\sum_p m_p} = " + out.answer.latex,
       "Centre of mass:"});
  return out;
}

Computed tensor_about_cm(Context& c, const std::string& quantity) {
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

bool about_cm(const std::string& quantity) {
  return quantity.size() > 3 && quantity.compare(quantity.size() - 3, 3, "_cm") == 0;
}

Computed principal_moments(Context& c, const std::string& quantity) {
  if (about_cm(quantity)) require_mass(c, quantity);
  const auto& p = principal(c, about_cm(quantity));
  return {p.moments, p.moment_steps};
}

Computed principal_axes(Context& c, const std::string& quantity) {
  if (about_cm(quantity)) require_mass(c, quantity);
  const auto& p = principal(c, about_cm(quantity));
  Computed out{p.axes, p.axis_steps};
  out.answer.axis_moments = p.moments.value.data;
  out.answer.axis_moments_symbolic = p.moments.symbolic;
  return out;
}

using K = AnswerKind;
using F = AnswerFrame;
constexpr SignConvention kNoSign = SignConvention::none;

const std::vector<QuantityRow<Context>>& rows() {
  static const std::vector<QuantityRow<Context>> r{
      {{"mass", "kg", K::scalar, F::none, kNoSign, "the total mass M"}, mass},
      {{"I", "kg m^2", K::tensor, F::none, kNoSign, "the inertia tensor about the origin O"},
       tensor_about_origin},
      {{"center_of_mass", "m", K::vector, F::none, kNoSign, "r_cm = sum m r / M"},
       center_of_mass},
      {{"I_cm", "kg m^2", K::tensor, F::none, kNoSign,
        "the tensor about the centre of mass (parallel-axis theorem)"},
       tensor_about_cm},
      {{"principal_moments", "kg m^2", K::principal_moments, F::none, kNoSign,
        "the principal moments about O, ascending"},
       principal_moments},
      {{"principal_axes", "", K::principal_axes, F::none, kNoSign,
        "the principal axes about O, unit columns e1, e2, e3"},
       principal_axes},
      {{"principal_moments_cm", "kg m^2", K::principal_moments, F::none, kNoSign,
        "the principal moments about the centre of mass"},
       principal_moments},
      {{"principal_axes_cm", "", K::principal_axes, F::none, kNoSign,
        "the principal axes about the centre of mass"},
       principal_axes},
  };
  return r;
}
}  // namespace

Key solve_inertia(const Problem& problem, const sym::Values& values) {
  Context c(problem, values);
  return assemble_parts(problem,
                        [&](const std::string& q) { return compute_quantity(rows(), c, q); });
}

SolverInfo inertia_solver() {
  SolverInfo s;
  s.name = "inertia";
  s.summary = "a body of point masses, shapes or a given tensor: mass, centre of mass, the "
              "tensor about O and the centre of mass, principal moments and axes";
  s.quantities = quantity_infos(rows());
  s.solve = solve_inertia;
  return s;
}

}  // namespace wobble
