#pragma once
/// @file
/// The heavy symmetric top solver (`solver = "heavy_top"`): a body (masses and/or shapes)
/// symmetric about z with its centre of mass on +z at l from the pivot (the origin), its tensor
/// about the pivot diag(I1, I1, I3); gravity g along -z; started at the Euler angles' tilt
/// theta0 with rates thetadot0, phidot0, psidot0 (Taylor's z-y-z; the `[motion]` table).
/// Its quantities, with units and meanings, are the rows of its table (`wobble solvers`,
/// README "Solvers").
///
/// Each value is checked against core/heavy_top.hpp (an independent double-precision route).
#include "problem/problem.hpp"
#include "solvers/key.hpp"
#include "solvers/registry.hpp"

namespace wobble {

/// @throws InputError: a body without mass, not symmetric about z, or with its centre of mass
///   off the z axis or not above the pivot; g not > 0; a vertical start (sin theta0 = 0) for
///   the nutation limits; no steady precession at theta0 (spin too slow) for its rates; and all of build_inertia_body's.
Key solve_heavy_top(const Problem& problem, const sym::Values& values);

/// Its registry entry.
SolverInfo heavy_top_solver();

}  // namespace wobble
