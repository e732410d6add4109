#pragma once
/// @file
/// The heavy symmetric top with a fixed point: closed forms that need care in floating point.
///
/// Conventions (SI): M mass (kg), l distance pivot -> centre of mass along the symmetry axis (m),
/// g (m/s^2), I1 the moment about a transverse axis through the pivot (kg m^2), p_psi = I3 w3
/// the conserved momentum about the symmetry axis (kg m^2/s). Angles are Taylor's z-y-z Euler
/// angles: theta the tilt of the symmetry axis e3 from the upward vertical z, phi the azimuth of
/// e3 (the precession), psi the spin angle about e3; u = cos(theta).
#include <optional>

namespace wobble {

/// The sleeping (vertical) top is stable when p_psi^2 >= 4 M g l I1. The discriminant is taken
/// in factored form, (|p| - 2 sqrt(M g l I1)) (|p| + 2 sqrt(M g l I1)), so that its sign is right
/// next to the threshold (p^2 - 4 M g l I1 rounds both terms and then cancels).
/// @throws std::invalid_argument unless M, g, l, I1 are finite and > 0 and p is finite.
double sleeping_top_discriminant(double p_psi, double M_kg, double g_m_s2, double l_m,
                                 double I1_kgm2);
bool sleeping_top_is_stable(double p_psi, double M_kg, double g_m_s2, double l_m, double I1_kgm2);

/// A heavy symmetric top about a fixed pivot on its axis.
struct HeavyTop {
  double M_kg = 0, l_m = 0, g_m_s2 = 0;
  double I1_kgm2 = 0;  ///< about a transverse axis through the pivot
  double I3_kgm2 = 0;  ///< about the symmetry axis
  /// @throws std::invalid_argument unless all are finite and > 0.
  void validate() const;
};

/// Euler angles and rates at t = 0 (phi and psi do not enter the dynamics).
struct HeavyTopStart {
  double theta = 0, thetadot = 0, phidot = 0, psidot = 0;
};

/// The conserved quantities: p_phi = I1 phidot sin^2 + p_psi cos, p_psi = I3 w3 with
/// w3 = phidot cos + psidot, the energy E = T + M g l cos(theta), and
/// E' = E - p_psi^2 / (2 I3) = I1/2 (thetadot^2 + phidot^2 sin^2) + M g l cos: the level of the
/// effective potential V(theta) = (p_phi - p_psi cos)^2 / (2 I1 sin^2) + M g l cos.
struct HeavyTopConstants {
  double p_phi = 0, p_psi = 0, w3 = 0, energy = 0, energy_prime = 0;
};
HeavyTopConstants heavy_top_constants(const HeavyTop& top, const HeavyTopStart& start);

/// The nutation limits: the roots u_min <= cos(theta0) <= u_max in [-1, 1] of
/// f(u) = (1 - u^2)(alpha - beta u) - (b - a u)^2 (a = p_psi/I1, b = p_phi/I1, alpha = 2E'/I1,
/// beta = 2 M g l/I1), i.e. thetadot^2 sin^2 = f. Computed as a cubic in d = u - cos(theta0),
/// whose constant term thetadot0^2 sin^2(theta0) >= 0 is exact: with thetadot0 = 0 the start is
/// a root, divided out, and the other comes from a quadratic (no cancellation): the nearest root
/// on the side the motion sets off to (f ~ c1 d); otherwise each root is bracketed in [-1, u0]
/// or [u0, 1] and found by TOMS 748 (Boost.Math) to full precision. Where f vanishes at a pole
/// (b = -+a) that pole is the limit only if f stays positive up to it: f / (1 -+ u), a
/// quadratic, decides (Nutation::through_hanging, through_upright).
/// theta_min = acos(u_max) <= theta0 <= theta_max = acos(u_min).
struct Nutation {
  double u_min = 0, u_max = 0, theta_min = 0, theta_max = 0;
  /// u_min - cos(theta0) and u_max - cos(theta0) as found (the roots in d), not rounded into u:
  /// a limit near a pole, 1 + u_min, is then (1 + cos(theta0)) + d_min without cancellation.
  double d_min = 0, d_max = 0;
  /// The limit is the pole itself, where f vanishes (b = -a: hanging; b = a: upright; a = b = 0,
  /// a pendulum swinging in a vertical plane, both when it swings over the top): the axle passes
  /// through the vertical there, and in the Euler angles theta turns back (it is >= 0) while
  /// phi and psi jump by pi. The limit is then exactly -1 - cos(theta0) or 1 - cos(theta0).
  bool through_hanging = false, through_upright = false;
};
/// @throws std::invalid_argument for an invalid top or a start with sin(theta0) = 0 (the axis
///   vertical: the sleeping top, where theta is not a coordinate of the nutation).
Nutation nutation_limits(const HeavyTop& top, const HeavyTopStart& start);

/// Steady precession at tilt theta with spin w3: the roots of I1 cos(theta) phidot^2 -
/// I3 w3 phidot + M g l = 0, slow = 2 M g l / q and fast = q / (2 I1 cos) with
/// q = I3 w3 + sign(w3) sqrt(D), D = (I3 w3)^2 - 4 I1 M g l cos (the product form: no
/// cancellation). None when D < 0; at cos(theta) = 0 only the slow one (fast = infinity).
struct SteadyPrecession {
  double slow = 0, fast = 0;
};
std::optional<SteadyPrecession> steady_precession(const HeavyTop& top, double theta, double w3);

}  // namespace wobble
