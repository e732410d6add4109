#pragma once
/// @file
/// A scene as data: what a `scenes/<id>.toml` file holds (see README, "Scene files").
///
/// The body uses the problem files' schema (parameters, masses, shapes or a tensor). Vectors
/// "in the body frame" are components along the axes the body is written in (frame B, origin O
/// of the file), which turn with the body; "space" is the inertial frame S, z up. Expressions
/// are kept as text and evaluated by the simulation layer, so messages can name their field.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "problem/problem.hpp"

namespace wobble {

using Expr3 = std::array<std::string, 3>;

enum class Frame { body, space };

/// The orientation at t = 0 (body B -> space S). Exactly one of the forms, identity if none.
struct OrientationSpec {
  enum class Kind { identity, quaternion, matrix, euler } kind = Kind::identity;
  std::array<std::string, 4> quaternion;  ///< (w, x, y, z); must be unit to 1e-12
  std::array<Expr3, 3> matrix;            ///< rows; must be a rotation to 1e-12
  Expr3 euler;                            ///< angles (phi, theta, psi), rad (or "30deg")
  std::string convention = "zyz";         ///< core/euler_angles.hpp
};

struct GravitySpec {
  std::string g = "9.80665";   ///< m/s^2, acting along -z in space
  Expr3 pivot{"0", "0", "0"};  ///< the fixed point, body frame, m
};

struct FreeFlightSpec {
  std::string g = "9.80665";
  Expr3 position{"0", "0", "0"};  ///< centre of mass at t = 0, space, m
  Expr3 velocity{"0", "0", "0"};  ///< m/s
};

struct TorqueSpec {
  Expr3 value;  ///< N m
  Frame frame = Frame::body;
  /// A friction brake: the torque (fixed in the body, along a symmetry axis) opposes the spin
  /// about its axis until that spin stops, then acts no more; it never spins a wheel backwards.
  bool brake = false;
};

/// The relative tolerances a scene may ask of the adaptive methods. Below 1e-14 each step's own
/// rounding (a few eps, over the thousands of steps of a run) is larger than what is asked, so
/// the tolerance could not be met; above 1e-2 the error estimate of a pair is no longer small
/// against the solution it estimates. The same limits hold in a scene file and for --tolerance.
inline constexpr double kMinSceneTolerance = 1e-14, kMaxSceneTolerance = 1e-2;
/// The sample counts: at least both ends of the run; at most a million (written in bounded
/// memory: simulate/row_store.hpp).
inline constexpr long kMinSamples = 2, kMaxSamples = 1000000;
/// A scene's tolerance when its file gives none: ten digits, what the tables print.
inline constexpr double kDefaultSceneTolerance = 1e-10;
/// "1e-14 to 1e-2" and "2 to 1000000", for the messages that state the limits.
std::string scene_tolerance_range();
std::string scene_samples_range();

struct Scene {
  /// id, title, statement (the scene's description), parameters and body, as in a problem.
  Problem model;
  Expr3 omega;  ///< initial angular velocity, rad/s
  Frame omega_frame = Frame::body;
  OrientationSpec orientation;
  std::optional<GravitySpec> gravity;
  std::optional<FreeFlightSpec> free_flight;
  std::optional<TorqueSpec> torque;
  std::vector<std::string> outputs;  ///< names from scene_output_names(), in the file's order
  std::string t_end = "10";          ///< s, > 0
  int samples = 101;                 ///< output times, evenly spaced over [0, t_end], >= 2
  double tolerance = kDefaultSceneTolerance;  ///< relative, in [kMin.., kMaxSceneTolerance]
  std::string method = "auto";       ///< auto or a name from simulation_method_names()
  std::optional<std::string> step;   ///< s, fixed-step methods only
};

/// Every output a scene may ask for, with a one-line description each.
const std::vector<std::pair<std::string, std::string>>& scene_output_names();

/// @throws InputError "FILE:LINE: FIELD: what" for a malformed file, an unknown key, effect or
///   output, a missing field, a bad count or tolerance, or two orientations given at once.
Scene load_scene(const std::filesystem::path& file);
/// The same from text already read (`name` stands for the file in messages): for the fuzzers.
Scene load_scene_text(const std::string& text, const std::filesystem::path& name);

/// The folder of the example scenes (io/data_dir.hpp says where).
std::filesystem::path scenes_dir();

/// Every scene in scenes_dir(), sorted by id; each file's id must equal its file name.
/// @throws InputError for the first bad file.
std::vector<Scene> load_scenes();

/// Resolves "ID" (scenes_dir()/ID.toml) or a path to a .toml file, and loads it.
/// @throws InputError for an unknown id (listing the known ones) or a bad file.
Scene find_scene(const std::string& id_or_file);

}  // namespace wobble
