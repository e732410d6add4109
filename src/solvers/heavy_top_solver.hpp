#pragma once
/// @file
/// The heavy symmetric top solver (`solver = "heavy_top"`): a body (masses and/or shapes)
/// symmetric about z with its centre of mass on +z at l from the pivot (the origin), its tensor
/// about the pivot diag(I1, I1, I3); gravity g along -z; started at the Euler angles' tilt
/// theta0 with rates thetadot0, phidot0, psidot0 (Taylor's z-y-z; the `[motion]` table).
/// Quantities, by the names the keys use (README, "Solvers"):
///
///     lagrangian0             L = I1/2 (phidot^2 sin^2 + thetadot^2) + I3/2 (phidot cos +
///                             psidot)^2 - M g l cos, at t = 0                      J
///     p_phi, p_psi            the conserved momenta                                kg m^2/s
///     energy                  E = T + M g l cos(theta)                             J
///     energy_prime            E' = E - p_psi^2/(2 I3): the level of the effective
///                             potential V(theta) = (p_phi - p_psi cos)^2/(2 I1 sin^2) + M g l cos
///     theta_min, theta_max    the nutation limits (exact when released with thetadot0 = 0,
///                             else numeric: roots of a cubic)                      rad
///     u_phidot_zero           p_phi / p_psi, where phidot = 0; its place against the limits
///                             names the kind of motion (waves, cusps, loops)       (none)
///     omega3, omega3_min      the spin phidot cos + psidot and the sleeping top's least
///                             stable spin 2 sqrt(M g l I1)/I3                       rad/s
///     phidot_slow, phidot_fast  steady precession at theta0 with this spin        rad/s
///
/// Each value is checked against core/heavy_top.hpp (an independent double-precision route).
#include "problem/problem.hpp"
#include "solvers/key.hpp"

namespace wobble {

/// @throws InputError: a body without mass, not symmetric about z, or with its centre of mass
///   off the z axis or not above the pivot; g not > 0; a vertical start (sin theta0 = 0) for
///   the nutation limits; no steady precession at theta0 (spin too slow) for its rates; an
///   unknown quantity; and all of build_inertia_body's.
Key solve_heavy_top(const Problem& problem, const sym::Values& values);

}  // namespace wobble
