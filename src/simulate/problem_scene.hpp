#pragma once
/// @file
/// A problem's motion as a scene: the same body and parameters, with the `[motion]` table's
/// initial conditions written as a scene's, so the problem's motion can be run by the methods
/// `wobble simulate` has (the exact solutions for a free body). Used by `solve --cross-check`
/// and by the page's 3-D view.
///
/// Each dynamics solver's initial conditions, as its header states them:
/// - torque_free_symmetric (omega, alpha): w(0) = omega (sin alpha, 0, cos alpha) in the body,
///   the body's axes along space's at t = 0, no effects;
/// - asymmetric_top (w1, w2, w3): w(0) = (w1, w2, w3) in the body, body = space at t = 0;
/// - heavy_top (g, theta0, thetadot0, phidot0, psidot0): the pivot at the origin O, gravity g
///   along -z, the attitude Taylor's z-y-z (0, theta0, 0), and w(0) = phidot z + thetadot e2' +
///   psidot e3 in the body at psi = 0: (-phidot0 sin theta0, thetadot0, phidot0 cos theta0 +
///   psidot0) (as scenes/heavy-top.toml).
/// Other solvers (inertia, Euler angles) have no motion: none.
#include <optional>

#include "problem/problem.hpp"
#include "problem/scene.hpp"

namespace wobble {

/// Whether the problem has a motion (a `[motion]` table and one of the solvers above): cheap,
/// for every view of a problem.
bool has_motion_scene(const Problem& problem);

/// The problem as a scene (outputs and run settings left at their defaults), or none.
std::optional<Scene> motion_scene(const Problem& problem);

}  // namespace wobble
