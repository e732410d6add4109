#pragma once
/// @file
/// Markdown with LaTeX math (a problem's statement) as plain terminal text: no `$`, no
/// backslash, no braces, no backticks. Math becomes Unicode: Greek letters, `\dot\theta_0` ->
/// `θ̇₀`, `\sqrt{3}` -> `√3`, `\frac{a}{b}` -> `a/b`, `\pm` -> `±`, `\sin\alpha` -> `sin α`,
/// digits in sub- and superscripts as Unicode (`I_1` -> `I₁`, `a^2` -> `a²`), other subscripts
/// as `_word` (`V_{body}` -> `V_body`). An unknown command prints as its name, so nothing of
/// LaTeX's syntax reaches a terminal.
#include <string>

namespace wobble {

/// LaTeX math (without `$`) as Unicode text.
std::string math_to_unicode(const std::string& latex);

/// A Markdown statement with `$...$` math as plain text.
std::string plain_text(const std::string& markdown);

}  // namespace wobble
