#pragma once
/// @file
/// Building answers from exact expressions (symbolic text, LaTeX, value) or from numbers only.
#include <ginac/ginac.h>

#include <string>
#include <vector>

#include "core/inertia.hpp"
#include "solvers/key.hpp"
#include "symbolic/expression.hpp"

namespace wobble {

/// Context shared by the answers of one key: the symbols and the parameter values.
struct ExactContext {
  const sym::SymbolTable& table;
  GiNaC::lst at;
};

Answer exact_scalar(const std::string& name, const GiNaC::ex& e, const std::string& unit,
                    const ExactContext& ctx);
Answer exact_vector(const std::string& name, const std::vector<GiNaC::ex>& v,
                    const std::string& unit, const ExactContext& ctx);
Answer exact_matrix(const std::string& name, const GiNaC::matrix& m, const std::string& unit,
                    const ExactContext& ctx);

/// Numeric only (no closed form): symbolic empty, LaTeX of the numbers, `why` as a note.
/// Entries smaller than kDegeneracyEps * eps * (largest entry) are rounding noise of exact zeros
/// and are printed as 0.
Answer numeric_vector(const std::string& name, const Vec3& v, const std::string& unit,
                      const std::string& why);
Answer numeric_matrix(const std::string& name, const Mat3& m, const std::string& unit,
                      const std::string& why);

/// The solvers' self-check: an exact value (rounded once from 40 digits) against the same
/// quantity by an independent double-precision route in core/. They must agree to `ulps` eps of
/// max(scale, |exact|); otherwise one route has a bug.
/// @throws std::logic_error naming the quantity and both values.
void check_routes_agree(double exact, double numeric, double scale, double ulps,
                        const std::string& name);

/// "[x, y, z]" and "[[..], ..]" GiNaC texts and the LaTeX pmatrix of expressions.
std::string vector_text(const std::vector<GiNaC::ex>& v, const sym::SymbolTable& t);
std::string matrix_text(const GiNaC::matrix& m, const sym::SymbolTable& t);
std::string vector_latex(const std::vector<GiNaC::ex>& v, const sym::SymbolTable& t);
std::string matrix_latex(const GiNaC::matrix& m, const sym::SymbolTable& t);

}  // namespace wobble
