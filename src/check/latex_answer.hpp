#pragma once
/// @file
/// Reading an answer written in LaTeX math: what a LaTeX or Markdown key prints, what the browser
/// copies from its typeset math, and what a student used to LaTeX types.
///
/// The LaTeX becomes the plain text the answer reader takes (answer_reading.hpp), products written
/// out: "\frac{m R^{2}}{4}" -> "(m*R^(2))/(4)". Read, besides digits, + - / ( ) and commas:
/// - products side by side, as LaTeX sets them ("m R^{2}", "2\alpha", "M g l"); in LaTeX a letter
///   is a symbol, so "mR" is m times R unless the problem has a symbol named mR;
/// - \frac \dfrac \tfrac, \sqrt{x} and \sqrt[n]{x}, powers ^{..}, \cdot \times \div, \big/;
/// - the problem's symbols as its file spells them in LaTeX, by meaning, not by spelling:
///   "\dot\psi_0", "\dot{\psi}_{0}" and "\dot{\psi_0}" are all psidot0; a Greek letter the
///   problem names in ASCII (\alpha for alpha), \varphi \vartheta \varepsilon as their letters;
/// - \sin \cos \tan \arcsin \arccos \arctan \sinh \cosh \tanh \exp \ln \log and \operatorname{f},
///   with parentheses or without ("\cos\theta_0", "\sin 2\alpha": one symbol, a number before
///   it), and a power after the name ("\sin^{2}\alpha" is sin(alpha)^2); \pi;
/// - \left( \right), \left| \right| (an absolute value), \bigl( \Bigr) ... and plain braces as a
///   group; spacing (\, \; \quad ~) between factors;
/// - pmatrix, bmatrix, matrix and array: a column or a row is a vector;
/// - a unit after the value, in \mathrm{..} or \text{..} or bare ("0.00072\,\mathrm{kg\,m^{2}}",
///   "15^\circ"); after each entry of a vector or matrix, ^\circ after a number or a unit in
///   \mathrm{..} or \text{..} ("(0.5\,\mathrm{rad/s}, 0)", "\dot\psi\,\mathrm{rad/s}" in a
///   pmatrix cell); and 7.2 \times 10^{-4};
/// - siunitx's \SI \qty \num \si \unit \ang (siunitx.hpp);
/// - the delimiters $..$, $$..$$, \(..\), \[..\] around it all.
/// Anything else (\pm, an unknown command, an & outside a matrix) is refused in one line naming it.
#include <string>

#include "symbolic/expression.hpp"

namespace wobble::check {

/// `s` trimmed, without Markdown's code span around it all, `..` or ``..`` (as a forum or a chat
/// sets a formula apart: "`m*R^2/4`", "`I0 = 0.00072 kg m^2`"); else as it is.
std::string without_code_marks(const std::string& s);

/// The math without its delimiters: $..$, $$..$$, \(..\), \[..\] around it all, inside a code
/// span or not ("`$m R^2/4$`", without_code_marks); else as it is.
std::string without_math_delimiters(std::string s);

/// Whether the answer is LaTeX: it has a backslash, or a brace after ^ or _ ("R^{2}").
bool looks_like_latex(const std::string& typed);

/// The answer in plain text (see above), for read_answer to read.
/// @throws InputError naming `field` for what is not read.
std::string latex_as_text(const std::string& latex, const sym::SymbolTable& table,
                          const std::string& field);

/// A parameter as a LaTeX key prints it, NAME = VALUE or NAME = VALUE = VALUE
/// ("$\dot\psi_0 = 150\,\mathrm{rad/s}$", "\theta_0 = 30^\circ = 0.5235987756\,\mathrm{rad}"),
/// in the plain text `--set` reads ("psidot0 = 150 rad/s", "theta0 = 30 deg = 0.5235987756 rad"):
/// the name and each value side read as latex_as_text reads them, the math delimiters dropped
/// ("$H = 0.0032738$"). Text with neither is returned as it is.
/// @throws InputError naming "--set" (and the parameter, for a value) for what is not read.
std::string latex_assignment_as_text(const std::string& text, const sym::SymbolTable& table);

}  // namespace wobble::check
