#include "solvers/key.hpp"

#include <fmt/format.h>

#include <cmath>

namespace wobble {

double Value::scale() const {
  double s = 0.0;
  for (double x : data) s = std::max(s, std::abs(x));
  return s;
}

void append_steps(PartKey& part, const std::vector<Step>& steps) {
  for (const auto& s : steps) {
    bool seen = false;
    for (const auto& have : part.steps)
      seen = seen || (have.text == s.text && have.latex == s.latex);
    if (!seen) part.steps.push_back(s);
  }
}

std::string format_number(double x) {
  if (x == 0.0) return "0";  // also turns -0 into 0
  return fmt::format("{:.10g}", x);
}

std::string value_latex(const Value& v) {
  if (v.shape == Value::Shape::scalar) return format_number(v.data.at(0));
  std::string s = "\\begin{pmatrix}";
  for (std::size_t i = 0; i < v.rows; ++i) {
    for (std::size_t j = 0; j < v.cols; ++j) s += (j ? " & " : " ") + format_number(v.at(i, j));
    s += i + 1 < v.rows ? " \\\\" : "";
  }
  return s + " \\end{pmatrix}";
}

}  // namespace wobble
