#pragma once
/// @file
/// Answers as a program writes them, rewritten in the reader's notation. A student who computes
/// in Mathematica, Python or MATLAB pastes what it shows:
/// - Mathematica: calls in square brackets, `Sqrt[x]`, `Cos[α]`, `ArcTan[x, y]` (atan2(y, x):
///   its arguments the other way), `N[..]` (the value of what it holds); numbers as InputForm
///   prints them, `2.395*^-7`; `Pi`; `Degree` (π/180: `30 Degree`).
/// - Python: a module before a function or pi, `np.sqrt`, `math.pi`, `numpy.arctan2`,
///   `sp.cos`, `scipy.special.ellipk`; `np.radians(x)`, `math.radians(x)`, `np.deg2rad(x)`.
///   A complex number with no imaginary part, as np.roots gives a real root, `4.995+0.j`, is its
///   real part.
/// - MATLAB: the element-wise operators `.^`, `.*`, `./`.
/// - Maple and Julia: the arctangent of two arguments, `arctan(y, x)`, `atan(y, x)`, as atan2(y,
///   x) (the same order); Maple's `evalf(..)`.
///
/// The complete elliptic integrals take the modulus k in wobble, as in GiNaC and as its keys print
/// them, `EllipticK(k)`; Mathematica's `EllipticK[m]`, SciPy's `ellipk(m)`, SymPy's
/// `elliptic_k(m)` and MATLAB's `ellipke(m)` take the parameter m = k². Each is read as its program
/// means it, `EllipticK(sqrt(m))`, so that a value right in the program is right here.
///
/// ASCII in, ASCII out (the reader's to_ascii has run); names not listed here are left alone,
/// and so are a program's containers (`np.array(..)`, `DiagonalMatrix[..]`), which the reader
/// unwraps itself.
#include <optional>
#include <string>
#include <vector>

namespace wobble::check {

/// `text` with every notation above in the reader's: `Sqrt[m]/EllipticK[0.3]` ->
/// `sqrt(m)/EllipticK(sqrt(0.3))`, `np.sqrt(2)*math.pi` -> `sqrt(2)*pi`, `R.^2` -> `R^2`.
std::string as_programs_mean(const std::string& text);

/// `text` with each `EllipticK(x)` and `EllipticE(x)` read as taking the parameter, `EllipticK(
/// sqrt(x))`, or nullopt where it calls neither: what a wrong answer meant if its integrals'
/// arguments are k² (as Mathematica's and SciPy's take them).
std::optional<std::string> elliptic_of_parameter(const std::string& text);

/// `text` with the two arguments of one two-argument arctangent swapped: atan2(y, x), arctan2,
/// Mathematica's ArcTan[x, y], Maple's and Julia's arctan(y, x) and atan(y, x). One text per
/// such call, in order, with the call's name as written: what a wrong answer meant if its
/// arguments are in another program's order (Mathematica's ArcTan takes x first).
struct SwappedArctangent {
  std::string text, name;
};
std::vector<SwappedArctangent> arctangents_swapped(const std::string& text);

}  // namespace wobble::check
