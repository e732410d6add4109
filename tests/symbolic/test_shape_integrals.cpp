// Two derivations of every shape's tensor: GiNaC integration and core's closed forms.
#include <catch2/catch.hpp>
#include <limits>

#include "core/shapes.hpp"
#include "symbolic/expression.hpp"
#include "symbolic/shape_integrals.hpp"

using namespace wobble;
using Catch::Matchers::WithinAbs;

TEST_CASE("integrated shape tensors equal the closed forms") {
  sym::SymbolTable t;
  const GiNaC::ex M = t.declare("M", "M", sym::SymbolSign::positive);
  const std::vector<GiNaC::ex> s{t.declare("s0", "s_0", sym::SymbolSign::positive),
                                 t.declare("s1", "s_1", sym::SymbolSign::positive),
                                 t.declare("s2", "s_2", sym::SymbolSign::positive)};
  const sym::Values values{{"M", 1.7}, {"s0", 0.3}, {"s1", 1.9}, {"s2", 0.55}};
  const GiNaC::lst at = sym::substitution(t, values);
  REQUIRE(shape_kinds().size() == 9);
  for (const auto kind : shape_kinds()) {
    const std::size_t n = shape_size_names(kind).size();
    const std::vector<GiNaC::ex> sizes(s.begin(), s.begin() + static_cast<long>(n));
    std::vector<double> sizes_m{0.3, 1.9, 0.55};
    sizes_m.resize(n);
    const auto derived = sym::derive_shape_inertia(kind, M, sizes);
    const Mat3 closed = shape_inertia_about_cm(kind, 1.7, sizes_m);
    INFO(shape_kind_name(kind));
    // The exact value rounded once vs a closed form of a few roundings: 8 eps of the largest.
    const double tol = 8 * std::numeric_limits<double>::epsilon() * closed.maxCoeff();
    for (unsigned i = 0; i < 3; ++i) {
      for (unsigned j = 0; j < 3; ++j) {
        REQUIRE_THAT(sym::evaluate(derived.I_cm(i, j), at, "I"),
                     WithinAbs(closed(static_cast<int>(i), static_cast<int>(j)), tol));
      }
    }
    REQUIRE_FALSE(derived.steps.empty());
  }
}
