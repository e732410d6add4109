#pragma once
/// @file
/// The conserved quantities of a scene (see simulation.hpp for which ones, by effects).
#include <functional>
#include <string>
#include <vector>

#include "simulate/scene_setup.hpp"

namespace wobble {

/// Propagated state at one time: momentum about the turning point (P) and attitude P -> S.
struct SimState {
  Vec3 m_P;
  Quat q_PtoS;
};

struct ConservedQuantity {
  std::string name, unit;
  /// Its value (up to 3 components; the error is the largest component's) at a state and t.
  std::function<Vec3(const SimState&, double)> value;
  double scale = 1.0;  ///< the size errors are relative to
};

/// The quantities the scene's effects conserve; empty when none is (a body-fixed torque).
std::vector<ConservedQuantity> conserved_quantities(const SceneSetup& s);

/// The characteristic angular momentum (kg m^2/s): the initial one, or under gravity or a torque
/// the momentum of their rate, so that a body released at rest still has a scale.
double momentum_scale(const SceneSetup& s);

}  // namespace wobble
