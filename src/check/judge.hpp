#pragma once
/// @file
/// Judging a student's answer against the key (`wobble check`).
///
/// An answer is a number, a vector "[x, y, z]" or a matrix "[[..], [..], [..]]", each optionally
/// followed by a unit (symbolic/units.hpp; none means SI), or an expression in the problem's
/// symbols
/// ("m*a^2/6"). Numbers are right within a relative tolerance (1% by default, or the answer's
/// `tolerance` in the problem file, or the user's) of the key's
/// value, or, with sigfigs N, when the key rounds to them at N significant digits; a zero is
/// judged with an absolute tolerance: the tolerance times the largest value of the same unit in
/// the key. Vectors and matrices are judged entry by entry and the wrong entries named; a
/// principal axis is right up to sign, principal moments in any order, and an axis of a
/// degenerate pair may be any unit vector of its plane. Expressions are right when their
/// difference from the key's closed form simplifies to zero (GiNaC's normal form), or, since
/// that cannot prove trigonometric identities, when they equal it at the set values and at three
/// more parameter points (each parameter scaled by 1.13, 0.87, 1.29 or their reciprocals, in an
/// order of its own, so that no two of up to twelve parameters scale alike), to 1e-9.
/// A wrong answer gets the likely mistake when it matches one (a reversed sign, products of
/// inertia with the wrong sign, degrees for radians, rev/s for rad/s, a factor 2, 4 or 12,
/// another answer of the key such as the body-frame vector for the space-frame one), else
/// the size of its error.
///
/// A line of a key may be pasted with its '=' ("I0 = m·R²/4 = 0.00072 kg m²"): every side is
/// judged. '≈' (and '≃', '∼', a leading '~') reads as '='; components one by one with their
/// labels ("x = 0.5, y = 1, z = 1.5") are one vector (written_forms.hpp).
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "solvers/key.hpp"
#include "symbolic/expression.hpp"

namespace wobble::check {

/// The relative tolerance of an answer when neither the user nor the problem file gives one: 1%,
/// what a hand calculation with three significant figures keeps.
inline constexpr double kDefaultRelativeTolerance = 0.01;

/// A value typed to N significant figures is right when it is within half a unit of the last
/// figure; the typed decimal and the key are each rounded to binary, which may put an exact half
/// a few ulps outside: this much relative slack keeps the boundary where the decimal puts it.
inline constexpr double kHalfUnitSlack = 1e-9;

struct Options {
  double rel_tol = kDefaultRelativeTolerance;
  bool rel_tol_given = false;  ///< given by the user: wins over the problem file's per answer
  std::optional<int> sigfigs;
};

struct Verdict {
  bool correct = false;
  std::string line;                   ///< one line: "correct" or "incorrect: ..."
  std::vector<std::string> feedback;  ///< more lines
  /// The answer's unit (or expression) has another dimension than the key's: read, but as no
  /// value of this answer (answer_choice.hpp takes an answer whose dimension it has).
  bool wrong_dimension = false;
};

struct Context {
  const Key& key;
  const sym::SymbolTable& table;
  const sym::Values& values;  ///< the parameter values the key was computed at
};

/// The scale a zero entry of `a` is judged against: the largest value of the same unit in the
/// key (1 if there is none).
double zero_scale(const Key& key, const Answer& a);

/// Whether `a` is a triple of Euler angles, each the same up to whole turns (ψ = 340° is ψ =
/// −20°): a vector in rad. The judge takes an entry whole turns off the key's as the key's.
bool angles_up_to_turns(const Answer& a);

/// The options `a` is judged with: the problem file's tolerance for it, unless the user gave one.
Options options_for(const Answer& a, const Options& options);

/// Whether `text` is Euler's equations written out, "dω₁/dt = c₁ ω₂ ω₃, ..", right or wrong
/// (check/euler_equations.hpp): an answer for the coefficients c₁, c₂, c₃.
bool written_as_euler_equations(const Context& ctx, const std::string& text);

/// A power of ten whose superscript was lost ("7.2 × 10−4", check/lost_power.hpp) is judged as
/// written; the verdict, or the refusal where only the power reads, says how it was read.
/// @throws InputError for an empty or unreadable answer, a wrong shape (a vector for a number),
///   or an unreadable unit.
Verdict judge(const Context& ctx, const Answer& expected, const std::string& text,
              const Options& opt);

/// The letters and digits of an answer's name however it is written, to compare names by:
/// "L_{0,\mathrm{body}}" (LaTeX), "L₀_body" (Unicode) and "L0_body" are all "L0body".
std::string name_spelling(const std::string& written);

/// `written` as the key names it, where it names a part or an answer however it is written:
/// "I₀" and "I_0" are I0, "L_{0,\mathrm{body}}" is L0_body, "Ω_body_rate" is Omega_body_rate
/// (a part's id or an answer's name as printed stays itself; one spelling that two answers share
/// names neither; an answer that does not exist at these values is one too; a name the steps
/// write for an answer is that answer, θ_L and r_cm; a prime makes another name, E′ is not E).
/// `written` itself otherwise, for the lookup to refuse with the key's names.
std::string name_in_key(const Key& key, const std::string& written);

/// name_in_key for many names of one key (a submission's lines): the key's names spelt once.
class NamesInKey {
 public:
  explicit NamesInKey(const Key& key);
  std::string operator()(const std::string& written) const;

 private:
  std::set<std::string> exact_;  ///< part ids and answer names, as printed
  /// Each spelling, primed or not, and the answers it names.
  std::map<std::pair<std::string, bool>, std::set<std::string>> spelt_;
};

/// The refusal of a line with its answer left out after the '=' or ':' ("rate_axis2 =", a
/// prompt's line pasted), naming `field`: the option, or the answer the line names.
std::string nothing_after(const std::string& field, const std::string& separator,
                          const std::string& line);

/// A refusal from judge() without the command-line option it names ("--answer: "), for the
/// surfaces where the student typed no option (a submission file, the worksheet, the browser);
/// one about an entry names it counted from 1: "entry 1: .." for "--answer[0]: ..", "entry (1,
/// 2): .." for "--answer[0][1]: ..".
std::string without_option(const std::string& message);

}  // namespace wobble::check
