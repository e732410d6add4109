#include "simulate/problem_scene.hpp"

#include "symbolic/quantity.hpp"

namespace wobble {

namespace {
// The expressions of a problem's [motion] table in SI, parenthesised to be used inside others:
// "(psidot0)", or "(1432)*(...)/(1)" for "1432 rpm" (symbolic/quantity.hpp).
struct Terms {
  const Problem& p;
  sym::SymbolTable table = p.symbol_table();
  std::string operator()(const std::string& key, const std::string& unit) const {
    return "(" + sym::quantity_expression(table, p.motion->at(key), "motion." + key, unit) + ")";
  }
};
}  // namespace

bool has_motion_scene(const Problem& problem) {
  return problem.motion && (problem.solver == "torque_free_symmetric" ||
                            problem.solver == "asymmetric_top" || problem.solver == "heavy_top");
}

std::optional<Scene> motion_scene(const Problem& problem) {
  if (!has_motion_scene(problem)) return std::nullopt;
  Scene scene;
  scene.model = problem;
  const Terms term{problem};
  if (problem.solver == "torque_free_symmetric") {
    const std::string w = term("omega", "rad/s"), a = term("alpha", "rad");
    scene.omega = {w + "*sin" + a, "0", w + "*cos" + a};
  } else if (problem.solver == "asymmetric_top") {
    scene.omega = {term("w1", "rad/s"), term("w2", "rad/s"), term("w3", "rad/s")};
  } else if (problem.solver == "heavy_top") {
    const std::string theta = term("theta0", "rad"), phidot = term("phidot0", "rad/s");
    scene.omega = {"-" + phidot + "*sin" + theta, term("thetadot0", "rad/s"),
                   phidot + "*cos" + theta + " + " + term("psidot0", "rad/s")};
    scene.orientation.kind = OrientationSpec::Kind::euler;
    scene.orientation.euler = {"0", problem.motion->at("theta0"), "0"};
    scene.gravity = GravitySpec{problem.motion->at("g"), {"0", "0", "0"}};
  }
  return scene;
}

}  // namespace wobble
