#pragma once
/// @file
/// What the dynamics solvers require of a body, written once with one message each. Each check
/// is exact: it holds identically in the parameters (GiNaC), not just at the values, so a
/// variant can never break it. `who` names the solver in the message ("the heavy_top solver").
///
/// Messages: "FILE: body: WHO needs ..., but ...", and where another solver takes the body,
/// its name.
#include <string>

#include <ginac/ginac.h>

#include "solvers/inertia_body.hpp"

namespace wobble {

/// The tensor about the centre of mass, or the tensor given (a tensor given directly has no
/// mass and is taken as about the centre).
GiNaC::matrix tensor_about_centre(const BodyContext& body);

/// A mass and a centre of mass: masses or shapes, not a tensor given directly.
void require_mass(const BodyContext& body, const std::string& who);

/// Principal axes along x, y, z: every product of inertia of `I` is zero. `about` says which
/// tensor ("about the centre of mass", "about the pivot"); `instead` names a solver that takes
/// the body otherwise, or is empty.
void require_principal_axes_along_xyz(const BodyContext& body, const GiNaC::matrix& I,
                                      const std::string& who, const std::string& about,
                                      const std::string& instead = "");

/// Symmetric about z: principal axes along x, y, z and I_xx = I_yy.
void require_symmetric_about_z(const BodyContext& body, const GiNaC::matrix& I,
                               const std::string& who, const std::string& about,
                               const std::string& instead = "");

/// The centre of mass on the z axis (x = y = 0).
void require_centre_on_z(const BodyContext& body, const std::string& who);

}  // namespace wobble
