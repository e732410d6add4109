#pragma once
/// @file
/// A number worked out with its units, as on paper: "0.5 kg × (0.05 m)²/2", "2π/(303.6 d)",
/// "1 rev / 304.46 sidereal days", "2π rad/(303.6 × 86400 s)". The reader takes one unit after
/// the value; here each unit inside the arithmetic is its SI factor (exactly, through
/// Unit::to_si_exact) and its dimension, and the whole is the number it works out to in the SI
/// unit of its one dimension.
///
/// Conventions, as units are written by hand:
/// - A product written by juxtaposition after a '/' is all of the denominator: "2π rad / 303.6
///   days" is 2π rad per 303.6 days (as "J/kg K" is J/(kg K)); a '*' or '×' ends it. After a
///   number in digits, "1/2 kg" is half a kilogram where only that reading has the answer's
///   dimension (units_worked_out's `key_unit`).
/// - Only a text every name of which is a unit, π or a function: a name that is a symbol of the
///   problem ("0.05 m" where m is a mass) or no unit leaves the text to the reader's refusal,
///   as does a unit with a number after it ("15 h 303 days": a quantity told in parts). d
///   after a number is the day where the problem has no symbol d (written_forms.hpp).
/// - An angle left over in a pure number keeps it an angle (rad), as unit_fits requires: "15°
///   × 2" is an angle, "(2 rad/s)/(4 rad/s)" a ratio.
/// - Plain text, or LaTeX as the reader sets it in text (units upright, "\mathrm{days}"; an
///   upright d the day where d is no symbol); a vector entry by entry (entries_worked_out), a
///   matrix not at all.
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "symbolic/expression.hpp"

namespace wobble::check {

/// A line's worth of an answer quoted in a refusal of it: a longer one is quoted in part.
inline constexpr std::size_t kQuotedCharacters = 60;

struct UnitsWorkedOut {
  std::string text;     ///< for the reader: "2.3952979e-07 1/s" (the value to 17 digits)
  std::string grouped;  ///< as read, for the line: "2π rad / (303.6 days)" (a line's worth)
  std::string unit;     ///< the unit it is written in: "rad/s", "kg m^2", "" (a pure number)
  double value_si = 0;
  /// The problem's symbols read as the units they name after a number ("m" for the metre where
  /// m is a mass): only beside a unit that is no symbol, where the text reads no other way or
  /// only that reading has the answer's dimension.
  std::vector<std::string> symbols_as_units;
};

/// `typed` worked out with its units as above, in `key_unit` where that is an SI unit of its
/// dimension ("rad/s" for 1/s; else the SI unit of powers of kg, m, s); nullopt where it has
/// no unit inside arithmetic or is not read so.
/// @throws InputError naming `field` where it adds or subtracts unlike dimensions ("2 m + 3 s"),
///   takes a unit's root ("(1 m)^(1/3)") or a function of one ("exp(1 m)").
std::optional<UnitsWorkedOut> units_worked_out(const std::string& typed,
                                               const sym::SymbolTable& table,
                                               const std::string& field,
                                               const std::string& key_unit = "");

/// LaTeX as the reader sets it in text, an upright d the day where d is no symbol; where that
/// reading refuses it, with its upright units (\mathrm{kg}, \text{days}) read as names, each a
/// unit here: "0.5\,\mathrm{kg} \cdot (0.05\,\mathrm{m})^2" as "0.5 kg*(0.05 m)^2".
/// @throws InputError the second reading's refusal ("Q is not one of this problem's symbols").
std::string latex_units_as_text(const std::string& typed, const sym::SymbolTable& table,
                                const std::string& field);

/// The name that keeps plain `typed` from being worked out with its units, as the reader reads
/// it: the first that is neither a unit, a symbol of `table`, π nor a function, where a unit is
/// there too ("0.5 kg × Q": Q); "" where there is none, or no unit, or `typed` is LaTeX.
std::string name_beside_units(const std::string& typed, const sym::SymbolTable& table,
                              const std::string& field);

/// The reader's refusal of plain `typed` with each unit in it read as a factor, its units
/// written back as typed: what keeps arithmetic with units all of which are units from being
/// worked out ("0.5 kg (0.05 m)^2 150 rad/s": "products need '*'"); nullopt where it reads so,
/// or has a name that is no unit, or no unit, or is LaTeX.
std::optional<std::string> units_refusal(const std::string& typed, const sym::SymbolTable& table,
                                         const std::string& field);

/// A vector's entries worked out so where one does not read as typed and holds a unit inside
/// arithmetic ("(−2 rad/s × sin 30°, 0.5 rad/s, 2 rad/s × cos 30° + 10 rad/s)"): the vector
/// with those entries as their numbers in `key_unit` (as units_worked_out), each other entry as
/// typed (a unit after each entry reads, a zero may go without), and the entries so read, by
/// index from 0; nullopt where no entry is so or `typed` is no bracketed list.
/// @throws InputError as units_worked_out, for an entry.
struct EntriesWorkedOut {
  std::string text;  ///< "(-1 rad/s, 0.5 rad/s, 11.73 rad/s)"
  std::vector<std::pair<std::size_t, UnitsWorkedOut>> worked;
};
std::optional<EntriesWorkedOut> entries_worked_out(const std::string& typed,
                                                   const sym::SymbolTable& table,
                                                   const std::string& field,
                                                   const std::string& key_unit);

}  // namespace wobble::check
