#pragma once
/// @file
/// A Moodle quiz (Moodle XML) of a problem: a category named after it, then one calculated
/// question per number a student gives (a scalar answer, or one entry of a vector or matrix
/// answer: Moodle's calculated question takes one number). Each question shows the statement
/// (math for Moodle's MathJax filter), the variant's values and the part's question; its
/// datasets hold, per variant (one dataset item each), the values, wobble's answer and each
/// known mistake's wrong value, so any answer can be exported, elliptic functions included. The
/// answer is graded within wobble's tolerance (relative; nominal for a zero); each mistake is a
/// 0% answer with wobble's message, tried after the right answer. Principal axes are left out:
/// an axis is right up to sign and a degenerate pair's anywhere in its plane, which one number
/// against a tolerance cannot say (PrairieLearn and Gradescope exports grade them).
#include <string>
#include <vector>

#include "check/judge.hpp"
#include "export/graded_variants.hpp"
#include "problem/problem.hpp"

namespace wobble::exports {

struct MoodleQuiz {
  std::string xml;
  int questions = 0;
  std::vector<std::string> left_out;  ///< answers not exported, each with why
};

/// @throws InputError when options ask for significant figures (Moodle grades by tolerance).
MoodleQuiz moodle_quiz(const Problem& problem, const VariantSet& variants,
                       const check::Options& options);

}  // namespace wobble::exports
