#pragma once
/// @file
/// The variants of a problem that an export can grade: per variant its values, its key and, per
/// answer, the rules wobble's judge applies (tolerance, the scale of a zero, principal axes'
/// degenerate planes) and the wrong answers of the known mistakes (check/diagnosis.hpp) with the
/// judge's message for each.
///
/// A variant is exported only if every mistake it lists can be told from the right answer: a
/// wrong answer that the judge would accept (at a small tilt "the body-frame components" for the
/// space-frame ones lie within 1%) makes the variant ungradable, and it is drawn again (the next
/// variant number). A mistake the judge accepts in more than three quarters of the variants
/// drawn first (k² for k near the separatrix, in all) is one a number cannot show in this
/// problem: no variant is refused for it (it is listed where it is told apart), and it is
/// reported. A variant where an answer does not exist (no steady precession) is drawn again. A
/// wrong answer equal to the key itself (the reversed sign of a zero, the products of inertia of a
/// diagonal tensor) is no mistake there and is left out; one the judge names as an earlier mistake
/// is left to that one.
#include <string>
#include <utility>
#include <vector>

#include "check/diagnosis.hpp"
#include "check/judge.hpp"
#include "problem/problem.hpp"
#include "solvers/key.hpp"

namespace wobble::exports {

/// One answer as an export grades it.
struct GradedAnswer {
  std::string part;
  Answer answer;
  double rel_tol = check::kDefaultRelativeTolerance;  ///< the problem file's or the user's
  double zero_scale = 1.0;                            ///< check/judge.hpp zero_scale
  /// principal_axes only: the key's principal directions as groups of columns (0-based).
  std::vector<std::vector<int>> eigenspaces;
  std::vector<check::WrongAnswer> mistakes;  ///< values and the judge's message, in order
};

struct GradedVariant {
  long number = 0;  ///< the variant number (`wobble solve --variant N` gives the same key)
  std::vector<std::pair<std::string, std::string>> values;  ///< NAME, value as a handout shows it
  Key key;
  std::vector<GradedAnswer> answers;
};

/// A variant number that was drawn and not exported, and why.
struct Rejection {
  long number = 0;
  std::string reason;
  std::string kind;  ///< the reason without this variant's numbers, for counting
};

/// A mistake no number tells from the answer in most variants of a problem.
struct UntoldMistake {
  std::string kind;  ///< a Rejection's kind
  long within = 0;   ///< the variants drawn first where it is within the tolerance
  long drawn = 0;    ///< of the variants drawn first (those where the answers exist)
};

struct VariantSet {
  std::vector<GradedVariant> variants;
  std::vector<Rejection> rejected;
  /// Mistakes within the tolerance in more than three quarters of the variants drawn first: no
  /// variant is refused for them.
  std::vector<UntoldMistake> untold;
};

/// Variants `first`, `first + 1`, ... until `count` are gradable (each rejected number is
/// replaced by the next), judged with `options` (check/judge.hpp).
/// @throws InputError when 10 times `count` numbers give fewer than `count` gradable variants,
///   counting the reasons.
VariantSet graded_variants(const Problem& problem, long first, long count,
                           const check::Options& options);

/// One variant's answers with their rules and mistakes (what graded_variants keeps).
/// @return the answers with the mistakes the judge tells apart, and each mistake it cannot tell
///   from the answer (or, with no answers, the answer that does not exist at these values).
std::pair<std::vector<GradedAnswer>, std::vector<Rejection>> grade_rules(
    const Problem& problem, const Key& key, const sym::Values& values,
    const check::Options& options);

/// The text a student would type for `values` in the shape of `a` (numbers to 17 digits and the
/// key's unit): "[1.5, 0, 2] kg m^2/s".
std::string answer_text(const Answer& a, const std::vector<double>& values);

}  // namespace wobble::exports
