#include "solvers/exact_answer.hpp"

#include <fmt/format.h>

#include <cfenv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/principal_axes.hpp"
#include "symbolic/canonical_print.hpp"

namespace wobble {

std::string vector_text(const std::vector<GiNaC::ex>& v, const sym::SymbolTable& t) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + sym::to_text(v[i], t);
  return s + "]";
}

std::string matrix_text(const GiNaC::matrix& m, const sym::SymbolTable& t) {
  std::string s = "[";
  for (unsigned i = 0; i < m.rows(); ++i) {
    std::vector<GiNaC::ex> row;
    for (unsigned j = 0; j < m.cols(); ++j) row.push_back(m(i, j));
    s += (i ? ", " : "") + vector_text(row, t);
  }
  return s + "]";
}

std::string vector_latex(const std::vector<GiNaC::ex>& v, const sym::SymbolTable& t) {
  std::string s = "\\begin{pmatrix}";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? " \\\\ " : " ") + sym::to_latex(v[i], t);
  return s + " \\end{pmatrix}";
}

std::string matrix_latex(const GiNaC::matrix& m, const sym::SymbolTable& t) {
  std::string s = "\\begin{pmatrix}";
  for (unsigned i = 0; i < m.rows(); ++i) {
    for (unsigned j = 0; j < m.cols(); ++j) {
      s += (j ? " & " : " ") + sym::to_latex(m(i, j), t);
    }
    s += i + 1 < m.rows() ? " \\\\" : "";
  }
  return s + " \\end{pmatrix}";
}

Answer exact_scalar(const std::string& name, const GiNaC::ex& e, const std::string& unit,
                    const ExactContext& ctx) {
  Answer a;
  a.name = name;
  a.symbolic = sym::to_text(e, ctx.table);
  a.latex = sym::to_latex(e, ctx.table);
  a.value = Value::scalar(sym::evaluate(e, ctx.at, name));
  a.unit = unit;
  return a;
}

Answer exact_vector(const std::string& name, const std::vector<GiNaC::ex>& v,
                    const std::string& unit, const ExactContext& ctx) {
  Answer a;
  a.name = name;
  a.symbolic = vector_text(v, ctx.table);
  a.latex = vector_latex(v, ctx.table);
  std::vector<double> values;
  for (const auto& e : v) values.push_back(sym::evaluate(e, ctx.at, name));
  a.value = Value::vector(std::move(values));
  a.unit = unit;
  return a;
}

Answer exact_matrix(const std::string& name, const GiNaC::matrix& m, const std::string& unit,
                    const ExactContext& ctx) {
  Answer a;
  a.name = name;
  a.symbolic = matrix_text(m, ctx.table);
  a.latex = matrix_latex(m, ctx.table);
  std::vector<double> values;
  for (unsigned i = 0; i < m.rows(); ++i) {
    for (unsigned j = 0; j < m.cols(); ++j) values.push_back(sym::evaluate(m(i, j), ctx.at, name));
  }
  a.value = Value::matrix(m.rows(), m.cols(), std::move(values));
  a.unit = unit;
  return a;
}

namespace {
std::vector<double> cleaned(std::vector<double> v) {
  double scale = 0.0;
  for (double x : v) scale = std::max(scale, std::abs(x));
  const double noise = kDegeneracyEps * std::numeric_limits<double>::epsilon() * scale;
  for (double& x : v) {
    if (std::abs(x) <= noise) x = 0.0;
  }
  return v;
}

}  // namespace

Answer numeric_vector(const std::string& name, const Vec3& v, const std::string& unit,
                      const std::string& why) {
  Answer a;
  a.name = name;
  a.value = Value::vector(cleaned({v.x(), v.y(), v.z()}));
  a.latex = value_latex(a.value);
  a.unit = unit;
  a.notes.push_back(why);
  return a;
}

Answer numeric_matrix(const std::string& name, const Mat3& m, const std::string& unit,
                      const std::string& why) {
  Answer a;
  a.name = name;
  std::vector<double> values;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) values.push_back(m(i, j));
  }
  a.value = Value::matrix(3, 3, cleaned(std::move(values)));
  a.latex = value_latex(a.value);
  a.unit = unit;
  a.notes.push_back(why);
  return a;
}

namespace {
constexpr int kRangeFlags = FE_OVERFLOW | FE_UNDERFLOW;
thread_local RouteCheckCounts counts;
}  // namespace

void begin_route_checks() { std::feclearexcept(kRangeFlags); }

RouteCheckCounts route_check_counts() { return counts; }

bool double_range_left() { return std::fetestexcept(kRangeFlags) != 0; }

void check_routes_agree(double exact, double numeric, double scale, double ulps,
                        const std::string& name, double input_sensitivity) {
  if (double_range_left()) {
    ++counts.skipped;
    return;
  }
  ++counts.compared;
  const double eps = std::numeric_limits<double>::epsilon();
  const double tolerance = ulps * eps * std::max(scale, std::abs(exact)) + input_sensitivity;
  if (!(std::abs(exact - numeric) <= tolerance)) {
    throw std::logic_error(fmt::format("{}: exact {} but numeric {}", name, exact, numeric));
  }
}

double rounding_sensitivity(const std::function<double(const std::vector<double>&)>& f,
                            const std::vector<double>& x) {
  const double eps = std::numeric_limits<double>::epsilon();
  const double step = std::ldexp(1.0, -20);
  // The differences below may over- or underflow where the route itself did not: they must not
  // turn the comparison off.
  std::fexcept_t saved;
  std::fegetexceptflag(&saved, kRangeFlags);
  double sum = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    std::vector<double> up = x, down = x;
    up[i] = x[i] * (1 + step);
    down[i] = x[i] * (1 - step);
    double change = std::numeric_limits<double>::quiet_NaN();
    try {
      change = std::abs(f(up) - f(down)) / (2 * step);
    } catch (const std::exception&) {
      // a neighbour outside the route's domain (an ordering flipped): that input is skipped
    }
    if (std::isfinite(change)) sum += change;
  }
  std::fesetexceptflag(&saved, kRangeFlags);
  return sum * eps;
}

}  // namespace wobble
