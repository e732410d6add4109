#pragma once
/// @file
/// Euler angles, for input and output only (orientation is never integrated as angles: they are
/// singular at theta = 0 and pi).
///
/// R_BtoS = Rz(phi) Ra(theta) Rz(psi), a = y (z-y-z, Taylor's convention) or x (z-x-z,
/// Goldstein's): rotate by phi about z, then by theta about the new a axis (the line of nodes
/// for z-x-z), then by psi about the new z (the body's e3). Angles in rad.
#include <string>

#include "core/inertia.hpp"

namespace wobble {

enum class EulerConvention { zyz, zxz };

/// @throws std::invalid_argument for a name other than "zyz" or "zxz".
EulerConvention euler_convention(const std::string& name);

Mat3 rotation_from_euler(const Vec3& phi_theta_psi, EulerConvention c);

/// The angles of a rotation: theta in [0, pi], phi and psi in (-pi, pi]. At theta = 0 or pi
/// (sin(theta) within 8 eps of 0, rounding noise) only phi + psi (or phi - psi) is defined: psi is
/// set to 0 and the whole turn given to phi. Next to them (sin(theta) ~ 1e-12) phi alone is poorly
/// determined, but psi is taken from the well-conditioned sum or difference, so the angles give
/// back the rotation to a few eps.
Vec3 euler_from_rotation(const Mat3& R_BtoS, EulerConvention c);

}  // namespace wobble
