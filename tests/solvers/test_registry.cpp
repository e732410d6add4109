// The registry is what the solvers compute: every registered quantity is computed by some
// problem of the catalog with the registered unit, kind, frame and sign; every quantity a
// catalog file asks for is registered; and the loader knows exactly the registry's solvers.
#include <catch2/catch.hpp>
#include <set>

#include "problem/values.hpp"
#include "solvers/catalog.hpp"
#include "solvers/quantity_table.hpp"
#include "solvers/registry.hpp"
#include "solvers/solve.hpp"

using namespace wobble;

namespace {
// `p` asking for one quantity, in a part of its own.
Problem asking_for(Problem p, const std::string& quantity) {
  p.parts = {PartSpec{"q", "?", "", {AnswerSpec{quantity, quantity, std::nullopt}}}};
  return p;
}
}  // namespace

TEST_CASE("every registered quantity is computed as registered by a catalog problem") {
  const auto catalog = load_catalog();
  for (const auto& solver : solver_registry()) {
    for (const auto& info : solver.quantities) {
      INFO(solver.name << " " << info.name);
      int computed = 0;
      for (const auto& p : catalog) {
        if (p.solver != solver.name) continue;
        Key key;
        try {
          key = solve(asking_for(p, info.name), parameter_values(p, {}));
        } catch (const InputError&) {
          continue;  // not at this problem (a tensor given: no mass); another one computes it
        }
        if (key.parts[0].answers.empty()) continue;  // absent at these values
        const Answer& a = key.parts[0].answers[0];
        CHECK(a.quantity == info.name);
        CHECK(a.kind == info.kind);
        CHECK(a.frame == info.frame);
        CHECK(a.sign == info.sign);
        CHECK(registered_unit(info.unit, a.unit));
        CHECK(!a.value.data.empty());
        if (a.kind == AnswerKind::principal_axes) CHECK(a.axis_moments.size() == 3);
        ++computed;
      }
      CHECK(computed > 0);
    }
  }
}

TEST_CASE("the loader's schemas are the registry's") {
  const auto& schemas = solver_schemas();
  REQUIRE(schemas.size() == solver_registry().size());
  for (std::size_t i = 0; i < schemas.size(); ++i) {
    const SolverInfo& s = solver_registry()[i];
    CHECK(schemas[i].name == s.name);
    CHECK(schemas[i].motion_keys == s.motion_keys);
    REQUIRE(schemas[i].quantities.size() == s.quantities.size());
    std::set<std::string> names;
    for (const auto& q : s.quantities) {
      CHECK(names.insert(q.name).second);  // no quantity registered twice
      CHECK(!q.description.empty());
    }
  }
  REQUIRE_THROWS_WITH(solver_info("inertial"),
                      Catch::Contains("unknown solver 'inertial'") && Catch::Contains("heavy_top"));
}

TEST_CASE("registered units: one, or alternatives joined by 'or'") {
  CHECK(registered_unit("rad/s", "rad/s"));
  CHECK(registered_unit("rad/s or 1/s", "1/s"));
  CHECK(registered_unit("rad/s or 1/s", "rad/s"));
  CHECK_FALSE(registered_unit("rad/s or 1/s", "s"));
  CHECK_FALSE(registered_unit("rad/s", "rad"));
  CHECK(registered_unit("", ""));
}
