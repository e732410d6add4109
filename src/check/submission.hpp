#pragma once
/// @file
/// Judging a whole submission: a text with one answer per line, as a student hands it in to an
/// autograder (Gradescope) or to `wobble check --answers`.
///
///     # comments and blank lines are skipped
///     variant = 17              (optional: the values of the student's handout)
///     p_phi = 0.0123 kg m^2/s
///     theta_min: 0.61
///
/// A line is NAME = ANSWER or NAME: ANSWER, NAME an answer of the key (`wobble solve` lists
/// them), or NAME ANSWER with a space between where NAME is one (spaced_answer_line). Each
/// answer is judged alone (judge.hpp): an unreadable answer is wrong, said to be "unreadable"
/// with its line and the reason, a missing one is wrong as "not answered", a line naming no
/// answer is reported, and none of these stops the others from being judged.
#include <optional>
#include <string>
#include <vector>

#include "check/judge.hpp"

namespace wobble::check {

struct SubmittedAnswer {
  std::string part, name;
  bool answered = false;
  std::string typed;
  Verdict verdict;
};

struct SubmissionResult {
  /// Every answer of the key, in the key's order, each part's answers that do not exist at
  /// these values after the others ("none" is right for them: absent_answer.hpp).
  std::vector<SubmittedAnswer> answers;
  std::vector<std::string> problems;     ///< lines that name no answer, or name one twice
  bool all_correct() const;
};

/// One line's name and answer: NAME = ANSWER or NAME: ANSWER (split at the first '=' or ':', or
/// '≈', '≃' or '∼', which the judge reads as '=': "φ̇_slow ≈ 4.995 rad/s"; a separator typed
/// twice, "NAME == ANSWER" or "NAME := ANSWER", is one),
/// a part's mark before the name dropped ("(b) rate_axis2 = 1.772 1/s"), and the unit the
/// worksheet's prompt shows after it ("rate_axis2 [rad/s or 1/s] = .."), both trimmed; as a
/// submission's line, and one word `wobble check` is given.
struct NamedAnswer {
  std::string name, answer;
  std::string separator = "=";  ///< as typed: "=", ":", "≈", ..
};
/// nullopt where the line has no separator.
std::optional<NamedAnswer> answer_line(const std::string& line);

/// "omega3_min 118.8 rad/s", "(c) I₀ 0.00072 kg m²": a name and its answer with only a space
/// between, as a student lists them. The first word (a part's mark before it dropped) and the
/// rest, where there is a rest and it does not go on with an operator ("omega3 * 2", "ω3 − 3"
/// are expressions); nullopt otherwise, where the line has a separator (answer_line's), and
/// where it is a relation ("E < 8 J", "θ ∈ [..]", "E -> 8 J": bounds, ranges and rules).
/// Whether the word names an answer, and so whether the line is read so, is the caller's to say
/// (name_in_key): the same line may be an expression, omega3 times 118.8, where it names none.
std::optional<NamedAnswer> spaced_answer_line(const std::string& line);

/// Whether an answer starts as a number or a list does ("118.8 rad/s", "-0.5", "−2e-3",
/// "[1, 0, 2]", "(1, 0, 1)/√2"), not with a name ("m a²/6"): after a word that may be a factor
/// as well as a label, only such a rest makes the word a label.
bool starts_as_number(const std::string& answer);

/// The submission's "variant = N" line, if it has one.
/// @throws InputError naming the line for a variant that is not a whole number.
std::optional<long> submission_variant(const std::string& text);

/// @throws InputError for a text too large (over 1 MB) for a submission.
SubmissionResult judge_submission(const Context& ctx, const std::string& text, const Options& opt);

}  // namespace wobble::check
