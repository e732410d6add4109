#pragma once
/// @file
/// The terminal's spelling of expressions, both ways: what a text key prints and what a student
/// pastes back.
///
/// Printing (to_unicode) turns GiNaC text into the terminal's notation: `*` -> `·`, `sqrt(` ->
/// `√(`, `^2` -> `²`, `^(-1)` and `^-1` -> `⁻¹`, Greek names -> letters (`alpha` -> `α`, `Pi` ->
/// `π`), a name with `dot` and digits -> the letter with a combining dot above (`phidot0` -> `φ̇0`).
/// Reading (to_ascii) undoes every one of these and accepts the common variants a student types
/// (`×` and `⋅` for `*`, `÷` for `/`, `−` for `-`, `√2` for `sqrt(2)`, superscripts with a sign
/// `⁻⁴`, `°` for degrees, `″` and `′` after a number for seconds and minutes of arc, `µ`/`μ`), so
/// that whatever wobble prints reads back as what it meant. Characters it does not know are left in
/// place, for the expression guard to refuse by name.
#include <map>
#include <string>

namespace wobble::sym {

/// Greek letter names and their Unicode letters ("alpha" -> "α"; "pi" and "Pi" -> "π").
const std::map<std::string, std::string>& greek_letters();

/// GiNaC text made pleasant for a terminal: m*a^2 -> m·a², sqrt( -> √(, alpha -> α, Pi -> π.
std::string to_unicode(const std::string& ginac_text);

/// The inverse of to_unicode, and the Unicode a student types: "ω·√(3·cos(α)² + 1)/2" ->
/// "omega*sqrt(3*cos(alpha)^2 + 1)/2", "7.2×10⁻⁴" -> "7.2*10^(-4)", "15°" -> "15 deg".
std::string to_ascii(const std::string& unicode_text);

/// Letters as mathematical typesetting styles them, as the plain letters they are: the italic,
/// bold, sans-serif, ... letters and digits a word processor's equation or a PDF gives when
/// copied (𝐼 -> I, 𝜔 -> ω, 𝟐 -> 2, ℎ -> h), and the variant forms of Greek letters (ϵ -> ε,
/// ϑ -> θ, ϕ -> φ, ϱ -> ρ, ϰ -> κ, ς -> σ), and the spacing dot above after a letter as the
/// combining one (a PDF's "φ˙" for φ̇). Two styled letters in a row are two symbols, as in the
/// equation they came from: "𝑚𝑅" -> "m R". The invisible function application and separator
/// (U+2061, U+2063) become spaces, invisible times (U+2062) '*', a zero-width space nothing.
/// Not Unicode's NFKC, which would also make x² x2 and ½ 1⁄2, both of which to_ascii reads.
std::string letters_folded(const std::string& text);

/// How a student types a symbol whose LaTeX is `latex`, as this notation reads it back: the
/// Unicode a key prints for it (math_to_unicode) through to_ascii, without underscores or
/// spaces. `\omega_1` -> "omega1" (from "ω₁"), `\dot\theta_0` -> "thetadot0", `I_1` -> "I1".
std::string typed_spelling(const std::string& latex);

}  // namespace wobble::sym
