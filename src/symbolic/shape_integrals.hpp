#pragma once
/// @file
/// Inertia tensors of uniform shapes derived by exact integration (GiNaC), independently of the
/// closed forms in core/shapes.hpp; geometry and conventions as there.
///
/// Method: the second moments S_ij = int x_i x_j dm about the centre of mass are diagonal for
/// these shapes, and I = tr(S) 1 - S. Each S_ii is a polynomial integral: Cartesian for the box,
/// plate and rod; over radius with the axial (disc, cylinder) or spherical symmetry used to share
/// int r^2 dm between the axes for the round shapes. The density is the mass over the volume
/// (area, length), itself integrated.
#include <ginac/ginac.h>

#include <string>
#include <vector>

#include "core/shapes.hpp"

namespace wobble::sym {

struct ShapeDerivation {
  GiNaC::matrix I_cm = GiNaC::matrix(3, 3);  ///< diagonal, entries normal()-ised
  /// Readable steps: the integrals set up, written with the shape's own size names.
  struct Step {
    std::string text;   ///< plain text (Unicode)
    std::string latex;  ///< the same in LaTeX math
  };
  std::vector<Step> steps;
};

/// @param sizes expressions in the order of shape_size_names(kind)
ShapeDerivation derive_shape_inertia(wobble::ShapeKind kind, const GiNaC::ex& mass,
                                     const std::vector<GiNaC::ex>& sizes);

}  // namespace wobble::sym
