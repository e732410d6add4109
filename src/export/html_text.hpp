#pragma once
/// @file
/// A problem's text as HTML for a learning system's page: special characters escaped, `code` as
/// <code>, paragraphs at blank lines, and the math ($...$ in problem files) between the
/// delimiters the system's MathJax reads.
#include <string>

namespace wobble::exports {

/// &, <, > and " as entities.
std::string html_escape(const std::string& text);

/// The statement as <p> paragraphs; each $...$ becomes open + math + close (the math escaped,
/// not otherwise changed).
std::string statement_html(const std::string& statement, const std::string& open,
                           const std::string& close);

/// One line (a part's question) as statement_html makes it, without the paragraph around it.
std::string inline_html(const std::string& text, const std::string& open, const std::string& close);

/// A unit as the page shows it: "kg m^2/s" as "kg m²/s", escaped.
std::string unit_html(const std::string& unit);

}  // namespace wobble::exports
