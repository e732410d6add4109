#pragma once
/// @file
/// A rotation matrix written as a product of turns about the axes, as the Euler angles' key
/// derives one: "Rz(φ) Ry(θ) Rz(ψ)", "R_z(phi)*R_y(theta)*R_z(psi)", "(Rz(φ)·Ry(θ))ᵀ" (the
/// transpose mark is the answer reader's), and PHY 711's "R_z(\psi)^T R_y(\theta)^T
/// R_z(\phi)^T": a factor transposed or inverted (ᵀ, ^T, ^{T}, ^\top, ', ⁻¹, ^-1, ^{-1}) is
/// the turn back, by minus its angle, and so is the whole product transposed or inverted by a
/// mark after its bracket or a program's call ("(Rz(φ) Ry(θ))⁻¹", "inv(..)", "transpose(..)",
/// NumPy's "np.linalg.inv(..)" and "(..).T", Mathematica's "Inverse[..]"): the turns back in
/// reverse order. Each factor is an active turn by its argument
/// (radians, or as the answer reader reads the argument) about x, y or z:
///   Rx(a) = [[1, 0, 0], [0, cos a, -sin a], [0, sin a, cos a]],
///   Ry(a) = [[cos a, 0, sin a], [0, 1, 0], [-sin a, 0, cos a]],
///   Rz(a) = [[cos a, -sin a, 0], [sin a, cos a, 0], [0, 0, 1]],
/// so that Rz(φ) Ry(θ) Rz(ψ) takes body components to space components (Taylor's convention).
/// The product is written out entry by entry, "[[cos(φ)*cos(θ)*.. + .., ..], ..]", for the
/// answer reader to read and the judge to simplify.
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace wobble::check {

/// The transpose marks after a closing bracket, as the answer reader reads them on a vector or a
/// matrix and here on a turn: "[1 2 3]ᵀ", "^T", LaTeX's "^{T}" and "^\top" (braced or not),
/// MATLAB's "'".
inline constexpr std::array<std::string_view, 6> kTransposeMarks{"ᵀ",      "^{T}", "^{\\top}",
                                                                 "^\\top", "^T",   "'"};

/// The most turns in one product: each entry of a product of n has up to 3^(n-1) terms.
inline constexpr int kMostTurns = 4;
/// The longest angle of a turn: each is written out up to 27 times in each of nine entries, so a
/// hostile angle of the answer's whole length would make megabytes (an Euler angle is a name).
inline constexpr std::size_t kLongestTurnAngle = 200;

/// The matrix a product of turns makes, as text; nullopt if `typed` is no such product (one
/// factor or more, nothing else but spaces and '*', '·', '⋅', or LaTeX's \cdot, \, or \;
/// between them, and one pair of
/// brackets around it all).
/// @throws InputError naming `field` for a product of more than kMostTurns turns, or a turn's
///   angle longer than kLongestTurnAngle.
std::optional<std::string> rotations_multiplied(const std::string& typed, const std::string& field);

}  // namespace wobble::check
