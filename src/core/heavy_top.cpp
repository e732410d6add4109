#include "core/heavy_top.hpp"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace wobble {

double sleeping_top_discriminant(double p, double M, double g, double l, double I1) {
  for (const double x : {M, g, l, I1}) {
    if (!std::isfinite(x) || !(x > 0.0))
      throw std::invalid_argument("heavy top: M, g, l and I1 must be finite and > 0");
  }
  if (!std::isfinite(p)) throw std::invalid_argument("heavy top: p_psi must be finite");
  // sqrt of a product of four rounded factors: relative error a few eps, against which the
  // factor (|p| - c) is exact when |p| and c are within a factor 2 (Sterbenz).
  const double c = 2.0 * std::sqrt(M * g * l * I1);
  return (std::abs(p) - c) * (std::abs(p) + c);
}

bool sleeping_top_is_stable(double p, double M, double g, double l, double I1) {
  return sleeping_top_discriminant(p, M, g, l, I1) >= 0.0;
}

void HeavyTop::validate() const {
  for (const double x : {M_kg, l_m, g_m_s2, I1_kgm2, I3_kgm2}) {
    if (!std::isfinite(x) || !(x > 0.0))
      throw std::invalid_argument("heavy top: M, l, g, I1 and I3 must be finite and > 0");
  }
}

HeavyTopConstants heavy_top_constants(const HeavyTop& top, const HeavyTopStart& s) {
  top.validate();
  const double st = std::sin(s.theta), ct = std::cos(s.theta);
  HeavyTopConstants c;
  c.w3 = s.phidot * ct + s.psidot;
  c.p_psi = top.I3_kgm2 * c.w3;
  c.p_phi = top.I1_kgm2 * s.phidot * st * st + c.p_psi * ct;
  const double V = top.M_kg * top.g_m_s2 * top.l_m * ct;
  c.energy_prime =
      0.5 * top.I1_kgm2 * (s.thetadot * s.thetadot + s.phidot * s.phidot * st * st) + V;
  c.energy = c.energy_prime + 0.5 * top.I3_kgm2 * c.w3 * c.w3;
  return c;
}

namespace {
// Roots of A x^2 + B x + C without cancellation (A != 0): x1 = q/A, x2 = C/q.
std::pair<double, double> quadratic_roots(double A, double B, double C) {
  const double D = B * B - 4 * A * C;
  if (D < 0) return {std::nan(""), std::nan("")};
  const double q = -0.5 * (B + std::copysign(std::sqrt(D), B));
  if (q == 0.0) return {0.0, 0.0};
  return {q / A, C / q};
}
}  // namespace

