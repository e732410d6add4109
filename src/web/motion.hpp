#pragma once
/// @file
/// The motion for the page's 3-D view, as JSON: the body as drawn (its shapes, point masses, or
/// for a tensor given directly the box with the same moments), and its attitude sampled in time
/// by wobble's own solution (the exact free-body solution when torque-free, else the scene's
/// integrator), which the page interpolates with quaternion slerp.
///
/// Frames and units: the body is drawn in the frame B its file is written in, with the turning
/// point (centre of mass, pivot or origin O: simulate/scene_setup.hpp) at the origin; space S
/// is z up. Each sample holds t (s), the attitude q_BtoS as (w, x, y, z), w in the body divided
/// by |w(0)|, and the direction of L in space. Magnitudes are left out on purpose: the samples
/// are shown to students, and |w| or |L| can be a key's answer. Directions, quaternions and
/// angles are rounded to kDirectionStep, lengths and times to 6 significant digits: finer than
/// a pixel, and never a key's value to its printed digits. (The motion itself is there to be
/// watched: as from a film of it, a patient student can measure an angle or a period.)
///
/// Sampling: every step of the attitude turns at most kMaxTurnPerSample, so slerp between two
/// samples stays on the motion to the eye; the span shows what the motion is about (two space
/// precessions of a symmetric top, two periods of an asymmetric one, about one precession of a
/// heavy top; a scene's own t_end), shortened if it would need more than kMaxSamples.
#include <string>
#include <vector>

#include "problem/problem.hpp"
#include "problem/scene.hpp"

namespace wobble::web {

inline constexpr double kMaxTurnPerSample = 0.2;  ///< rad
inline constexpr double kDirectionStep = 1e-5;
inline constexpr int kMaxSamples = 3001;
inline constexpr int kMinSamples = 241;

/// Whether the problem has a motion to show (a dynamics solver: simulate/problem_scene.hpp).
bool has_motion(const Problem& problem);

/// The problem's motion at the values of the assignments ("NAME=VALUE", a variant's).
/// @throws InputError if it has none, or as the simulation does.
std::string problem_motion_json(const Problem& problem,
                                const std::vector<std::string>& assignments);

/// A scene's motion at its defaults (its own t_end and method).
std::string scene_motion_json(const Scene& scene);

}  // namespace wobble::web
