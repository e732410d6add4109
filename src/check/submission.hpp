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
/// them). Each answer is judged alone (judge.hpp): an unreadable answer is wrong, said to be
/// "unreadable" with its line and the reason, a missing one is wrong as "not answered", a line
/// naming no answer is reported, and none of these stops the others from being judged.
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

/// The submission's "variant = N" line, if it has one.
/// @throws InputError naming the line for a variant that is not a whole number.
std::optional<long> submission_variant(const std::string& text);

/// @throws InputError for a text too large (over 1 MB) for a submission.
SubmissionResult judge_submission(const Context& ctx, const std::string& text, const Options& opt);

}  // namespace wobble::check
