#include "solvers/principal_answers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/principal_axes.hpp"
#include "symbolic/principal_refined.hpp"
#include "symbolic/canonical_print.hpp"
#include "symbolic/principal_sym.hpp"

namespace wobble {

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();
const char* kAxisName = "xyz";

std::string degeneracy_note(const PrincipalAxes& pa) {
  switch (pa.degeneracy) {
    case Degeneracy::pair12:
      return "Degenerate: λ1 = λ2, so any axis in the plane of e1 and e2 is principal; wobble "
             "picks a fixed pair in that plane (README, conventions).";
    case Degeneracy::pair23:
      return "Degenerate: λ2 = λ3, so any axis in the plane of e2 and e3 is principal; wobble "
             "picks a fixed pair in that plane (README, conventions).";
    case Degeneracy::all:
      return "Degenerate: all three moments are equal, so every axis is principal; the axes are "
             "taken along x, y, z.";
    case Degeneracy::none:
      break;
  }
  return "";
}

// Tolerance for the exact route agreeing with the numeric one: the eigen residual bound
// 8 n eps |I| (n = 3) on moments, and on axes the same over the smallest gap between moments.
double moment_tolerance(const Mat3& I) {
  constexpr double kResidualFactor = 8.0, kDimension = 3.0;
  return kResidualFactor * kDimension * kEps * std::max(I.norm(), 1e-300);
}

// A unit axis carries its own rounding (a few eps per component, normalised) besides what the
// moments' error moves it by: this many eps.
constexpr double kAxisRoundingUlps = 64;

void add_method_steps(const sym::SymPrincipal& sp, const ExactContext& ctx,
                      std::vector<Step>& steps) {
  const auto& t = ctx.table;
  if (sp.too_large) {
    steps.push_back(
        {fmt::format("The tensor's entries are too long for a closed form (over {} expression "
                     "nodes): the moments and axes are computed numerically, from the exact "
                     "tensor in 60 digits.",
                     sym::kMaxClosedFormNodes),
         ""});
    return;
  }
  steps.push_back(
      {"Characteristic equation det(λ 1 − I) = 0: " + sym::to_text(sp.characteristic, t) + " = 0",
       "\\det(\\lambda\\,\\mathbf{1} - I) = " + sym::to_latex(sp.characteristic, t) + " = 0",
       "Characteristic equation:"});
  using M = sym::SymPrincipal::Method;
  switch (sp.method) {
    case M::diagonal:
      steps.push_back(
          {"Every product of inertia is zero: the axes x, y, z are principal and the "
           "moments are the diagonal entries.",
           ""});
      break;
    case M::block: {
      const auto p = static_cast<unsigned>(sp.block_p), q = static_cast<unsigned>(sp.block_q);
      const auto k = static_cast<unsigned>(sp.block_k);
      steps.push_back(
          {fmt::format(
               "Only I_{0}{1} is nonzero: {2} is a principal axis with moment I_{2}{2}; the "
               "{0}-{1} block gives λ = (I_{0}{0} + I_{1}{1})/2 ± sqrt(((I_{0}{0} − "
               "I_{1}{1})/2)² + I_{0}{1}²).",
               kAxisName[p], kAxisName[q], kAxisName[k]),
           fmt::format("\\lambda_\\pm = \\frac{{I_{{{0}{0}}} + I_{{{1}{1}}}}}{{2}} \\pm "
                       "\\sqrt{{\\left(\\frac{{I_{{{0}{0}}} - I_{{{1}{1}}}}}{{2}}\\right)^2 + "
                       "I_{{{0}{1}}}^2}}",
                       kAxisName[p], kAxisName[q]),
           fmt::format(
               "Only I_{0}{1} is nonzero: {2} is a principal axis with moment I_{2}{2}; the "
               "{0}-{1} block gives",
               kAxisName[p], kAxisName[q], kAxisName[k])});
      break;
    }
    case M::factored:
      steps.push_back(
          {"The characteristic polynomial factors into linear and quadratic factors; "
           "their roots are the moments.",
           ""});
      break;
    case M::numeric:
      steps.push_back(
          {"The characteristic polynomial does not factor over the rationals in the "
           "parameters, so the moments are computed numerically (iterative symmetric "
           "eigensolver) at the given values.",
           ""});
      break;
  }
}
}  // namespace

