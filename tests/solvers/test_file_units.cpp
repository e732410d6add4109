// A problem's quantities read with units of their own, converted exactly: a body's masses,
// sizes, positions and tensor entries ("300 g", "4 cm", "2.5 g cm^2") give the exact tensor the
// same values give in SI as rationals, and the same doubles; motion values ("1432 rpm") give the
// same key as the same value in SI.
#include <algorithm>
#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <variant>

#include "core/input_error.hpp"
#include "problem/values.hpp"
#include "solvers/catalog.hpp"
#include "solvers/inertia_body.hpp"
#include "solvers/solve.hpp"
#include "symbolic/expression.hpp"
#include "temp_files.hpp"

using namespace wobble;
using Catch::Matchers::Contains;
using Catch::Matchers::EndsWith;
using Catch::Matchers::Equals;

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
  // A long text and unit are shown shortened, as the expression reader shows a text.
  std::string long_text = "sin(1";
  for (int i = 0; i < 1000; ++i) long_text += "+1";
  long_text += ")";
  for (int i = 0; i < 1000; ++i) long_text += " m";
  const std::string shown = refusal(box_with([&](ShapeSpec& s) { s.mass = long_text; }));
  CHECK_THAT(shown, Contains("'sin(1+1+1+") && Contains("...' is in m m m") &&
                        Contains("(length¹⁰⁰⁰); it must be in kg (mass)"));
  CHECK(shown.size() < 200);
  // A parameter named like a unit stays the parameter; side by side it is a product without '*'.
  CHECK_THAT(refusal(box_with([](ShapeSpec& s) { s.mass = "2 M"; })),
             Contains("products need '*'"));
}

namespace {
// Every text and number of two keys' answers and steps.
void require_same_key(const Key& x, const Key& y) {
  REQUIRE(x.parts.size() == y.parts.size());
  for (std::size_t i = 0; i < x.parts.size(); ++i) {
    const PartKey &a = x.parts[i], &b = y.parts[i];
    INFO("part " << a.id);
    REQUIRE(a.answers.size() == b.answers.size());
    for (std::size_t k = 0; k < a.answers.size(); ++k) {
      INFO(a.answers[k].name);
      CHECK(a.answers[k].symbolic == b.answers[k].symbolic);
      CHECK(a.answers[k].latex == b.answers[k].latex);
      CHECK(a.answers[k].value.data == b.answers[k].value.data);
    }
    REQUIRE(a.steps.size() == b.steps.size());
    for (std::size_t k = 0; k < a.steps.size(); ++k) CHECK(a.steps[k].text == b.steps[k].text);
  }
}

Key key_of(const Problem& p) {
  return solve(p, parameter_values(p, {}));
}
}  // namespace

TEST_CASE("a problem's motion values read units: the same value in another unit, the same key") {
  // Each written as the parameter converted out of SI and back by the unit's exact factor, so
  // the exact forms cancel to the parameter itself.
  Problem top = find_problem("heavy-top");
  const Key si = key_of(top);
  top.motion->exprs = {{"g", "100*g cm/s^2"},  // g the parameter, before the unit cm/s^2
                       {"theta0", "theta0*180/pi deg"},
                       {"thetadot0", "thetadot0 1/s"},
                       {"phidot0", "phidot0 rad/s"},
                       {"psidot0", "psidot0*60/(2*pi) rpm"}};
  require_same_key(key_of(top), si);

  Problem plate = find_problem("flying-plate");
  const Key plate_si = key_of(plate);
  plate.motion->exprs["omega"] = "omega/(2*pi) Hz";
  require_same_key(key_of(plate), plate_si);

  Problem euler = find_problem("euler-angles");
  const Key euler_si = key_of(euler);
  euler.motion->exprs["theta"] = "theta/(2*pi) rev";
  euler.motion->exprs["psidot"] = "psidot*60/(2*pi) rpm";
  require_same_key(key_of(euler), euler_si);

  Problem asymmetric = find_problem("asymmetric-top");
  const Key asymmetric_si = key_of(asymmetric);
  asymmetric.motion->exprs["w2"] = "w2*60/(2*pi) rpm";
  require_same_key(key_of(asymmetric), asymmetric_si);
}

