#pragma once
/// @file
/// A power of ten whose superscript was lost: "7.2 × 10−4" (a PDF's 10⁻⁴ copied as text) or
/// "7.2*10-4" (typed so) is 7.2 × (10 − 4) to the reader, which reads a '-' as a minus wherever
/// it stands. The judge reads such an answer as written, and says how it was read and how a
/// power of ten is written (judge.hpp).
///
/// A lost power is "10", then a minus ('-', '−' or '–') and one to three digits, right after a
/// times sign ('*', '×', '·', '⋅', or the letter x) that follows a number: "7.2 x 10-4 kg m^2",
/// "[7.2*10-4, 0]". "10 - 4" (spaced), "2*10-4.5", "a*10-4" and "710-4" are not: each
/// reads as the difference it writes.
#include <optional>
#include <string>

namespace wobble::check {

struct LostPower {
  std::string as_powers;  ///< the text with each lost power written as one: "7.2 × 10^-4"
  std::string written;    ///< the first as typed: "10−4"
  std::string exponent;   ///< its digits, which a power's minus makes negative: "4"
};

/// The text's lost powers of ten, nullopt where it has none.
std::optional<LostPower> lost_powers_of_ten(const std::string& text);

}  // namespace wobble::check