Nutation nutation_limits(const HeavyTop& top, const HeavyTopStart& s) {
  top.validate();
  const double u0 = std::cos(s.theta), s0 = std::sin(s.theta), s02 = s0 * s0;
  if (!(std::abs(s0) > 0.0)) {
    throw std::invalid_argument("heavy top: the axis starts vertical (sin theta0 = 0)");
  }
  const HeavyTopConstants k = heavy_top_constants(top, s);
  const double a = k.p_psi / top.I1_kgm2, b = k.p_phi / top.I1_kgm2;
  const double beta = 2 * top.M_kg * top.g_m_s2 * top.l_m / top.I1_kgm2;
  // f(u0 + d) = c0 + c1 d + c2 d^2 + beta d^3, expanded about the start (see the header).
  const double P = s.thetadot * s.thetadot + s.phidot * s.phidot * s02;
  const double c0 = s.thetadot * s.thetadot * s02;
  const double c1 = -beta * s02 - 2 * u0 * P + 2 * a * s.phidot * s02;
  const double c2 = 2 * u0 * beta - P - a * a;
  const auto g = [&](double d) { return c0 + d * (c1 + d * (c2 + d * beta)); };
  const double lo = -1 - u0, hi = 1 - u0;  // u = -1 and u = 1
  double d_min = 0, d_max = 0;
  if (c0 == 0.0) {
    // The start is a turning point; the motion sets off where f > 0, on c1's side (f ~ c1 d),
    // to the nearest root there of c1 + c2 d + beta d^2. Nearest overall would be wrong where
    // the other side's root is a pole: a pendulum released at rest (a = b = 0, roots at both
    // poles) falls, however near upright it starts. c1 = 0: a double root, steady precession.
    // A pole root may round past its pole: limited to [lo, hi] after the choice.
    const auto [r1, r2] = quadratic_roots(beta, c2, c1);
    double other = 0.0;
    for (const double r : {r1, r2}) {
      if (std::isfinite(r) && r * c1 > 0.0 && (other == 0.0 || std::abs(r) < std::abs(other)))
        other = r;
    }
    other = std::clamp(other, lo, hi);
    d_min = std::min(0.0, other);
    d_max = std::max(0.0, other);
  } else {
    // f(-1) = -(b + a)^2 <= 0 <= f(u0) = c0 <= ... f(1) = -(b - a)^2: one root on each side.
    const double f_lo = -(b + a) * (b + a), f_hi = -(b - a) * (b - a);
    const auto solve = [&](double x0, double x1, double f0, double f1) {
      std::uintmax_t iterations = 200;
      const auto r = boost::math::tools::toms748_solve(
          g, x0, x1, f0, f1, boost::math::tools::eps_tolerance<double>(52), iterations);
      return 0.5 * (r.first + r.second);
    };
    // Where f is zero at a pole (b = a: p_phi = p_psi, the axle can pass through the upright;
    // b = -a, through hanging; a = b = 0, a pendulum swinging in a plane, both), the limit on
    // that side is the pole only if f stays positive up to it. f = (1 -+ u) G(u), and G, a
    // quadratic, has its coefficients from the start without cancellation (alpha - beta u0 =
    // P): G(u0 + d) = thetadot^2 (1 +- u0) + (+-(P + a^2) - beta (1 +- u0)) d -+ beta d^2. Its
    // first root on that side, if short of the pole, is the limit, polished on f.
    const auto limit_before_pole = [&](double pole, double side) {
      const double one_pm_u0 = side > 0 ? 1 + u0 : 1 - u0;
      const auto [r1, r2] = quadratic_roots(-side * beta, side * (P + a * a) - beta * one_pm_u0,
                                            s.thetadot * s.thetadot * one_pm_u0);
      double limit = pole;
      for (const double r : {r1, r2}) {
        if (std::isfinite(r) && r * side > 0.0 && std::abs(r) < std::abs(limit)) limit = r;
      }
      if (limit == pole) return pole;
      const double beyond = 0.5 * (limit + pole);  // f < 0 between the root and the pole
      const double f_beyond = g(beyond);
      return f_beyond < 0.0 ? solve(std::min(0.0, beyond), std::max(0.0, beyond),
                                    side > 0 ? c0 : f_beyond, side > 0 ? f_beyond : c0)
                            : limit;
    };
    d_min = f_lo == 0.0 ? limit_before_pole(lo, -1.0) : solve(lo, 0.0, f_lo, c0);
    d_max = f_hi == 0.0 ? limit_before_pole(hi, 1.0) : solve(0.0, hi, c0, f_hi);
  }
  // A pole root found by the quadratic of a start at rest may be a rounding off the pole.
  constexpr double kPoleSlack = 8 * std::numeric_limits<double>::epsilon();
  Nutation n;
  if (b + a == 0.0 && lo < 0.0 && d_min <= lo * (1 - kPoleSlack)) {
    d_min = lo;
    n.through_hanging = true;
  }
  if (b - a == 0.0 && hi > 0.0 && d_max >= hi * (1 - kPoleSlack)) {
    d_max = hi;
    n.through_upright = true;
  }
  n.u_min = std::max(-1.0, u0 + d_min);
  n.u_max = std::min(1.0, u0 + d_max);
  n.d_min = std::max(d_min, lo);
  n.d_max = std::min(d_max, hi);
  n.theta_min = std::acos(n.u_max);
  n.theta_max = std::acos(n.u_min);
  return n;
}

std::optional<SteadyPrecession> steady_precession(const HeavyTop& top, double theta, double w3) {
  top.validate();
  const double c = std::cos(theta), Mgl = top.M_kg * top.g_m_s2 * top.l_m;
  const double p = top.I3_kgm2 * w3;
  const double D = p * p - 4 * top.I1_kgm2 * Mgl * c;
  if (D < 0 || (p == 0.0 && D == 0.0)) return std::nullopt;
  const double q = p + std::copysign(std::sqrt(D), p);
  SteadyPrecession out;
  out.slow = 2 * Mgl / q;
  out.fast = c == 0.0 ? std::numeric_limits<double>::infinity() : q / (2 * top.I1_kgm2 * c);
  return out;
}

}  // namespace wobble
