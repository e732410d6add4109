#pragma once
/// @file
/// Why an answer could not be read, in the words a student needs (inside the check layer only:
/// judge.cpp appends these to the reader's refusals). What the text more likely meant (a decimal
/// comma, digits grouped by threes, an imaginary number), what a name the problem has no symbol
/// for stands for and what may be written instead, and what kept arithmetic with units from
/// being worked out. A hint is a remark in parentheses to append, " (..)", or "" where none
/// applies; refused_beside_units gives a whole refusal in place of the reader's.
#include <optional>
#include <string>

#include "check/judge.hpp"
#include "core/input_error.hpp"

namespace wobble::check::detail {

/// What `typed` more likely meant, in parentheses, or "". Where one number is wanted: a decimal
/// comma ("15,5deg" reads as two entries) or digits grouped by threes ("26,233,128.66 s" reads as
/// a 3-vector, "26 233 128.66 s" as numbers side by side). Where a vector or matrix is, and
/// `entries_read` were read: decimal commas, each splitting an entry in two ("(0,57, 4,21,
/// 4,56)" as a 6-vector).
std::string misreading_hint(const Answer& a, const std::string& typed,
                            std::optional<std::size_t> entries_read);

/// A hint where a number is wanted and `typed` gives an imaginary one, or "": an i or a j standing
/// alone ("9.131i rad/s"; Python's 9.131j), read as a unit vector, or the root of a negative
/// number (the reader's `message` says "not real"). The frequency of a perturbation about the
/// unstable axis is imaginary; the key asks for its rate of growth.
std::string imaginary_hint(const Answer& a, const std::string& typed, const std::string& message);

/// A symbol as a line names it: "the problem's symbol for the height" (its description).
std::string symbol_described(const Context& ctx, const std::string& name);

/// Where every letter group of a unit as read is also a symbol of the problem ("h" where h is a
/// height, "0.75 h ẑ" read as hours): a line naming them, with what to write for the product;
/// "" otherwise. After a number the letters are the unit (as "0.5 m" is half a metre even where
/// m is a mass); the line says so where that reading gave the wrong dimension and reading them
/// as the symbols does not give the answer's either (judge.cpp's judged_as_product reads them
/// so where it does).
std::string unit_spelling_symbols(const Context& ctx, const std::string& unit_text);

/// " (the key's steps' I1, I3, omega3 (ω3) and its answers' names up to part (b) read too)":
/// where a name is refused and no name in `typed` has a hint, what may be written besides the
/// problem's symbols (the reader's list names those); "" where the key reads no other name in `a`.
std::string names_read_too(const Context& ctx, const Answer& a);

/// Whether the reader's `message` refuses a name that may have been meant for one the key reads:
/// not a unit's ("kg is not one of this problem's symbols" for a unit inside arithmetic).
bool name_refused(const std::string& message);

/// For the reader's refusal `message` of `typed`: the hint of the first name in `typed` that
/// has one ("I₀ diag(1, 1, 2)": I₀ is an answer, not a symbol; ψ̇ for the given ψ̇₀; a name the
/// statement defines), else where norm(..) was refused what it reads, else where a name was
/// refused the names the key reads besides the problem's symbols; "" otherwise.
std::string answer_name_hint(const Context& ctx, const Answer& a, const std::string& typed,
                             const std::string& message);

/// "0.5\,\mathrm{kg} \cdot Q", "0.5 kg × Q": arithmetic with units, refused for a unit in it
/// ("kg is not one of this problem's symbols", "cannot read the unit 'kg × Q'"), where another
/// name keeps it from being worked out (unit_arithmetic.hpp): that name's refusal, with the names
/// the key reads; nullopt where `refusal` names no unit or no such name is there.
std::optional<InputError> refused_beside_units(const Context& ctx, const Answer& a,
                                               const std::string& text, const std::string& refusal);

}  // namespace wobble::check::detail
