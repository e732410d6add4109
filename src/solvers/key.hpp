#pragma once
/// @file
/// A solution key: one data structure, rendered by render/ as text, Markdown, LaTeX and JSON.
///
/// Each answer has a name, its exact symbolic form (GiNaC-readable text, and LaTeX; empty where
/// only a numeric value exists, with a note saying why), its value at the parameter values and
/// its SI unit. Vectors and matrices are symbolic as "[x, y, z]" and "[[..], [..], [..]]" whose
/// entries GiNaC reads (sym::parse_symbolic_value reads the whole back).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/input_error.hpp"

namespace wobble {

/// A scalar, a vector or a matrix of doubles (row-major).
struct Value {
  enum class Shape { scalar, vector, matrix };
  Shape shape = Shape::scalar;
  std::size_t rows = 1, cols = 1;
  std::vector<double> data;

  static Value scalar(double x) { return {Shape::scalar, 1, 1, {x}}; }
  static Value vector(std::vector<double> v) {
    const std::size_t n = v.size();
    return {Shape::vector, n, 1, std::move(v)};
  }
  static Value matrix(std::size_t rows, std::size_t cols, std::vector<double> rowmajor) {
    return {Shape::matrix, rows, cols, std::move(rowmajor)};
  }
  double at(std::size_t i, std::size_t j) const { return data[i * cols + j]; }
  /// The largest magnitude of the entries (the scale for comparisons).
  double scale() const;
};

/// A number as printed in text, Markdown and LaTeX keys: 10 significant digits ("0", not "-0").
std::string format_number(double x);

/// A number as LaTeX math, without e-notation: "4.44 \times 10^{-16}".
std::string number_latex(double x);

/// A value as LaTeX: a number, or a pmatrix (vectors as a column).
std::string value_latex(const Value& v);

/// What an answer is, set by its solver's registry row (solvers/registry.hpp): the judge, the
/// renderers and the exports read it, never the answer's name.
enum class AnswerKind {
  scalar,             ///< a number (a mass, an energy, a modulus)
  angle,              ///< a number in radians
  rate,               ///< a number in rad/s (or 1/s)
  vector,             ///< three components in `frame`
  matrix,             ///< a 3x3 matrix that is not an inertia tensor (a rotation)
  tensor,             ///< an inertia tensor, kg m^2
  principal_moments,  ///< three moments, ascending; judged in any order
  principal_axes,     ///< unit columns e1, e2, e3; judged each up to sign, degenerate pairs as
                      ///< planes (core/principal_axes.hpp decides which moments are equal)
};

/// The basis a vector's components are given in.
enum class AnswerFrame {
  none,    ///< not a vector, or no frame applies (a centre of mass in the problem's axes)
  body,    ///< the body's principal axes e1, e2, e3
  space,   ///< the fixed axes
  primed,  ///< the line-of-nodes basis of Euler angles (e1', e2', e3' = z)
};

/// What an answer bounds: a least value (the sleeping top's least spin, the least tilt of a
/// nutation) or a greatest (the largest angle reached), which a student may give as the
/// inequality it is, "ω₃ ≥ 118.8 rad/s".
enum class AnswerBound { none, lower, upper };

/// What the sign of an answer says.
enum class SignConvention {
  none,                ///< an ordinary signed quantity
  sense_of_precession  ///< signed along e3: + with the spin (oblate), - against (prolate)
};

/// Names for messages and the JSON key ("principal_axes", "body", "sense_of_precession").
const char* kind_name(AnswerKind k);
const char* frame_name(AnswerFrame f);
const char* sign_name(SignConvention s);
/// "scalar", "vector" or "matrix": how a value is typed (the exports and the page's inputs).
const char* shape_name(Value::Shape s);

/// A textbook approximation of an answer, evaluated at the key's values, or a value the problem
/// file names (an observation beside the model's answer): the judge names it when a student
/// gives it for the answer ("the fast-top approximation M g l / (I3 ω3)").
struct Approximation {
  std::string name;  ///< what it is, with its formula: "the fast-top approximation M g l / (I3 ω3)"
  std::string remedy;  ///< what the answer is instead: "the slow rate is the smaller root of .."
  std::vector<double> values;  ///< in the answer's unit, as Value::data
  /// What it is measured against in the judge's line ("16.2% below the exact value here"): an
  /// observation is off from the answer, not from an exact value it approximates.
  std::string beside = "the exact value";
};

struct Answer {
  std::string name;
  std::string quantity;  ///< the solver's quantity (the name unless the problem renamed it)
  AnswerKind kind = AnswerKind::scalar;
  AnswerFrame frame = AnswerFrame::none;
  SignConvention sign = SignConvention::none;
  /// principal_axes only: the moments of the columns, ascending (the judge needs them to know
  /// which axes form a degenerate plane).
  std::vector<double> axis_moments;
  std::string axis_moments_symbolic;  ///< their exact form, GiNaC text ("" if numeric only)
  std::string symbolic;  ///< GiNaC text; empty if numeric only
  std::string latex;     ///< LaTeX of the symbolic form (or of the value if numeric only)
  Value value;
  std::string unit;  ///< SI unit, "" for dimensionless
  /// The unit a question shows beside the answer's name (the handout, the worksheet's prompt,
  /// the page's label, the exports): `unit`, or the solver's registered alternatives where the
  /// unit would give the answer away ("rad/s or 1/s": a growth rate's 1/s says the axis is
  /// unstable, which the question asks). Set from the quantity's row; "" means `unit`.
  std::string asked_unit;
  std::vector<std::string> notes;
  /// Approximations a course teaches for this answer, at these values (not in the JSON key: the
  /// notes say them).
  std::vector<Approximation> approximations;
  std::optional<double> check_tolerance;  ///< from the problem file, for `wobble check`
  /// Set by the solver for a least or greatest value (not in the JSON key: the quantity's
  /// description says it).
  AnswerBound bound = AnswerBound::none;
  /// A vector's entries as its question names them, where it names them (kEulerCoefficients;
  /// "Ω₂", "Ω₃" of a pair): empty for components along axes (entry_names gives those). Set by
  /// the solver; the JSON key lists them as "entries".
  std::vector<std::string> named_entries;
  /// A rate about a principal axis: whether the spin about it is stable (the rate is a
  /// frequency) or not (a growth rate), and why, "the spin about e₂ is unstable (Ω₃ Ω₁ < 0)".
  /// The judge weighs a student's word on it after the number, "1.772 1/s (unstable)". Set by
  /// the solver; not in the JSON key (the notes say it).
  struct Stability {
    bool stable = false;
    std::string why;
  };
  std::optional<Stability> stability;
  /// What the steps (or the question) call this answer where that is not its name, GiNaC text
  /// ("theta_L" for the angle of L from e₃, as tan θ_L = (I1/I3) tan α writes it), or a label
  /// no symbol has ("E'", "dw/dt"): a student may write it so. Set by the solver; not in the
  /// JSON key (the steps say it).
  std::vector<std::string> step_names;
};

/// How an answer is typed, as a question shows it beside the name and unit: "a vector [Ω₂, Ω₃]"
/// (entries the question names), "a vector [x, y, z]" (along the fixed axes), "a vector [.., ..,
/// ..] along e₁, e₂, e₃" (a body's components are no x, y, z), "a matrix [[..], [..], [..]]",
/// "three moments [.., .., ..], in any order"; "" for a number.
std::string answer_form(const Answer& a);

/// The unit to show where an answer is asked for: its asked_unit, else its unit.
inline const std::string& asked_unit(const Answer& a) {
  return a.asked_unit.empty() ? a.unit : a.asked_unit;
}

/// The entries of the coefficients c in Euler's equations dω₁/dt = c₁ ω₂ ω₃, ..: the answer
/// that bears these names is the one Euler's equations written out answer (check/answer_choice).
inline const std::vector<std::string> kEulerCoefficients{"c₁", "c₂", "c₃"};

/// The names of a vector answer's entries, as its question writes them: its named_entries, else
/// for three components its frame's axes ("x", "y", "z" of the fixed axes or of none; "e₁", "e₂",
/// "e₃" of the body; "e₁′", "e₂′", "e₃′" of the line-of-nodes basis); empty for a matrix, a
/// scalar, a list of moments, or a vector of another length without names (counted instead).
std::vector<std::string> entry_names(const Answer& a);

struct Step {
  Step(std::string text_, std::string latex_ = "", std::string label_ = "")
      : text(std::move(text_)), latex(std::move(latex_)), label(std::move(label_)) {}
  std::string text;   ///< the whole step as plain text (Unicode allowed)
  std::string latex;  ///< its formula as LaTeX math, may be empty
  std::string label;  ///< the prose that introduces `latex`: Markdown and LaTeX print label +
                      ///< formula when there is a formula (an empty label: the formula alone),
                      ///< else text; the text renderer always prints text
};

struct PartKey {
  std::string id;
  std::string question;
  std::vector<Answer> answers;
  std::vector<Step> steps;
  /// Answers the problem asks for that do not exist at these values (no steady precession of a
  /// too slow top): left out of `answers`, a step says why.
  std::vector<std::string> absent;
  /// For each absent answer, the text of the step that says why ("" where none does).
  std::vector<std::string> absent_why;
  /// For each absent answer, the unit it would be asked in were it to exist ("rad/s"; "" for a
  /// pure number), so that it is asked as the others are: a prompt without a unit would tell.
  std::vector<std::string> absent_unit;

