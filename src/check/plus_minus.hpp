#pragma once
/// @file
/// Answers with a '±': "±9.131 1/s" for the growth rate of a perturbation about the unstable
/// axis (the roots of Ω² = −83.4 s⁻²), "(I3ω3 ± √(..))/(2 I1 cos θ)" for the heavy top's
/// precession rates (the roots of a quadratic). Such an answer is two answers; each is judged
/// and the student is told which of them, if any, is right. The sign is written '±' or '∓'
/// (Unicode), "+/-", "+-" or "-/+" (ASCII), \pm or \mp (LaTeX). Every '±' takes the same sign
/// in one reading and every '∓' the other, as in the books' (a ± b)(c ∓ d).
#include <optional>
#include <string>

namespace wobble::check {

/// The answer written with each sign: `plus` with every '±' as '+' (and '∓' as '-'), `minus`
/// the other way.
struct SignReadings {
  std::string plus;
  std::string minus;
};

/// The two readings of `text` if it has a '±' in any of its spellings, or nullopt.
std::optional<SignReadings> sign_readings(const std::string& text);

}  // namespace wobble::check
