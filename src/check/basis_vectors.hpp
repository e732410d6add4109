#pragma once
/// @file
/// Unit vectors as students write them after a component, rewritten to the one spelling the
/// answer reader knows (answer_reading.cpp reads a sum of components along them as a vector):
/// - the space basis: "x̂", "î" as typed, and LaTeX's "\hat{x}", "\hat\imath", "\hat{i}",
///   "\mathbf{i}", "\boldsymbol{\hat{k}}", "\hat{\mathbf{z}}" (x, y, z with a hat; i, j, k with a
///   hat or in bold) -> "x̂", "î", .. (the precomposed forms where Unicode has them);
/// - the space basis in ASCII, as plain text and chat write it: "ihat", "i_hat", "i-hat",
///   "x^" (before a sign, a bracket's end, a comma, a unit or the end), "e_x" -> "î", "x̂", ..
///   (only where the letter is no symbol of the problem);
/// - the body basis, the problem statements' e₁, e₂, e₃: "e₁", "e1", "e_1", "ê₁", "e_{1}",
///   "\hat{e}_1", "\mathbf{e}_1", "\vec{e}_{1}", "\hat{\mathbf{e}}_1" -> "ê₁", "ê₂", "ê₃".
/// - the primed basis of the Euler angles (the body's before the last turn), "e₂′", "e_2'",
///   "\hat{e}_2'", "e_2^\prime" -> "ê₁′", "ê₂′", "ê₃′".
/// A bare e1 glued to a number ("2e1" is 20) or one that is the problem's own symbol is left as
/// it is.
#include <string>

#include "symbolic/expression.hpp"

namespace wobble::check {

/// The body basis as the rewriting spells it, e₁ to e₃ in order, then the primed basis.
inline constexpr const char* kBodyUnitVectors[6] = {"ê₁", "ê₂", "ê₃", "ê₁′", "ê₂′", "ê₃′"};

/// `typed` with each unit vector spelled as above; `typed` itself where it has none.
std::string basis_vectors_spelled(const std::string& typed, const sym::SymbolTable& table);

}  // namespace wobble::check
