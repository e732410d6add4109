#pragma once
/// @file
/// Euler's torque-free equations written out as the answer to "find the coefficients": the
/// equations dω_i/dt = c_i ω_j ω_k, (i, j, k) a cyclic order of 1, 2, 3, read as the vector
/// (c₁, c₂, c₃) a key gives. A student writes the equations a question shows, and the key's own
/// step prints them so: "dω₁/dt = -0.965066 ω₂ ω₃, dω₂/dt = 0.99115 ω₃ ω₁, ...".
#include <optional>
#include <string>
#include <vector>

#include "symbolic/expression.hpp"

namespace wobble::check {

/// Equations in LaTeX, "\dot\omega_1 = -0.5\,\omega_2\omega_3, ..", in the plain text
/// euler_equation_coefficients reads ("omegadot1 = -0.5*omega2*omega3, .."): read as any LaTeX
/// answer is, with the body's components of ω and their derivatives known besides `table`'s
/// symbols; the LaTeX key's source of its step, "$\mathrm{d}\omega_{1}/\mathrm{d}t$ = $-$0.5
/// $\omega_2$ $\omega_3$, ..", as one formula. Any other text, LaTeX that does not read so
/// included, as it is.
std::string euler_equations_as_text(const std::string& typed, const sym::SymbolTable& table);

/// Euler's equations as read: the vector of their coefficients, or what is wrong with them.
struct EulerEquations {
  /// "[-0.9651, 0.9912, -0.6]"; empty where a right side has other components than its
  /// equation's (then `wrong_products` says which).
  std::string coefficients;
  /// One line for each equation whose right side is no coefficient times the other two
  /// components: "dω₃/dt = c₃ ω₁ ω₂, and yours has ω₁ ω₃".
  std::vector<std::string> wrong_products;
};

/// "dω₁/dt = -0.9651 ω₂ ω₃, dω₂/dt = 0.9912 ω₃ ω₁, dω₃/dt = -0.6 ω₁ ω₂" read as the coefficients
/// "[-0.9651, 0.9912, -0.6]": three equations parted by ',', ';' or line breaks, in any order,
/// each a derivative of one component of ω (dω₁/dt, ω̇₁, ω₁', in ASCII domega1/dt, dw1/dt,
/// omega1dot, w1') equal to a coefficient times the other two components (ω₂ ω₃, ω₃·ω₂, w2*w3,
/// a bare ω₂ω₃ for a coefficient 1, "-ω₂ ω₃" for -1). The coefficient may be any expression; it
/// is left for the reader. A right side that is a product of other components (ω₁ ω₃, ω₂²)
/// is read as a wrong equation. nullopt for any other text, and for right sides with no
/// component of ω at all (the coefficients labelled by their equations, read elsewhere).
/// @throws InputError naming `field` for such equations that are not one for each component
///   (two of them, or dω₁/dt twice), saying which is missing or twice.
std::optional<EulerEquations> read_euler_equations(const std::string& typed,
                                                   const std::string& field);

}  // namespace wobble::check
