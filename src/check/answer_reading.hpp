#pragma once
/// @file
/// Reading a student's answer: the text as typed or pasted, in whatever notation a key printed
/// it, to a value (number, vector, matrix or expression) and an optional unit.
///
/// Accepted, besides wobble's reading form ("[x, y, z]", "[[..], [..], [..]]", GiNaC syntax):
/// - the terminal's Unicode (symbolic/unicode_notation.hpp): "m·R²/4", "ω·cos(α)", "√2/2",
///   "7.2×10⁻⁴", "15°", "kg m²";
/// - vectors as printed "(2.588, 0, 19.32)", as rows "[2.588 0 19.32]", or bare "5, 7, 10", in
///   angle brackets "⟨5, 7, 10⟩" or "<5, 7, 10>";
/// - a vector as components along unit vectors, "0.5 i + j - 1.5 k", "0.5î + 1.5k̂", "(x̂ +
///   2ŷ) m" (i, j, k where the problem has no such symbol): each term a coefficient times one;
///   also the body's "e₁", "e_1", the primed "e₁′", and LaTeX's "\hat{x}", "\mathbf{e}_1"
///   (basis_vectors.hpp), one basis in a sum;
/// - a transpose mark after a vector or matrix, "[5 7 10]ᵀ", "^T", "^{T}", "^\top", "'": a
///   vector is the same either way, a matrix is transposed;
/// - matrices as printed, row by row ("[ 10 0 0 ] [ 0 6 1 ] [ 0 1 6 ]", on one line or several);
/// - MATLAB's rows "[10 0 0; 0 6 1; 0 1 6]" (a column "[1; 2; 3]" is a vector) and Mathematica's
///   lists "{{10, 0, 0}, {0, 6, 1}, {0, 1, 6}}";
/// - a diagonal matrix as a call, lines of numbers as MATLAB shows them, labelled components
///   ("x = 0.5, y = 1, z = 1.5") and degrees with minutes and seconds of arc: written_forms.hpp;
/// - a number glued to pi, a function or a symbol that spells no unit, as a product ("2pi/3",
///   "4l^2", "2sqrt(3)"; "0.25m R^2" where m is a mass, beside another symbol), and pi beside a
///   number ("1/6 pi") or against a bracket ("2pi(1 - H)"); a Greek letter beside a Latin one
///   as a product ("Hω" is H times ω; μ excepted: "μs");
/// - seconds and minutes of arc after a number typed with the keyboard's '"' and "'";
/// - a unit glued to a vector's bracket, "(0.5, 1, 1.5)m", and per second without its 1,
///   "4.995/s";
/// - a vector or matrix with a factor outside, "M/12 [[b^2 + c^2, 0, 0], ..]", "[a, b, c]/2",
///   "1/2 (a, b, c) m" (a product only: the rest is a factor times the bracket);
/// - vectors (or matrices) of one shape added, each with a factor or none, "φ̇ (0, 0, 1) + θ̇
///   (−sin φ, cos φ, 0)", a unit after the sum only;
/// - a numeric exponent with its sign, "10^-4" (read as 10^(-4), as a student means it), and
///   the letter x for the times sign before 10^, "7.2x10^-4";
/// - powers as Python writes them, "R**2", and a trigonometric power as textbooks do,
///   "cos^2(alpha)" or "cos²(α)" for cos(alpha)^2;
/// - a subscript as LaTeX writes it, "psidot_0" for the problem's psidot0;
/// - a unit after the value, "0.00072 kg m²", "(0, 0, 9.66) rad/s" (symbolic/symbolic/units.hpp),
///   or after each number of a vector or matrix, "(40°, 30°, 70°)", a zero without one;
/// - an SI unit after an expression in the symbols (which is in SI): "m·R²/4 kg m²", and after
///   each expression of a vector, "(φ̇ rad/s, 0, ψ̇ rad/s)";
/// - what ends a line but is no part of the answer: MATLAB's closing ';' ("0.00072;") and a
///   sentence's full stop ("0.00072 kg m².").
/// A unit glued to a plain number ("45deg", "0.21kg") is read as such unless the problem uses one
/// of its letters as a symbol: where m is a mass, "2m" is ambiguous and refused.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/input_error.hpp"
#include "symbolic/units.hpp"
#include "symbolic/value_text.hpp"

namespace wobble::check {

struct ReadAnswer {
  sym::ValueText value;
  std::optional<Unit> unit;
  bool symbolic = false;  ///< has the problem's symbols (then a unit, if any, is an SI one)
  /// Its numbers carry a unit that was written after it (judge.cpp's "M R²/2 × 150 rad/s"): the
  /// symbols' dimension alone is not the answer's, and is not to be said to be.
  bool unit_on_numbers = false;
  /// Read along bare unit vectors i, j, k only because the text as written did not read: what
  /// reading it as written said, for a caller that wants no vector (the letters are then names
  /// of the student's own, "k²" with k an elliptic modulus); else "".
  std::string as_written_error;
};

/// The identifiers in s, in order, as (start, length): "M*R^2 psidot_0" -> M, R, psidot_0 (a
/// number's exponent, "2e5", is none).
std::vector<std::pair<std::size_t, std::size_t>> identifiers(const std::string& s);

/// `typed` without what ends a line but is no part of the answer: MATLAB's ';' that keeps a value
/// from echoing ("0.00072;", "[1 0 0; 0 1 0];"), a sentence's full stop ("0.00072 kg m^2.",
/// "\frac{m R^2}{4}.", "ω₁ ω₂ ." as a PDF's text copies it). One full stop only: "0.333..."
/// stays as typed (and is refused).
std::string without_closing_punctuation(const std::string& typed);

/// The answer in wobble's reading form, the unit still attached: "(1, 0, 0) rad/s" ->
/// "[1, 0, 0] rad/s". Never throws; what it cannot rearrange it leaves for the parser.
std::string reading_form(const std::string& typed);

/// read_answer's refusal of a text it took for a sum along unit vectors and could not read as
/// one ("0.5 i + j^2"). Where every such letter is a bare i, j or k (no hat), the text may use
/// it as a name of its own instead ("k'^2 = 0.9976", k an elliptic modulus): `as_written` then
/// holds what reading the text as written said, for a caller that wants no vector; else "".
struct UnitVectorsUnread : InputError {
  UnitVectorsUnread(const std::string& message, std::string as_written_message)
      : InputError(message), as_written(std::move(as_written_message)) {}
  std::string as_written;
};

/// @throws InputError naming `field` for an empty or unreadable answer or unit, one line a
///   student can act on (never a parser's jargon); UnitVectorsUnread, above.
ReadAnswer read_answer(const std::string& typed, const sym::SymbolTable& table,
                       const std::string& field);

}  // namespace wobble::check
