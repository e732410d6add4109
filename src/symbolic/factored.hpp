#pragma once
/// @file
/// Factoring polynomials over the rationals, with a cheap proof of irreducibility first.
///
/// GiNaC's factor() first makes its argument square-free (Yun's algorithm: multivariate gcds in
/// one symbol after another), then factors each part; on the polynomials of the larger inertia
/// tensors (seven symbols) one call took 41 ms. Most polynomials wobble factors are irreducible,
/// and that can usually be shown from univariate images, each a few microseconds:
/// p in Q[x, y...] with deg_x p = d >= 1 is irreducible when
///  - p is primitive in x (the gcd of its coefficients in x, polynomials in y..., is a number),
///  - and d = 1, or the image p(x, y = a...) at some integers a has degree d and is irreducible.
/// (A factorisation p = g h maps to one of the image, with both degrees kept since the leading
/// coefficients cannot vanish; a factor free of x would divide the content.) Primitivity is shown
/// the same way: a coefficient that is a number or a monomial (and no symbol dividing p), or two
/// coefficients whose images in each of their symbols have a constant gcd.
/// The integers are fixed primes, not random: the same input takes the same path in every run.
/// A difference of two squares of monomials, u^2 - v^2, splits into u - v and u + v, each
/// factored on (factor() took 0.25 ms for a^2 - b^2). Any other polynomial not shown
/// irreducible (reducible, or an unlucky image) goes to factor().
#include <ginac/ginac.h>

#include <utility>

namespace wobble::sym {

/// True only if `p`, an expanded polynomial in symbols with rational coefficients and two or more
/// terms, is shown irreducible over Q; false when it is not shown (it may still be).
bool shown_irreducible(const GiNaC::ex& p);

/// p = content * q for `p` as shown_irreducible() takes it: the content a number times a monomial
/// (each symbol to its lowest power in p), negative when every term of p is, so that q has a
/// positive term (as factor() writes it); q expanded. What factor() would take out of p first,
/// without factoring q.
std::pair<GiNaC::ex, GiNaC::ex> split_content(const GiNaC::ex& p);

/// GiNaC::factor(p); p itself (expanded, as given) when shown irreducible, without factoring.
/// factor() would return the same polynomial, but sometimes partly collected in one symbol
/// (4*M + 4*m1^2*(1+M) - 2*M*m1), chosen by GiNaC's run-dependent order. A product or power is
/// factored one explicit factor at a time, as factor() does, each through factored().
GiNaC::ex factored(const GiNaC::ex& p);

/// numerator / denominator, polynomials over Q, as {numerator, denominator} with each factor of
/// the denominator that is a sum (factored()'s) divided out of the numerator as often as it
/// divides it exactly: the sums the two share, found without a gcd (numer_denom()'s cost the
/// three-atom molecule's solve as much as simplify() saved by not proving sums irreducible). A
/// monomial the two share is left to GiNaC, which cancels it by itself in the quotient.
std::pair<GiNaC::ex, GiNaC::ex> sums_divided_out(const GiNaC::ex& numerator,
                                                 const GiNaC::ex& denominator);

}  // namespace wobble::sym
