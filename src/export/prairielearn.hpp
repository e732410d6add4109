#pragma once
/// @file
/// A PrairieLearn question folder (v3 question): info.json (a uuid derived from the problem id,
/// so a new export replaces the question instead of adding one), question.html (the statement
/// with its math for PrairieLearn's MathJax, the variant's values, one input per answer: a
/// number input, or a matrix component input for a vector or matrix), server.py (the same for
/// every problem: generate() picks a variant from variants.json, grade() applies wobble's rules
/// and messages) and variants.json (per variant its values, answers, rules and mistakes; read by
/// the server only, never sent to the browser).
#include <array>
#include <vector>

#include "check/judge.hpp"
#include "export/graded_variants.hpp"
#include "export/output_file.hpp"
#include "problem/problem.hpp"

namespace wobble::exports {

/// The question's files, paths relative to the question folder.
std::vector<OutputFile> prairielearn_question(const Problem& problem, const VariantSet& variants,
                                              const check::Options& options);

/// The names of the files prairielearn_question writes, in its order: a command can refuse to
/// replace them before any variant is drawn.
inline constexpr std::array<const char*, 4> kPrairieLearnFiles{"info.json", "question.html",
                                                               "server.py", "variants.json"};

/// The uuid of the problem's question: a name-based (SHA-1) uuid of "wobble/problem/ID".
std::string question_uuid(const std::string& problem_id);

/// The name of an answer's input: "PART_NAME" (an answer name may recur in another part).
std::string input_name(const GradedAnswer& a);

/// HTML from a problem's text made safe for question.html, a Mustache template: the second brace
/// of each "{{" (LaTeX's `\frac{1}{{2}}`) as the entity &#123;, which the browser, and so
/// MathJax, reads as a brace, and Mustache does not read as a tag.
std::string mustache_safe(const std::string& html);

/// The grading rules and variants as the server reads them (variants.json).
std::string variants_json(const VariantSet& variants, const check::Options& options);

}  // namespace wobble::exports
