#pragma once
// The heavy top's second derivation for the tests: Lagrange's equations in the Euler angles,
// integrated by Boost.Odeint (no elliptic function, no quaternion), and the top and starts
// both heavy-top test files use.
#include <array>
#include <cmath>
#include <vector>

#include "bench/odeint.hpp"
#include "core/heavy_top.hpp"

namespace wobble::testing {

namespace ode = boost::numeric::odeint;
using LagrangeState = std::array<double, 4>;  // theta, thetadot, phi, psi

// L = I1/2 (phidot^2 sin^2 + thetadot^2) + I3/2 w3^2 - M g l cos with p_phi and p_psi = I3 w3
// conserved: phidot = (p_phi - p_psi cos) / (I1 sin^2), psidot = w3 - phidot cos.
struct Lagrange {
  HeavyTop top;
  double p_phi, p_psi;
  double phidot(double theta) const {
    const double st = std::sin(theta);
    return (p_phi - p_psi * std::cos(theta)) / (top.I1_kgm2 * st * st);
  }
  void operator()(const LagrangeState& x, LagrangeState& d, double) const {
    const double st = std::sin(x[0]), ct = std::cos(x[0]), pd = phidot(x[0]);
    d[0] = x[1];
    d[1] = (top.I1_kgm2 * pd * pd * st * ct - p_psi * pd * st + top.M_kg * top.g_m_s2 * top.l_m * st) /
           top.I1_kgm2;
    d[2] = pd;
    d[3] = p_psi / top.I3_kgm2 - pd * ct;
  }
};

// Constructed in place (GCC 12 warns of uninitialised members when a stepper is copied).
using LagrangeStepper = ode::controlled_runge_kutta<ode::runge_kutta_fehlberg78<LagrangeState>>;
using LagrangeChecker =
    ode::default_error_checker<double, ode::array_algebra, ode::default_operations>;

// A disc (M 0.5 kg, R 5 cm) on an axle, its centre 8 cm from the pivot: the heavy-top scene's.
inline const HeavyTop kTop{0.5, 0.08, 9.81, 0.5 * 0.05 * 0.05 / 4 + 0.5 * 0.08 * 0.08,
                           0.5 * 0.05 * 0.05 / 2};

// Cusps (released at rest), waves (phidot > 0 throughout), loops (phidot changes sign), a start
// between the limits (thetadot != 0), a slow top that swings wide, and a hanging start.
inline const std::vector<HeavyTopStart> kHeavyTopStarts{
    {M_PI / 6, 0, 0, 150}, {0.8, 0, 4, 150},     {0.8, 0, -3, 150},
    {0.9, 2.0, 1.0, 120},  {0.5, -1.0, 0.5, 30}, {2.5, 0.3, 0.0, 60}};

}  // namespace wobble::testing
