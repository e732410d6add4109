#include "simulate/problem_scene.hpp"

namespace wobble {

namespace {
// An expression of the [motion] table, parenthesised to be used inside another.
std::string term(const Problem& p, const std::string& key) {
  return "(" + p.motion->at(key) + ")";
}
}  // namespace

bool has_motion_scene(const Problem& problem) {
  return problem.motion && (problem.solver == "torque_free_symmetric" ||
                            problem.solver == "asymmetric_top" || problem.solver == "heavy_top");
}

std::optional<Scene> motion_scene(const Problem& problem) {
  if (!has_motion_scene(problem)) return std::nullopt;
  Scene scene;
  scene.model = problem;
  if (problem.solver == "torque_free_symmetric") {
    const std::string w = term(problem, "omega"), a = term(problem, "alpha");
    scene.omega = {w + "*sin" + a, "0", w + "*cos" + a};
  } else if (problem.solver == "asymmetric_top") {
    scene.omega = {term(problem, "w1"), term(problem, "w2"), term(problem, "w3")};
  } else if (problem.solver == "heavy_top") {
    const std::string theta = term(problem, "theta0"), phidot = term(problem, "phidot0");
    scene.omega = {"-" + phidot + "*sin" + theta, term(problem, "thetadot0"),
                   phidot + "*cos" + theta + " + " + term(problem, "psidot0")};
    scene.orientation.kind = OrientationSpec::Kind::euler;
    scene.orientation.euler = {"0", problem.motion->at("theta0"), "0"};
    scene.gravity = GravitySpec{problem.motion->at("g"), {"0", "0", "0"}};
  }
  return scene;
}

}  // namespace wobble
