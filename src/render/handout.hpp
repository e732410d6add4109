#pragma once
/// @file
/// The handout of a problem: its statement, the parameter values a student works with, and the
/// questions, without any answer (Markdown).
#include <optional>
#include <string>
#include <vector>

#include "solvers/key.hpp"

namespace wobble {

/// `shown` maps parameter names to the text to print (a variant's "22deg"); others print their
/// value from the key.
std::string render_handout(const Key& key,
                           const std::vector<std::pair<std::string, std::string>>& shown,
                           std::optional<long> variant);

/// The same handout as a LaTeX document for pdflatex: a name line, the variant number, the
/// values in a table, each question with room to answer.
std::string render_handout_latex(const Key& key,
                                 const std::vector<std::pair<std::string, std::string>>& shown,
                                 std::optional<long> variant);

/// The same handout as plain terminal text (the worksheet's introduction): the statement's
/// math in Unicode, one line per parameter; the questions only if `with_questions`.
std::string render_handout_text(const Key& key,
                                const std::vector<std::pair<std::string, std::string>>& shown,
                                std::optional<long> variant, bool with_questions);

}  // namespace wobble
