#pragma once
/// @file
/// Forms of a whole answer that name its parts instead of laying them out, rewritten to the
/// reading form (answer_reading.hpp) before the answer is read:
/// - a diagonal matrix as a call, as the key's steps print one ("diag(M·(b² + c²)/12, ..)") and
///   as MATLAB, NumPy, SymPy, Julia and Mathematica write it: "diag(a, b, c)",
///   "np.diag([a, b, c])", "diag([a b c])", "diagm([a, b, c])", "DiagonalMatrix[{a, b, c}]";
/// - numbers laid out in lines without brackets, as MATLAB displays a result: "0.5 1 1.5" (a
///   vector), one number on each line (a column: a vector), or rows of numbers (a matrix);
/// - a comment after an answer, as in a script or a LaTeX source: "m*R**2/4  # disc",
///   "7.2e-4 % kg m^2";
/// - a result as a program labels it, "Out[3]= 0.00072" (Mathematica), "Out[3]: .." (IPython);
/// - an angle in degrees, minutes and seconds of arc, "44°41′", "44° 41′ 37″", "44°41'37\""
///   (units.hpp's sexagesimal_degrees, which parameter values share);
/// - a vector's components given one by one with their labels, as a student lists them:
///   "x = 0.5, y = 1, z = 1.5", "ω₁ = 2 rad/s, ω₂ = 0, ω₃ = 9.7 rad/s", "I1 = .., I2 = .., I3 =
///   ..". The labels differ in their last letter or digit only, x y z or 1 2 3 (in any order: the
///   components are put in theirs).
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace wobble::check {

/// The value and the unit after it ("" if none): the first split at a space whose right side is
/// a unit, as typed or in ASCII ("1.5 m" -> ("1.5", "m"); "4.2 kg m²" -> ("4.2", "kg m²"); "2 * m"
/// and "x / s" are no value and unit); `s` itself and "" for a text without one.
std::pair<std::string, std::string> split_unit(const std::string& s);

/// "[0.5, 1, 1.5]" for "0.5 1 1.5", "[[1, 0], [0, 2]]" for the lines "1 0" and "0 2": text
/// that is only plain numbers (two or more), separated by spaces and line breaks, each line as
/// many; a row in parentheses, "(0.5 1 1.5)", and a row with a unit after it, "0.5 1 1.5 m" ->
/// "[0.5, 1, 1.5] m"; nullopt for any other text.
std::optional<std::string> number_rows(const std::string& typed);

/// `ascii` with each diagonal matrix written as its rows: "M/12 diag(a, b, c)" ->
/// "M/12 [[a, 0, 0], [0, b, 0], [0, 0, c]]". Text that is no such call is left as it is.
/// @throws InputError naming `field` for a diagonal of more than three entries: wobble's
///   matrices are 3x3, and n entries would be written out as n² (a hostile answer's thousands).
std::string diagonals_written_out(const std::string& ascii, const std::string& field);

/// Labelled components in the reading form, and whether they were vectors, a matrix's columns.
struct LabelledComponents {
  std::string text;
  bool columns = false;
  /// A formula between a label and its value, "I₃ = I₁ + I₂ = 5.5": read past, not judged, and
  /// said so ("I₁ + I₂ (before I₃'s value) is not judged: its value is").
  std::vector<std::string> notes;
};

/// "[0.5, 1, 1.5]" for "x = 0.5, y = 1, z = 1.5" (the text as typed, Unicode or not), and equal
/// components told once, "I₁ = I₂ = 0.00975, I₃ = 0.006" (labels of one word each before the
/// value); vectors labelled e1 = (..), e2 = (..), e3 = (..) as the columns they are, "[[..],
/// ..]^T". A unit after the last value alone is the whole vector's ("x = 0.5, y = 1, z = 1.5 m"
/// -> "[0.5, 1, 1.5] m"). nullopt for a text that is no list of labelled components.
/// Labels are placed by the key's names of its entries where they are those (`entry_names`,
/// name_spelling'd: "Ω₃ = 7.2, Ω₁ = −11.6" for the pair the key names (Ω₃, Ω₁)); otherwise by
/// the one character in which they differ (x, y, z or 1, 2, 3; two of them where the answer has
/// `entries` = 2, a pair as the lecture's generic "Ω₁, Ω₂"). Where the answer is a matrix
/// (`entries` = 9), labels alike but for two indices side by side are its entries, "I_xx = ..,
/// I_yy = .., I_zz = .., I_xy = ..", one not given its mirror's (a symmetric tensor) or zero.
/// @throws InputError naming `field` for such a list whose labels are not one name for each of
///   x, y, z or 1, 2, 3 (its components could be put in no order).
std::optional<LabelledComponents> labelled_components(
    const std::string& text, const std::string& field,
    const std::vector<std::string>& entry_names = {}, std::size_t entries = 3);

/// Some of a 3-vector's components by label, the others left out as zero: "z = −3h/4",
/// "z_cm = −3h/4", "L_z = 0.0139", "x = 0, z = −3h/4" (as a centre of mass on a body's axis is
/// given). `text` is the vector in the reading form ("[0, 0, −3h/4]", a unit after the last
/// value the whole vector's) and `missing` the places of those left out. A label names its axis
/// alone (x), first before an underscore (z_cm), or last (L_z, Lz, ω₃); two labels differ in
/// that one character. nullopt for a text that is no such list.
struct SomeComponents {
  std::string text;
  std::vector<std::size_t> missing;
};
std::optional<SomeComponents> some_components(const std::string& text);

/// `text`, a list of labelled components, without a last item that says the rest are zero:
/// "I_xx = 10 m a², I_yz = m a², others 0" (also "the rest are zero", "all others = 0", "other
/// entries vanish"), as the components left out are read as zero anyway. `text` itself where it
/// ends otherwise, or where no item before it has a label ('=').
std::string without_others_zero(const std::string& text);

/// Mathematica's rules as equations: "E -> 7.371" and Solve's "{{E -> 7.371}}" as "E = 7.371",
/// "{a -> 1, b -> 2}" as "a = 1, b = 2" ("→" as "->"), so that a label reads as after '='.
/// `text` itself where it is no list of rules, each one arrow between two sides.
std::string rules_as_equations(const std::string& text);

/// "0.569, 4.209 and 4.556 kg m²", "Ω₂ = −11.89 and Ω₃ = −7.2": a list's last item after the
/// word "and" (a comma before it or not), as a list is written in words, with a comma in its
/// place; in LaTeX, the word in \text{..} (or \textrm, \mathrm) with the spacing around it
/// ("-11.89 \text{ and } -7.2", ",\quad\text{and}\quad"). `typed` itself where it has none.
std::string and_as_comma(const std::string& typed);

/// `typed` without its comments: each line up to a '#', or up to a '%' at its start or after a
/// space, a tab or a ';' (MATLAB's and LaTeX's: "I0 = 7.2e-4; % kg m^2"; "50%" keeps its sign).
/// No answer wobble reads has either.
std::string without_comments(const std::string& typed);

/// "λ = (2.5, 3, 3.5) m a²" for "λ = 2.5, 3, 3.5 (in units of m a²)": a value given in units of an
/// expression, in brackets or not, as that expression times the value after the last '=' (a list
/// in brackets first); in brackets also "(in m a²)", "(times m a²)", "(× m a²)", "(all × m a²)".
/// `typed` itself where it does not end so.
std::string in_units_of_written(const std::string& typed);

/// `typed` without a remark in words after it, in brackets: "303.6 days" for "303.6 days (Euler's
/// period)", "0.00072 kg m^2" for "0.00072 kg m^2 (about the centre)". A remark is the text's
/// last bracket, after a space, of two words or more in ASCII letters (an apostrophe, a hyphen
/// or a comma between), one of them of three letters or more that `is_known` denies (the
/// problem's symbols, units, functions and Greek letters' names are known): "2 (m R)" stays a
/// product and "2 (I omega)" an error to report, never a remark dropped. `typed` itself
/// otherwise.
std::string without_remark(const std::string& typed,
                           const std::function<bool(const std::string&)>& is_known);

/// An answer with one word after it in brackets that says what the motion does, "1.772 1/s
/// (unstable)", "2.047 rad/s (stable)", "4.995 rad/s (prograde)", or last after a comma, a
/// semicolon, a dash or a space, "2.047 rad/s, stable": the answer and the word as typed. Only
/// words of a short list (stable, unstable, oscillating, growing, prolate, oblate,
/// prograde, retrograde, approx, exact, rounded and their like), none a symbol of any problem,
/// so that "m R^2 (omegs)" is still refused as the misspelt name it is, never dropped.
struct WordRemark {
  std::string answer;   ///< "1.772 1/s"
  std::string bracket;  ///< "(unstable)", or the word alone where it has no bracket: "stable"
  bool bracketed = true;
  /// What the word says of a spin's stability: true for stable, oscillating (and their like),
  /// false for unstable, growing, exponential; empty for a word on something else ("prograde").
  std::optional<bool> says_stable;
  /// What the word says of a precession's sense: true for prograde or oblate (with the spin),
  /// false for retrograde or prolate (against it); empty for a word on something else.
  std::optional<bool> says_with_spin;
};
std::optional<WordRemark> word_remark(const std::string& typed);

/// The text after a program's label of its result: "0.00072" for "Out[3]= 0.00072",
/// "Out[3]//N= 0.00072" or "Out[3]: 0.00072"; `typed` itself when it has no such label.
std::string without_output_label(const std::string& typed);

/// An answer given again, in another unit or rounded, in a bracket after it, as one writes it:
/// "118.8 rad/s (about 1134 rpm)", "(≈ 1134 rpm)", "(i.e. 18.9 Hz)", "(or 0.0811 kg m²/s)".
struct Restatement {
  std::string answer;   ///< "118.8 rad/s"
  std::string again;    ///< "1134 rpm"
  std::string bracket;  ///< "(about 1134 rpm)", as typed
};

/// The restatement in `typed`: its last bracket, after a space, holding a lead (about, approx.,
/// approximately, roughly, around, circa, ca., nearly, i.e., that is, or, =, ≈, ≃, ∼, ~) and
/// then a number (a digit, a point or a sign first). nullopt otherwise: "(about the centre)" is a
/// remark in words (without_remark), "2 (m R)" a product.
std::optional<Restatement> restatement_of(const std::string& typed);

/// Labels before a ':' as one writes an answer down: "0.569, 4.209, 4.556" for "eigenvalues:
/// 0.569, 4.209, 4.556" (a label of up to four words, letters first, no operator or bracket),
/// and components labelled so as with '=', "I1 = 0.569, I2 = 4.209" for "I1: 0.569, I2: 4.209".
/// `typed` itself where no such label is.
std::string without_colon_labels(const std::string& typed);

/// The end of the plain number that starts at `at` in `s` ("90", "1.5", "2e-3"; no sign), or
/// `at` itself if none starts there.
std::size_t number_end(const std::string& s, std::size_t at);

/// Whether `s` is arithmetic on angles in degrees: two numbers in degrees or more joined by a
/// '+' or '-' ("15 deg - 7.63 deg"), or one divided by a number ("15 deg/2"); and no list or
/// vector (no comma, semicolon or square or curly bracket).
bool degrees_joined(const std::string& s);

/// "phi + (90*pi/180)" for "phi + 90 deg": in an expression, a text that names one of the
/// problem's symbols or a function (`in_expression`), each plain number in degrees ("90 deg",
/// "90deg", as "90°" arrives here) as radians, the SI of an expression ("(φ + 90°, θ, ψ − 90°)",
/// "cos(30°)", "sin 15°" as "sin(15°)"), and in arithmetic on angles ("15° − 7.63°", "15°/2").
/// Not a number whose degrees are divided by a unit or raised ("10 deg/s"), nor after a name's
/// digits ("x2 deg"); `ascii` itself where it is neither: "15 deg" alone, or in a vector of
/// numbers, is a number with its unit.
std::string degrees_in_expression(const std::string& ascii,
                                  const std::function<bool(const std::string&)>& in_expression);

/// "4*EllipticK(k)/lambda" for "4K(k)/lambda", "4 K(k)": the complete elliptic integral of the
/// first kind as books write it, K(k) of the modulus k (as the key's EllipticK takes it), where K
/// is no symbol of the problem (`is_symbol`) and stands alone before its bracket; a number or a
/// bracket before it multiplies it. `ascii` itself where there is no such K.
std::string elliptic_integral_named(const std::string& ascii,
                                    const std::function<bool(const std::string&)>& is_symbol);

/// "303.6 day" for "303.6 d", "3.036e2d", "(300 + 3.6) d": the SI's symbol for the day after a
/// number, where d is no symbol of the problem (`is_symbol`); the Earth's Euler period is told
/// in days. Where a problem names a length d (the molecule's bond), "2 d" is twice it, and units
/// refuse d as days everywhere else. `ascii` itself where there is no such d.
std::string days_written_d(const std::string& ascii,
                           const std::function<bool(const std::string&)>& is_symbol);

}  // namespace wobble::check
