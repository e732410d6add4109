#pragma once
/// @file
/// Building answers from exact expressions (symbolic text, LaTeX, value) or from numbers only.
#include <ginac/ginac.h>

#include <functional>
#include <optional>
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

/// The rounding a double-precision route of core/ may carry, in ulps of its scale: each is a
/// closed form of at most a few dozen operations, each rounding by half an ulp, in forms that do
/// not amplify it more than twofold (cancellations are removed by construction; where a route
/// does amplify, the caller adds rounding_sensitivity). The exact route is rounded once.
inline constexpr double kRouteUlps = 64.0;

/// The solvers' self-check: an exact value (rounded once from 40 digits) against the same
/// quantity by an independent double-precision route in core/. The double route carries its own
/// rounding, up to `ulps` eps of max(scale, |exact|), and the rounding of its inputs, which it
/// amplifies by the problem's conditioning: `input_sensitivity` (see rounding_sensitivity) is
/// how far that moves it. Beyond the sum one route has a bug.
/// No comparison is made once the double route has overflowed or underflowed during this solve
/// (begin_route_checks clears the flags): at such values only the exact route has the digits.
/// @throws std::logic_error naming the quantity and both values.
void check_routes_agree(double exact, double numeric, double scale, double ulps,
                        const std::string& name, double input_sensitivity = 0.0);

/// How far a double-precision route f moves when each of its inputs x_i is off by one rounding
/// (relative eps): sum_i |x_i df/dx_i| eps, by central differences at relative step 2^-20 (their
/// own error, about eps |f| 2^20 / step, is far below the sum). An input whose neighbours f
/// cannot evaluate is skipped.
double rounding_sensitivity(const std::function<double(const std::vector<double>&)>& f,
                            const std::vector<double>& x);

/// Clears the floating-point overflow and underflow flags: solve() calls it before a problem's
/// routes run, and check_routes_agree reads them.
void begin_route_checks();

/// Whether a double route overflowed or underflowed since begin_route_checks.
bool double_range_left();

/// A double-precision route run for the self-check, or nothing when it failed after its values
/// left the double range (an overflow or underflow since begin_route_checks: a wobble of 1e-200
/// squares to zero). Any other failure is a bug and propagates.
template <class F>
auto double_route(F&& route) -> std::optional<decltype(route())> {
  try {
    return route();
  } catch (const std::exception&) {
    if (!double_range_left()) throw;
    return std::nullopt;
  }
}

/// The route comparisons made and skipped (over- or underflow) on this thread, for tests.
struct RouteCheckCounts {
  long compared = 0, skipped = 0;
};
RouteCheckCounts route_check_counts();

/// "[x, y, z]" and "[[..], ..]" GiNaC texts and the LaTeX pmatrix of expressions.
std::string vector_text(const std::vector<GiNaC::ex>& v, const sym::SymbolTable& t);
std::string matrix_text(const GiNaC::matrix& m, const sym::SymbolTable& t);
std::string vector_latex(const std::vector<GiNaC::ex>& v, const sym::SymbolTable& t);
std::string matrix_latex(const GiNaC::matrix& m, const sym::SymbolTable& t);

}  // namespace wobble
