// A body's masses, sizes, positions and tensor entries read with units of their own ("300 g",
// "4 cm", "2.5 g cm^2"), converted exactly: the exact tensor is the one the same values give in
// SI as rationals, and the numeric tensor is the same doubles.
#include <catch2/catch.hpp>
#include <map>
#include <string>

#include "core/input_error.hpp"
#include "problem/values.hpp"
#include "solvers/catalog.hpp"
#include "solvers/inertia_body.hpp"
#include "symbolic/expression.hpp"

using namespace wobble;
using Catch::Matchers::Contains;

namespace {
// box-corner (parameters M, a, b, c) with its one box's mass, sizes and centre replaced.
template <class Change>
Problem box_with(const Change& change) {
  Problem p = find_problem("box-corner");
  change(p.body.shapes.at(0));
  return p;
}

// Built with one symbol table per catalog problem, so that two bodies' exact tensors share
// their symbols (a table's symbols are its own) and their difference can cancel.
InertiaBody built(const Problem& p) {
  static std::map<std::string, sym::SymbolTable> tables;
  const auto [at, fresh] = tables.try_emplace(p.id);
  if (fresh) at->second = p.symbol_table();
  return build_inertia_body(p, at->second, parameter_values(p, {}));
}

std::string refusal(const Problem& p) {
  try {
    (void)built(p);
  } catch (const InputError& e) {
    return e.what();
  }
  FAIL("accepted");
  return "";
}

void require_same_tensor(const InertiaBody& x, const InertiaBody& y) {
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) {
      INFO(i << ", " << j);
      CHECK(sym::is_identically_zero(x.exact.I_O(i, j) - y.exact.I_O(i, j)));
      CHECK(x.numeric.I_O(i, j) == y.numeric.I_O(i, j));
    }
  }
}
}  // namespace

TEST_CASE("a body's mass, sizes and centre with units are the exact SI rationals") {
  const InertiaBody with_units = built(box_with([](ShapeSpec& s) {
    s.mass = "300 g";
    s.sizes = {"4 cm", "20 mm", "a"};  // a parameter in SI beside values with units
    s.center = {"2 cm", "1 [cm]", "a/2"};
  }));
  const InertiaBody rationals = built(box_with([](ShapeSpec& s) {
    s.mass = "3/10";
    s.sizes = {"1/25", "1/50", "a"};
    s.center = {"1/50", "1/100", "a/2"};
  }));
  require_same_tensor(with_units, rationals);
  CHECK(with_units.numeric.mass_kg == 0.3);
  // Exact: I_zz about the centre is M (a^2 + b^2)/12 = 3/10 (1/625 + 1/2500)/12 = 1/20000, and
  // the centre's shift adds M (x^2 + y^2) = 3/10 (1/2500 + 1/10000) = 3/20000.
  CHECK(sym::is_identically_zero(with_units.exact.I_O(2, 2) - GiNaC::numeric(4, 20000)));
}

TEST_CASE("point masses and a tensor given directly read units too") {
  Problem masses = find_problem("four-masses");
  Problem masses_si = masses;
  for (auto& m : masses.body.masses) m.mass = "(" + m.mass + ")*1000 g";
  masses.body.masses.at(0).at = {"-a/2*100 cm", "-a/2", "a/2*1000 mm"};
  require_same_tensor(built(masses), built(masses_si));

  Problem tensor = box_with([](ShapeSpec&) {});
  tensor.body.shapes.clear();
  tensor.body.tensor = {{{"2 g cm^2", "0", "0"}, {"0", "3 g cm^2", "0"}, {"0", "0", "4/10000000"}}};
  Problem tensor_si = tensor;
  (*tensor_si.body.tensor)[0][0] = "2/10000000";
  (*tensor_si.body.tensor)[1][1] = "3/10000000";
  require_same_tensor(built(tensor), built(tensor_si));
}

TEST_CASE("a body's unit of the wrong dimension, or a word that is no unit, is refused") {
  CHECK_THAT(refusal(box_with([](ShapeSpec& s) { s.mass = "2 m"; })),
             Contains("body.shapes[0].mass: '2 m' is in m (length); it must be in kg (mass)"));
  CHECK_THAT(refusal(box_with([](ShapeSpec& s) { s.sizes.at(1) = "3 g"; })),
             Contains("body.shapes[0].sizes[1]: '3 g' is in g (mass); it must be in m"));
  CHECK_THAT(refusal(box_with([](ShapeSpec& s) { s.center.at(2) = "1 s"; })),
             Contains("body.shapes[0].center[2]: '1 s' is in s (time)"));
  CHECK_THAT(refusal(box_with([](ShapeSpec& s) { s.mass = "2 parsecs"; })),
             Contains("body.shapes[0].mass: cannot read the unit 'parsecs'"));
  CHECK_THAT(refusal(box_with([](ShapeSpec& s) { s.mass = "-5 g"; })),
             Contains("body.shapes[0].mass: \"-5 g\" is -0.005"));
  // A parameter named like a unit stays the parameter; side by side it is a product without '*'.
  CHECK_THAT(refusal(box_with([](ShapeSpec& s) { s.mass = "2 M"; })),
             Contains("products need '*'"));
}
