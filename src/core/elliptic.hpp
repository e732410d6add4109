#pragma once
/// @file
/// Jacobi elliptic functions driven by the complementary parameter.
///
/// Why not Boost.Math's `jacobi_elliptic`: it takes the modulus k, and near the separatrix of a
/// free body (k -> 1) the motion is decided by k'^2 = 1 - k^2, which k rounded to double no
/// longer carries (k'^2 = 1e-16 gives k == 1 exactly); Boost 1.74's dn also loses accuracy near
/// u = K (see shared numerics notes). This routine takes k'^2 itself, computed by the caller in
/// factored form, and stays accurate down to k'^2 = 1e-16 (tests/core/test_elliptic.cpp measures
/// it against Boost.Math at 50 digits). The elliptic integrals come from Boost.Math (Carlson).
#include <cmath>

#include "core/double_double.hpp"

namespace wobble {

struct SnCnDn {
  double sn, cn, dn;
};

/// sn, cn, dn of u for parameter m = k^2 = 1 - kc2, 0 <= kc2 <= 1 (Bulirsch's descending
/// Landen/AGM algorithm, 1965). kc2 == 0 gives tanh, sech, sech. Accurate for |u| <= K; reduce
/// larger arguments by the periods first.
SnCnDn jacobi_sncndn(double u, double kc2);

/// K(k) = R_F(0, kc2, 1) for kc2 = 1 - k^2 > 0.
double complete_K(double kc2);

/// F(phi | k) for |phi| <= pi/2, from sin and cos of phi: sin R_F(cos^2, cos^2 + kc2 sin^2, 1).
double incomplete_F(double sin_phi, double cos_phi, double kc2);

/// (Pi(n; phi | k) - F(phi | k)) / n for |phi| <= pi/2, n <= 1, without the cancellation of the
/// difference: sin^3 R_J(cos^2, cos^2 + kc2 sin^2, 1, 1 - n sin^2) / 3. For n > 0 give the
/// complement one_minus_n = 1 - n, formed without cancellation by the caller: R_J's last
/// argument is then (1 - n) + n cos^2, which keeps its digits where n sin^2 is near 1 (n within
/// eps of 1 rounds to 1, and 1 - n sin^2 to 0 at phi = pi/2, where R_J is infinite; the excess
/// itself is large but finite there). Without it, 1 - n.
double third_kind_excess(double sin_phi, double cos_phi, double kc2, double n, double one_minus_n);
double third_kind_excess(double sin_phi, double cos_phi, double kc2, double n);

/// The complete counterpart: (Pi(n | k) - K(k)) / n = R_J(0, kc2, 1, 1 - n) / 3, kc2 > 0.
double complete_third_kind_excess(double kc2, double n);

/// An argument reduced by the period 2K that sn and cn have up to sign: u = r + 2 K j with r
/// in [-K, K], and sn, cn, dn of r (of u itself: sn and cn times (-1)^j, dn the same). K
/// infinite (the separatrix, kc2 = 0): no reduction, j = 0.
struct ReducedArgument {
  double j = 0.0, r = 0.0;
  SnCnDn of_r{};
  /// (-1)^j: sn(u) = sign() sn(r), cn(u) = sign() cn(r).
  double sign() const { return std::fmod(j, 2.0) == 0.0 ? 1.0 : -1.0; }
};
ReducedArgument reduce_by_half_period(double u, double K, double kc2);
/// The same for u and K to double-double (kc2 > 0): r = u - 2 K j formed in double-double, so
/// that r keeps the digits of u and K however many periods u spans (in double, u's rounding,
/// eps |u|, would be r's error); near +-K, cn from K - |r| in double-double, so that it keeps
/// its relative digits where it is small.
ReducedArgument reduce_by_half_period(const DoubleDouble& u, const DoubleDouble& K, double kc2);

/// K(k) to double-double, from k'^2 to double-double (0 < kc2 <= 1): pi / (2 AGM(1, k')),
/// the arithmetic-geometric mean iterated in double-double until its two means agree.
DoubleDouble complete_K_dd(const DoubleDouble& kc2);

/// complete_third_kind_excess to double-double, (Pi(n | k) - K(k)) / n for n < 1, from the
/// complement one_minus_n = 1 - n > 0 formed by the caller (n within 1e-32 of 1, as a top
/// released near upright has it, leaves 1 - n no digit when formed from n, even in
/// double-double): Bulirsch's cel(k', p, 0, 1) (Numer. Math. 13, 1969), p = 1 - n, a
/// quadratically convergent Landen iteration of sums, products, quotients and square roots
/// only, here in double-double.
DoubleDouble complete_third_kind_excess_dd(const DoubleDouble& kc2,
                                           const DoubleDouble& one_minus_n);

/// Pi(n; phi | k) for n < 0 without its cancellation (A&S 17.7.15; Boost.Math's ellint_3
/// takes n < 0 so; the heavy top needs it for n < -1). Written Pi(n) = F + n G_n, the two
/// terms are large and nearly cancel when n << -1 (Pi(n) ~ pi / (2 sqrt(-n)) while F ~ K), and
/// G_n's rounding times n is then an error of eps K. With N = (k^2 - n) / (1 - n) in (k^2, 1),
///   Pi(n; phi) = linear F(phi) + excess_coef G_N(phi) + atan_coef atan(atan_p sin cos / delta),
///   linear = A + B, excess_coef = A N, atan_coef = C, atan_p = sqrt(-n N),
///   A = -n k'^2 / ((1 - n)(k^2 - n)), B = k^2 / (k^2 - n), C = sqrt(-n / ((1 - n)(k^2 - n))),
/// G_N = third_kind_excess(..., N, one_minus_N), 1 - N = k'^2 / (1 - n) without cancellation,
/// delta = sqrt(1 - k^2 sin^2): every term of Pi's sign (A, B, C, N > 0), so none is larger.
/// For |phi| <= pi/2; past it G_N continues through the periods and the arctangent, whose
/// period is sin cos's, repeats. The caller gives 1 - n, k^2 and k'^2 in double-double (each
/// formed without cancellation); the coefficients come in double-double for a caller that
/// multiplies them by a growing phase.
struct NegativeThirdKind {
  DoubleDouble N, one_minus_N;  ///< G_N's characteristic and its complement
  DoubleDouble linear;          ///< A + B, F's coefficient
  DoubleDouble excess_coef;     ///< A N, G_N's coefficient
  DoubleDouble atan_coef;       ///< C (dimensionless, as Pi)
  double atan_p = 0.0;          ///< sqrt(-n N)
};
NegativeThirdKind negative_third_kind(const DoubleDouble& n, const DoubleDouble& one_minus_n,
                                      const DoubleDouble& k2, const DoubleDouble& kc2);
/// The arctangent of that form at a reduced argument r (|r| <= K): atan(p sn cn / dn). cn is
/// taken as |cn|: r may pass +-K by a rounding, where cn < 0, and G_N (of cn^2) takes r as
/// reflected there, so the arctangent must too, or their sum breaks by p C times the rounding.
/// On the separatrix (k' = 0) cn = dn = sech: where both underflow to 0, cn / dn is its limit 1.
double negative_third_kind_atan(double atan_p, const SnCnDn& of_r);

/// (Pi(n; am u | k) - u) / n for any u, continued past |u| = K through the periods: 2 j times
/// `complete` (complete_third_kind_excess(kc2, n)) plus the incomplete excess of r.
double third_kind_excess(const ReducedArgument& a, double kc2, double n, double complete);

}  // namespace wobble
