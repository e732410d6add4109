#pragma once
/// @file
/// Uniform solid shapes: their inertia tensors about their own centre of mass.
///
/// Every shape is centred at its centre of mass with its edges or symmetry axis along the frame
/// axes (conventions of inertia.hpp: SI units, I_ij = int (r^2 delta_ij - r_i r_j) dm):
///
///     kind      sizes    geometry                                   I_cm / mass
///     box       a, b, c  edges a, b, c along x, y, z                diag(b²+c², a²+c², a²+b²)/12
///     plate     a, b     thin rectangle in the x-y plane            diag(b², a², a²+b²)/12
///     disc      R        thin disc in the x-y plane, axis z         diag(1/4, 1/4, 1/2) R²
///     cylinder  R, h     solid, axis z, height h                    diag(R²/4+h²/12, same, R²/2)
///     sphere    R        solid ball                                 (2/5) R² 1
///     rod       L        thin rod along z                           diag(L²/12, L²/12, 0)
///     cone      R, h     solid right cone, axis z, apex up: apex    diag(3R²/20+3h²/80, same,
///                        at z = 3h/4, base (radius R) at z = -h/4   3R²/10)
///     ring      R        thin hoop in the x-y plane, axis z         diag(1/2, 1/2, 1) R²
///     shell     R        thin spherical shell                       (2/3) R² 1
///
/// A shape is one entry of the table in shapes.cpp (name, sizes, this closed form) and its enum
/// value; symbolic/shape_integrals derives each tensor again by integration, and the two are
/// tested against each other.
#include <string>
#include <string_view>
#include <vector>

#include "core/inertia.hpp"

namespace wobble {

enum class ShapeKind { box, plate, disc, cylinder, sphere, rod, cone, ring, shell };

/// Every kind, in the table's order.
std::vector<ShapeKind> shape_kinds();

/// The kind named `name` ("box", "plate", ...).
/// @throws std::invalid_argument for an unknown name (the message lists the known ones).
ShapeKind shape_kind_from_name(std::string_view name);
std::string_view shape_kind_name(ShapeKind kind);
/// The size names of a kind, in order (box: a, b, c; disc: R; ...).
const std::vector<std::string>& shape_size_names(ShapeKind kind);

/// Inertia tensor (kg m^2) about the centre of mass of a uniform shape of mass mass_kg whose
/// sizes (m) are given in the order of shape_size_names.
/// @throws std::invalid_argument if the mass or a size is not finite and > 0, or the count of
///         sizes is wrong.
Mat3 shape_inertia_about_cm(ShapeKind kind, double mass_kg, const std::vector<double>& sizes_m);

}  // namespace wobble