PrincipalAnswers principal_answers(const GiNaC::matrix& I_exact, const Mat3& I_numeric,
                                   double I_numeric_error,
                                   const std::string& moments_name, const std::string& axes_name,
                                   const ExactContext& ctx) {
  PrincipalAnswers out;
  const PrincipalAxes pa = principal_axes(I_numeric);
  const GiNaC::symbol lambda("lambda");
  const sym::SymPrincipal sp = sym::principal_closed_form(I_exact, lambda);
  add_method_steps(sp, ctx, out.moment_steps);
  const std::string unit = "kg m^2";
  // An error E in each entry moves each eigenvalue by at most ||E||_2 <= 3 E (Weyl).
  const double tol = moment_tolerance(I_numeric) + 3 * I_numeric_error;

  std::array<std::size_t, 3> order{0, 1, 2};
  // Without a closed form, the exact tensor diagonalised in 60 digits (principal_refined.hpp):
  // double precision alone loses eps |I| / gap in the axes of nearly equal moments.
  PrincipalAxes refined = pa;
  if (sp.method == sym::SymPrincipal::Method::numeric && pa.degeneracy == Degeneracy::none) {
    const sym::RefinedPrincipal r = sym::refined_principal(I_exact, ctx.at);
    refined.moments = r.moments;
    refined.axes.col(0) = canonical_sign(r.axes.col(0));
    refined.axes.col(1) = canonical_sign(r.axes.col(1));
    const Vec3 e3 = r.axes.col(2);
    refined.axes.col(2) = refined.axes.col(0).cross(refined.axes.col(1)).dot(e3) < 0 ? Vec3(-e3) : e3;
    for (int k = 0; k < 3; ++k) {
      const double gap = std::min(k > 0 ? pa.moments[k] - pa.moments[k - 1] : INFINITY,
                                  k < 2 ? pa.moments[k + 1] - pa.moments[k] : INFINITY);
      if (std::abs(refined.moments[k] - pa.moments[k]) > tol ||
          (refined.axes.col(k) - pa.axes.col(k)).norm() > tol / gap + kAxisRoundingUlps * kEps) {
        throw std::logic_error(fmt::format(
            "{}: the 60-digit principal axis {} disagrees with the double-precision one",
            axes_name, k + 1));
      }
    }
  }
  if (sp.method == sym::SymPrincipal::Method::numeric) {
    out.moments = numeric_vector(moments_name, refined.moments, unit,
                                 sp.too_large
                                     ? "Numeric: the tensor is too long for the closed-form "
                                       "route; computed from the exact tensor in 60 digits."
                                     : "Numeric: no closed form (the characteristic cubic does "
                                       "not factor); computed from the exact tensor in 60 "
                                       "digits.");
  } else {
    std::array<double, 3> values{};
    for (std::size_t i = 0; i < 3; ++i)
      values[i] = sym::evaluate(sp.moments[i], ctx.at, moments_name);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
    std::vector<GiNaC::ex> sorted;
    for (std::size_t i = 0; i < 3; ++i) {
      sorted.push_back(sp.moments[order[i]]);
      if (std::abs(values[order[i]] - pa.moments[static_cast<Eigen::Index>(i)]) > tol) {
        throw std::logic_error(
            fmt::format("{}: exact moment {} = {} but the numeric solver gives {}", moments_name,
                        i + 1, values[order[i]], pa.moments[static_cast<Eigen::Index>(i)]));
      }
    }
    out.moments = exact_vector(moments_name, sorted, unit, ctx);
    out.moment_steps.push_back({"In ascending order at the given values: " + out.moments.symbolic,
                                "(\\lambda_1, \\lambda_2, \\lambda_3) = " + out.moments.latex,
                                "In ascending order at the given values:"});
  }
  if (pa.moments[2] <= pa.degeneracy_tolerance) {
    out.moments.notes.push_back(
        "All moments are 0: all the mass is at this point (or there is none), so the tensor is "
        "zero; it cannot turn a rotation into angular momentum.");
  } else if (pa.moments[0] <= pa.degeneracy_tolerance) {
    out.moments.notes.push_back(
        "λ1 = 0: all the mass lies on the axis e1 (a line); the tensor is "
        "still valid.");
  }
  if (pa.degeneracy != Degeneracy::none) out.moments.notes.push_back(degeneracy_note(pa));

  // Axes.
  out.axis_steps.push_back(
      {"Each axis solves (I − λ_k 1) e_k = 0 with |e_k| = 1; e1 and e2 have "
       "their largest-magnitude component positive, and e3 = e1 × e2.",
       "(I - \\lambda_k\\,\\mathbf{1})\\,e_k = 0,\\quad |e_k| = 1,\\quad e_3 = e_1\\times e_2",
       "Each axis solves the equations below; e1 and e2 have their "
       "largest-magnitude component positive:"});
  if (pa.degeneracy != Degeneracy::none) {
    out.axes = numeric_matrix(axes_name, pa.axes, "", degeneracy_note(pa));
    return out;
  }
  std::array<std::optional<sym::SymVec3>, 3> exact_axes;
  if (sp.method != sym::SymPrincipal::Method::numeric) {
    for (std::size_t i = 0; i < 3; ++i) {
      exact_axes[i] = sym::principal_axis_closed_form(I_exact, sp, order[i], ctx.at);
    }
  }
  if (!exact_axes[0] || !exact_axes[1] || !exact_axes[2]) {
    out.axes = numeric_matrix(axes_name, refined.axes, "",
                              "Numeric: computed at the given values (no closed form), from the "
                              "exact tensor in 60 digits, so every printed digit is right even "
                              "for nearly equal moments.");
    return out;
  }
  if (sp.method == sym::SymPrincipal::Method::block) {
    const auto p = static_cast<unsigned>(sp.block_p), q = static_cast<unsigned>(sp.block_q);
    const double theta = sym::evaluate(sp.block_angle, ctx.at, axes_name);
    out.axis_steps.push_back(
        {fmt::format("In the {0}-{1} plane the axes are turned by θ = atan2(2 I_{0}{1}, I_{0}{0} − "
                     "I_{1}{1})/2 = {2} = {3} rad",
                     kAxisName[p], kAxisName[q], sym::to_text(sp.block_angle, ctx.table),
                     format_number(theta)),
         "\\theta = " + sym::to_latex(sp.block_angle, ctx.table) + " = " + format_number(theta) +
             "\\,\\mathrm{rad}",
         fmt::format("In the {}-{} plane the axes are turned by", kAxisName[p], kAxisName[q])});
  }
  GiNaC::matrix columns(3, 3);
  Mat3 values;
  for (unsigned k = 0; k < 3; ++k) {
    Vec3 v;
    for (unsigned i = 0; i < 3; ++i) v[i] = sym::evaluate((*exact_axes[k])[i], ctx.at, axes_name);
    // An integer sign: a double would turn GiNaC's exact numbers into floats.
    int sign = 1;
    if (k < 2) {
      sign = canonical_sign(v).dot(v) < 0.0 ? -1 : 1;
    } else {
      sign = values.col(0).cross(values.col(1)).dot(v) < 0.0 ? -1 : 1;
    }
    values.col(k) = static_cast<double>(sign) * v;
    for (unsigned i = 0; i < 3; ++i) columns(i, k) = sym::normal_kept(sign * (*exact_axes[k])[i]);
    // Agreement with the numeric solver; an axis is as good as eps |I| over the nearest gap.
    const double gap = std::min(k > 0 ? pa.moments[k] - pa.moments[k - 1] : INFINITY,
                                k < 2 ? pa.moments[k + 1] - pa.moments[k] : INFINITY);
    if ((values.col(k) - pa.axes.col(k)).norm() > tol / gap + kAxisRoundingUlps * kEps) {
      throw std::logic_error(
          fmt::format("{}: exact axis {} disagrees with the numeric solver", axes_name, k + 1));
    }
  }
  out.axes = exact_matrix(axes_name, columns, "", ctx);
  out.axes.notes.push_back("Columns are e1, e2, e3.");
  return out;
}

}  // namespace wobble
