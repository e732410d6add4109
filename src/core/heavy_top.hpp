#pragma once
/// @file
/// The heavy symmetric top with a fixed point: closed forms that need care in floating point.
///
/// Conventions (SI): M mass (kg), l distance pivot -> centre of mass along the symmetry axis (m),
/// g (m/s^2), I1 the moment about a transverse axis through the pivot (kg m^2), p_psi = I3 w3
/// the conserved momentum about the symmetry axis (kg m^2/s).
namespace wobble {

/// The sleeping (vertical) top is stable when p_psi^2 >= 4 M g l I1. The discriminant is taken
/// in factored form, (|p| - 2 sqrt(M g l I1)) (|p| + 2 sqrt(M g l I1)), so that its sign is right
/// next to the threshold (p^2 - 4 M g l I1 rounds both terms and then cancels).
/// @throws std::invalid_argument unless M, g, l, I1 are finite and > 0 and p is finite.
double sleeping_top_discriminant(double p_psi, double M_kg, double g_m_s2, double l_m,
                                 double I1_kgm2);
bool sleeping_top_is_stable(double p_psi, double M_kg, double g_m_s2, double l_m, double I1_kgm2);

}  // namespace wobble
