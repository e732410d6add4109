#pragma once
/// @file
/// The inertia solver (`solver = "inertia"`): a body of point masses and/or uniform shapes, or a
/// tensor given directly, and any of these quantities as answers (README, "Solvers"):
/// | quantity            | what                                              | unit    |
/// |---------------------|---------------------------------------------------|---------|
/// | mass                | total mass                                        | kg      |
/// | I                   | inertia tensor about the origin O                 | kg m^2  |
/// | center_of_mass      | centre of mass, from O                            | m       |
/// | I_cm                | inertia tensor about the centre of mass           | kg m^2  |
/// | principal_moments   | principal moments about O, ascending              | kg m^2  |
/// | principal_axes      | principal axes about O (columns e1, e2, e3)       | 1       |
/// | principal_moments_cm, principal_axes_cm | the same about the centre of mass |      |
#include "problem/problem.hpp"
#include "solvers/key.hpp"

namespace wobble {

/// @throws InputError: see build_inertia_body; also an unknown quantity, or a quantity that
///         needs a mass when the tensor is given directly.
Key solve_inertia(const Problem& problem, const sym::Values& values);

}  // namespace wobble
