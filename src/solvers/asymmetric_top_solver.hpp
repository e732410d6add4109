#pragma once
/// @file
/// The torque-free asymmetric-top solver (`solver = "asymmetric_top"`): a body whose tensor about
/// its centre of mass (or the tensor given) is diag(I1, I2, I3) in the problem's axes with
/// I1 < I2 < I3, spun with w(0) = (w1, w2, w3) in the body frame (the `[motion]` table).
/// Quantities, by the names the keys use (README, "Solvers"):
///
///     euler_coefficients      c with dw1/dt = c1 w2 w3, ... : ((I2-I3)/I1, (I3-I1)/I2,
///                             (I1-I2)/I3)                                          (none)
///     dw_dt0                  dw/dt at t = 0                                       rad/s^2
///     Omega_axis1..3          for spin s = |w(0)| about e_k, (Omega_i, Omega_j) of the
///                             lecture, (i, j, k) cyclic: Omega_i = s (I_k - I_j)/I_i,
///                             Omega_j = s (I_k - I_i)/I_j                           rad/s
///     rate_axis1..3           sqrt|Omega_i Omega_j|: the small-oscillation frequency where
///                             stable (product > 0), the growth rate where not      rad/s or 1/s
///     energy, L_magnitude     T and |L| from w(0)                                  J, kg m^2/s
///     k, k2, kc2              the modulus k of the exact solution, k^2 and k'^2 = 1 - k^2
///     period                  of w(t): 4 K(k) / lambda                             s
///     flip_interval           half the period: w2 changes sign (the flip near e2)  s
///     period_small_oscillation  2 pi / rate about the axis w circulates about      s
///
/// The exact forms use the factored invariants 2 T I3 - L^2 = I1 (I3-I1) w1^2 + I2 (I3-I2) w2^2
/// and L^2 - 2 T I1 = I2 (I2-I1) w2^2 + I3 (I3-I1) w3^2, so k'^2 has no cancellation; each is
/// checked against core's ExactFreeMotion (an independent double-precision route).
#include "problem/problem.hpp"
#include "solvers/key.hpp"

namespace wobble {

/// @throws InputError: a tensor with products of inertia, moments not in the order
///   I1 < I2 < I3 (two equal: a symmetric top, for the torque_free_symmetric solver), w(0) zero
///   or not finite, an unknown quantity; the separatrix (L^2 = 2 T I2, no period) for the
///   period's quantities; and all of build_inertia_body's.
Key solve_asymmetric_top(const Problem& problem, const sym::Values& values);

}  // namespace wobble
