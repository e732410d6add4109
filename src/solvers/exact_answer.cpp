#include "solvers/exact_answer.hpp"

#include <fmt/format.h>

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

void check_routes_agree(double exact, double numeric, double scale, double ulps,
                        const std::string& name) {
  const double eps = std::numeric_limits<double>::epsilon();
  if (!(std::abs(exact - numeric) <= ulps * eps * std::max(scale, std::abs(exact)))) {
    throw std::logic_error(fmt::format("{}: exact {} but numeric {}", name, exact, numeric));
  }
}

}  // namespace wobble
