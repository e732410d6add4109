#pragma once
/// @file
/// What a student's page shows of a problem, as JSON: its statement (math in $...$ for KaTeX),
/// its values for a variant, its parts with their questions and one input per answer (name,
/// unit, kind, shape), and whether a part has a hint. Never an answer's value or form, nor a
/// hint's text (that comes on request after tries): served to anyone.
#include <optional>
#include <string>
#include <vector>

#include "problem/problem.hpp"
#include "solvers/key.hpp"

namespace wobble::web {

/// `key` is the problem's key at the variant's values (its answers are not read beyond their
/// names, units, kinds and shapes); `assignments` the variant's "NAME=VALUE" as drawn, so that
/// a value shows as the handout shows it ("16°" with its radians). Each part says whether it has
/// a hint; with `with_hints` (the page file, which has no server to ask) it carries the hint.
std::string student_view_json(const Problem& problem, const Key& key, std::optional<long> variant,
                              const std::vector<std::string>& assignments, bool with_hints = false);

/// The problem list: [{"id", "title"}], in the catalog's order.
std::string problem_list_json(const std::vector<Problem>& problems);

}  // namespace wobble::web
