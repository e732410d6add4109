#pragma once
/// @file
/// Double-double numbers: an unevaluated sum hi + lo with |lo| <= ulp(hi) / 2, about 106 bits,
/// for the few quantities whose rounding would otherwise grow with time: the exact solutions'
/// phase u0 + lambda t and its reduction by the period (core/exact_free_body.hpp). Products are
/// exact by fma (two_prod), sums by Knuth's two_sum; the operations are those of Dekker (1971)
/// and the QD library (Hida, Li, Bailey), relative error a few 2^-104. Boost 1.74, the version
/// Debian 12 ships, has no double-double type (cpp_double_double came in Boost 1.86), and its
/// software quad (cpp_bin_float_quad) costs ~100x more per operation, which the phase, evaluated
/// at every sample, cannot afford.
#include <cmath>

namespace wobble {

struct DoubleDouble {
  double hi = 0.0, lo = 0.0;

  DoubleDouble() = default;
  DoubleDouble(double x) : hi(x) {}  // NOLINT(google-explicit-constructor): exact widening
  DoubleDouble(double h, double l) : hi(h), lo(l) {}

  /// The nearest double.
  double value() const { return hi + lo; }
};

/// a + b = s + e exactly (Knuth).
inline DoubleDouble two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

/// a * b = p + e exactly (one fma).
inline DoubleDouble two_prod(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

namespace dd_detail {
// hi + lo renormalised, |lo| small against hi (Dekker's fast two-sum).
inline DoubleDouble quick_two_sum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}
}  // namespace dd_detail

inline DoubleDouble operator+(const DoubleDouble& a, const DoubleDouble& b) {
  DoubleDouble s = two_sum(a.hi, b.hi);
  const DoubleDouble t = two_sum(a.lo, b.lo);
  s.lo += t.hi;
  s = dd_detail::quick_two_sum(s.hi, s.lo);
  s.lo += t.lo;
  return dd_detail::quick_two_sum(s.hi, s.lo);
}

inline DoubleDouble operator-(const DoubleDouble& a) {
  return {-a.hi, -a.lo};
}

inline DoubleDouble operator-(const DoubleDouble& a, const DoubleDouble& b) {
  return a + (-b);
}

inline DoubleDouble operator*(const DoubleDouble& a, const DoubleDouble& b) {
  DoubleDouble p = two_prod(a.hi, b.hi);
  p.lo += a.hi * b.lo + a.lo * b.hi;
  return dd_detail::quick_two_sum(p.hi, p.lo);
}

inline DoubleDouble operator/(const DoubleDouble& a, const DoubleDouble& b) {
  // Long division: a quotient digit, the remainder exactly, a second digit, a third.
  const double q1 = a.hi / b.hi;
  DoubleDouble r = a - b * DoubleDouble(q1);
  const double q2 = r.hi / b.hi;
  r = r - b * DoubleDouble(q2);
  const double q3 = r.hi / b.hi;
  return dd_detail::quick_two_sum(q1, q2) + DoubleDouble(q3);
}

/// sqrt(a), a >= 0: one Newton step from the double root (Karp and Markstein).
inline DoubleDouble sqrt(const DoubleDouble& a) {
  if (!(a.hi > 0.0)) return {0.0, 0.0};
  const double x = 1.0 / std::sqrt(a.hi), ax = a.hi * x;
  const DoubleDouble residual = a - two_prod(ax, ax);
  return two_sum(ax, residual.hi * (x * 0.5));
}

/// pi to double-double.
inline DoubleDouble dd_pi() {
  return {3.141592653589793116e+00, 1.224646799147353207e-16};
}

/// x - 2 pi q, q the nearest whole number of turns, rounded to double: an angle that keeps its
/// last digits however many turns x holds (|x| below 2^52 turns, q exact in a double).
inline double remainder_two_pi(const DoubleDouble& x) {
  const DoubleDouble two_pi(2.0 * dd_pi().hi, 2.0 * dd_pi().lo);
  const double turns = std::nearbyint(x.hi / two_pi.hi);
  return (x - (two_prod(turns, two_pi.hi) + DoubleDouble(turns * two_pi.lo))).value();
}

}  // namespace wobble
