#pragma once
/// @file
/// A problem as data: what a `problems/<id>.toml` file holds (see README, "Problem files").
///
/// Expressions (masses, positions, sizes, tensor entries) are kept as text here; a solver
/// parses them against the parameters' symbol table, so every message can name its field.
#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "symbolic/expression.hpp"

namespace wobble {

/// An interval of allowed values, read from text such as "(0, inf)" or "[0, pi/2)".
struct Interval {
  double lo = 0.0, hi = 0.0;
  bool lo_open = true, hi_open = true;
  std::string text;
  bool contains(double x) const;
};

struct Parameter {
  std::string name;         ///< identifier used in expressions and in --set
  std::string latex;        ///< LaTeX spelling, e.g. "\\alpha", "d_1"
  std::string unit;         ///< SI unit: "kg", "m", "rad", ...
  std::string description;  ///< one line, Markdown with $...$ math as a statement
  double default_value = 0.0;
  Interval range;
  bool fixed = false;  ///< a physical constant (g): the same in every variant
  bool is_angle() const { return unit == "rad"; }
};

struct MassSpec {
  std::string mass;
  std::array<std::string, 3> at;
};

struct ShapeSpec {
  std::string shape;  ///< "box", "disc", ... (core/shapes.hpp)
  std::string mass;
  std::vector<std::string> sizes;                    ///< in the order of shape_size_names
  std::array<std::string, 3> center{"0", "0", "0"};  ///< centre of mass, from the origin
};

struct BodySpec {
  std::vector<MassSpec> masses;
  std::vector<ShapeSpec> shapes;
  std::optional<std::array<std::array<std::string, 3>, 3>> tensor;  ///< given directly, about O
};

/// The `[motion]` table: the initial conditions and constants a dynamics solver takes, as
/// expressions in the parameters, by key. Which keys a solver requires is its registry row's
/// (solvers/registry.hpp); what they mean, its header's.
struct MotionSpec {
  std::map<std::string, std::string> exprs;
  /// @throws std::logic_error for a key the loader did not check (a solver's bug).
  const std::string& at(const std::string& key) const;
};

/// A value students give for an answer that is not it, named by the problem file so that the
/// judge can say what it is: an observation beside a model's answer ("433 day", the Earth's
/// observed wobble, for a rigid Earth's 304 days), or a formula for another quantity ("m*R^2/2",
/// the moment about the other axis). Read against the answer's unit when the problem is solved
/// (a solver computes the unit; solvers/named_mistakes.hpp), so a value of another dimension is
/// refused there, naming `field`.
struct MistakeSpec {
  std::string value;   ///< a constant with its unit ("433 day") or an expression in the parameters
  std::string what;    ///< what it is: "the observed period of the pole's free wobble"
  std::string remedy;  ///< what the answer is instead, or why it differs
  std::string field;   ///< "parts[1].answers[0].mistakes[0]", for messages
};

/// The smallest relative tolerance an answer may be judged with: a key prints ten significant
/// digits, within 5e-10 of the value, so below this its own printed answers would be judged
/// wrong.
inline constexpr double kMinRelativeTolerance = 1e-9;
/// Why a relative tolerance is too fine to judge with (below kMinRelativeTolerance); "" if not.
/// The reason starts with `shown`, the tolerance as typed ("'1e-10%'"), else the number.
std::string tolerance_too_fine(double tolerance, const std::string& shown = "");

struct AnswerSpec {
  std::string name;                 ///< the name in the key (JSON)
  std::string quantity;             ///< what the solver computes for it (defaults to name)
  std::optional<double> tolerance;  ///< relative tolerance for `wobble check` (default 1%)
  std::vector<MistakeSpec> mistakes = {};
};

struct PartSpec {
  std::string id;
  std::string question;
  /// Markdown with $...$ math, as the question: shown after wrong tries in the worksheet and the
  /// browser, and carried by the exports. May be empty.
  std::string hint;
  std::vector<AnswerSpec> answers;
};

struct Problem {
  std::string id, title, source, statement, solver;
  std::vector<std::string> notes;  ///< conventions or choices the key must state
  std::vector<Parameter> parameters;
  BodySpec body;
  std::optional<MotionSpec> motion;
  std::vector<PartSpec> parts;
  std::filesystem::path file;
  /// Each field's line in `file`, for refusals found at solve time (problem/field_lines.hpp).
  std::map<std::string, int> field_lines;
  /// Loaded by its id from the catalog: such a refusal comes from values set, not from the file.
  bool from_catalog = false;

  /// The parameter a name spells: its identifier ("theta0"), or as a key prints it: the
  /// terminal's Unicode ("θ0", "ψ̇0"), a LaTeX subscript ("theta_0"), the parameter's LaTeX
  /// (`\theta_0`, `\theta_{0}`, in $..$ or not) or what that LaTeX prints as ("ω₁", "omega1"
  /// for w1 whose LaTeX is `\omega_1`).
  /// @throws InputError naming the unknown parameter (and the known ones).
  const Parameter& parameter(const std::string& name) const;
  /// The hint of the part with this id; empty if it has none (or there is no such part).
  const std::string& hint(const std::string& part_id) const;
  /// A symbol table with one symbol per parameter (positive if its range excludes negatives).
  sym::SymbolTable symbol_table() const;
};

}  // namespace wobble
