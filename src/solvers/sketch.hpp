#pragma once
/// @file
/// The data of a solver's sketch (render/figure.hpp draws it): the geometry of a torque-free
/// symmetric top at t = 0, in space axes. A solver whose registry row has a `sketch` function
/// fills it; the renderer sees this type only, never the solver.
#include <string>

#include "core/inertia.hpp"

namespace wobble {

struct TopSketch {
  std::string title;
  Vec3 e3, omega, L;            ///< unit vectors (e3 = z)
  double body_half_angle = 0;   ///< (w, e3): the body cone about e3 through w, rad
  double space_half_angle = 0;  ///< (w, L): the space cone about L through w, rad
  double body_rate = 0;         ///< Omega_body along e3 (sign: sense of precession), rad/s
  double space_rate = 0;        ///< |Omega_space|, along L, rad/s
  std::string kind;             ///< "prolate", "oblate" or "spherical"
};

}  // namespace wobble
