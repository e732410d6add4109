#pragma once
/// @file
/// Exact inertia tensors in the parameters: the symbolic twins of core/inertia.hpp, same
/// conventions (I_ij = sum m (r^2 delta_ij - r_i r_j), one frame, SI).
#include <ginac/ginac.h>

#include <array>
#include <vector>

namespace wobble::sym {

using SymVec3 = std::array<GiNaC::ex, 3>;

struct SymPointMass {
  GiNaC::ex mass;
  SymVec3 r_O;
};

/// Mass, centre of mass and tensor about O, as exact expressions (entries normal()-ised).
struct SymMassProperties {
  GiNaC::ex mass = 0;
  SymVec3 r_cm{0, 0, 0};
  GiNaC::matrix I_O = GiNaC::matrix(3, 3);
};

/// m (|d|^2 1 - d d^T).
GiNaC::matrix parallel_axis_term(const GiNaC::ex& mass, const SymVec3& d);

/// Sum of the parallel-axis terms of the masses, total mass and centre of mass.
SymMassProperties mass_properties(const std::vector<SymPointMass>& masses);

/// The properties of a body placed with its centre of mass at r_cm, given its tensor about the
/// centre of mass: I_O = I_cm + parallel_axis_term(mass, r_cm).
SymMassProperties placed(const GiNaC::ex& mass, const GiNaC::matrix& I_cm, const SymVec3& r_cm);

/// Sum of parts about the same O.
SymMassProperties combine(const std::vector<SymMassProperties>& parts);

/// Each entry simplified (see simplify()); an entry equal to its mirror image is simplified once.
GiNaC::matrix normalized(const GiNaC::matrix& m);

}  // namespace wobble::sym