  /// "phidot_fast does not exist at these values: θ0 = 90°: the axle is horizontal, ..": the
  /// `i`-th absent answer as every surface names it, with its reason where there is one;
  /// "phidot_fast (part d) does not .." with `name_part`, for a line outside the part's own.
  std::string absent_line(std::size_t i, bool name_part = false) const;

  /// Every answer the part asks for, by name: its answers, then those absent at these values,
  /// which are asked for all the same ("none" is their answer): a list of what to give that left
  /// them out would tell a student that they do not exist.
  std::vector<std::string> asked_names() const;
};

/// Appends `steps` to the part, skipping any whose text the part already has (two answers of a
/// part often share a derivation).
void append_steps(PartKey& part, const std::vector<Step>& steps);

/// One computed quantity: its answer and the steps that derive it. `exists` false: there is no
/// such quantity at these values, and the steps say why.
struct Computed {
  Answer answer;
  std::vector<Step> steps;
  bool exists = true;
};

struct ParameterValue {
  std::string name, latex, unit, description;
  double value = 0.0;
};

/// A name a solver's convention gives a quantity that is one parameter of this problem, which
/// names it otherwise: the PHY 711 problem's α is Taylor's φ (its [motion] phi = "alpha"). A
/// student may write either; `wobble check` reads the convention's name as the parameter and
/// says so.
struct ConventionName {
  std::string name;       ///< the convention's, as GiNaC text: "phi"
  std::string parameter;  ///< the problem's: "alpha"
};

/// A name the solver's steps write for a quantity of this problem that is no parameter of it (the
/// heavy top's I1 and I3, its moments about the pivot), with its exact form at these values. A
/// student may write an answer as the steps do; `wobble check` reads the name as that form and
/// says so.
struct DefinedName {
  std::string name;      ///< as GiNaC text: "I3"; or such a name and a prime: "omega1'" (ω₁′)
  std::string symbolic;  ///< its exact form, GiNaC text: "1/2*M*R^2"
  std::string meaning;   ///< what it is, for that line: "the moment about the axle"
};

struct Key {
  std::string problem, title, source, statement;
  std::optional<long> variant;  ///< the student's variant the values are drawn for, if any
  std::string figure;           ///< a sketch drawn beside the key (a LaTeX key includes it)
  std::vector<std::string> notes;  ///< conventions and choices, printed with every key
  std::vector<ParameterValue> parameters;
  /// Parameters whose set values the exact forms are written with, as a zero rate is (a heavy
  /// top's θ0 = 90°: cos θ0 is 0 in its forms): an expression is judged with them held there.
  std::vector<std::string> held;
  /// The convention's names for parameters named otherwise here, and whose names they are
  /// ("Taylor's"); not in the JSON key (its notes say them).
  std::vector<ConventionName> convention_names;
  std::string convention;
  /// The names the steps write for quantities that are no parameter; not in the JSON key (the
  /// steps say them).
  std::vector<DefinedName> defined_names;
  std::vector<PartKey> parts;
};

/// A check asks for a part or an answer the key does not have (the server answers it with 404).
struct AnswerNotFound : InputError {
  using InputError::InputError;
};

/// The answer a check asks for: by part id and answer name; the part's only answer when no name
/// is given; the answer of that name in whichever part has it when no part is (names are unique
/// in a problem). A part id that names no part but an answer is taken for that answer's name.
/// `part_field` and `name_field` are what the caller calls them ("part", "--name").
/// @throws AnswerNotFound naming the field and listing what exists: an unknown part or name, a
///   part with several answers and no name, a part or answer absent at these values.
/// @throws InputError when neither a part nor a name is given.
/// The key's answers by part, for a message: "(a) I0, I; (b) L0_body, L0_space", "none" if
/// there are none (parts with nothing to check at these values are left out).
std::string answers_by_part(const Key& key);

/// Whether one of the key's parts asks for the answer `name` (PartKey::asked_names: one that
/// does not exist at these values too).
bool asks_for(const Key& key, const std::string& name);

const Answer& find_answer(const Key& key, const std::string& part_id, const std::string& name,
                          const std::string& part_field, const std::string& name_field);

}  // namespace wobble