TEST_CASE("every motion rate in rpm and angle in degrees gives the key of the same value in SI") {
  // 30 rpm is pi rad/s and 30 deg pi/6 rad exactly: pi then enters the exact forms, where
  // factoring once took it for a coefficient and stopped with GiNaC's internal error.
  std::size_t compared = 0;
  for (const Problem& catalog : load_catalog()) {
    if (!catalog.motion) continue;
    for (const auto& [key, value] : catalog.motion->exprs) {
      const std::string text = value;  // a name to capture (clang refuses a structured binding)
      const auto named = std::find_if(catalog.parameters.begin(), catalog.parameters.end(),
                                      [&](const Parameter& p) { return p.name == text; });
      if (named == catalog.parameters.end()) continue;
      const bool angle = named->is_angle(), rate = named->unit == "rad/s";
      if (!angle && !rate) continue;
      INFO(catalog.id << ": motion." << key);
      Problem si = catalog, with_unit = catalog;
      si.motion->exprs[key] = angle ? "pi/6" : "pi";
      with_unit.motion->exprs[key] = angle ? "30 deg" : "30 rpm";
      const auto outcome = [](const Problem& p) -> std::variant<Key, std::string> {
        try {
          return key_of(p);
        } catch (const InputError& e) {
          return std::string(e.what());
        }
      };
      const auto a = outcome(si), b = outcome(with_unit);
      REQUIRE(a.index() == b.index());
      if (a.index() == 1) {  // the same refusal, but for the value shown as it was typed
        std::string refused = std::get<1>(b);
        const std::string typed = with_unit.motion->exprs[key];
        if (const auto at = refused.find(typed); at != std::string::npos)
          refused.replace(at, typed.size(), si.motion->exprs[key]);
        CHECK(std::get<1>(a) == refused);
      } else {
        require_same_key(std::get<0>(a), std::get<0>(b));
      }
      ++compared;
    }
  }
  CHECK(compared >= 20);  // the rates and angles of nine problems' motions
}

TEST_CASE("a motion value in a unit of another dimension is refused, naming the key") {
  Problem top = find_problem("heavy-top");
  top.motion->exprs["g"] = "2 s";
  CHECK_THROWS_WITH(key_of(top), Contains("motion.g: '2 s' is in s (time); it must be in m/s^2"));
  top = find_problem("heavy-top");
  top.motion->exprs["theta0"] = "30 rpm";
  CHECK_THROWS_WITH(key_of(top), Contains("motion.theta0: '30 rpm' is in rpm"));
}

TEST_CASE("a rate given as an angle, or an angle as a mass, is told what the field takes") {
  // rad/s is a time's inverse: 5 rad is no spin, and the field is no angle.
  Problem solid = find_problem("rect-solid");
  solid.motion->exprs["omega"] = "5 rad";
  CHECK_THROWS_WITH(key_of(solid), Equals("motion.omega: '5 rad' is in rad (an angle); it must be "
                                          "in rad/s (1 / time)"));
  solid = find_problem("rect-solid");
  solid.motion->exprs["omega"] = "3 kg";
  CHECK_THROWS_WITH(key_of(solid), EndsWith("it must be in rad/s (1 / time)"));
  // An angle is a pure number; said as the field takes it, whether given with a unit or by its
  // parameters' units.
  solid = find_problem("rect-solid");
  solid.motion->exprs["alpha"] = "2 kg";
  CHECK_THROWS_WITH(key_of(solid), EndsWith("'2 kg' is in kg (mass); it must be an angle (rad, deg "
                                            "or rev)"));
  solid = find_problem("rect-solid");
  solid.motion->exprs["alpha"] = "m";
  CHECK_THROWS_WITH(key_of(solid), EndsWith("'m' is in kg (mass) by its parameters' units; it must "
                                            "be an angle (rad, deg or rev)"));
}

TEST_CASE("a file of one's own is refused at the field's line when it is solved") {
  // The catalog's rect-solid, read from a file named by its path, with its spin in a mass.
  std::ifstream in(problems_dir() / "rect-solid.toml");
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::string from = "omega = \"omega\"";
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n');
  text.replace(at, from.size(), "omega = \"3 kg\"");
  const auto file = test::write_file("units/own-rect-solid.toml", text);
  const Problem own = find_problem(file.string());
  CHECK_FALSE(own.from_catalog);
  CHECK_THROWS_WITH(key_of(own), Equals(file.string() + ":" + std::to_string(line) +
                                        ": motion.omega: '3 kg' is in kg (mass); it must be in "
                                        "rad/s (1 / time)"));
}
