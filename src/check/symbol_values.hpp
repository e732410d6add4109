#pragma once
/// @file
/// Numbers in a student's expression that are a parameter's value at the set values: "0.12" in
/// "m 0.12²/4" where R is 0.12 m, "30°" in "(φ, 30°, ψ)" where θ is 30°. An expression right at
/// the set values and wrong away from them most likely has such a number where the key has the
/// symbol; the judge (judge.cpp) writes the symbols in and, where that makes the key's
/// expression, says which to write.
#include <string>
#include <vector>

#include "solvers/key.hpp"

namespace wobble::check {

/// A parameter a number may stand for.
struct Candidate {
  std::string name;   ///< as typed in expressions: "theta"
  std::string shown;  ///< as printed, and as typed where that differs: "θ (theta)", "R"
  bool in_degrees = false;  ///< the number is the angle's value in degrees, without its mark
};

/// One number and the parameters whose value it is (more than one where they share a value:
/// I₃ and θ̇ both 0.5).
struct NumberForSymbol {
  std::string number;  ///< as typed, a degree as "°" ("0.12", "30°")
  std::vector<Candidate> candidates;
  bool rounded = false;            ///< a value rounded to the digits typed ("0.2618" for α)
  std::size_t at = 0, length = 0;  ///< where the number is in sym::to_ascii(typed), "deg" too
};

/// The key's parameter of that name, or nullptr.
const ParameterValue* parameter_named(const Key& key, const std::string& name);

/// A parameter as printed, with its typed name where that differs: "θ (theta)", "R".
std::string shown_of(const ParameterValue& p);

/// The numbers in `typed` (read in ASCII; in degrees where "°" or "deg" follows) equal to a
/// nonzero parameter value of `key` to 1e-9, or, typed to three significant digits or more, to
/// within half a unit in their last digit; in the order typed. An angle's value in degrees
/// without "°" counts too ("15" for α = 15°, of two digits or more), its candidate marked
/// in_degrees: the number stands for the angle, but as radians it is not its value. An exponent
/// ("R^2") is no such number, nor a digit of a name ("R2"), nor a single digit without "°" ("/2",
/// "(1/2)": a coefficient far more often than a value).
std::vector<NumberForSymbol> numbers_for_symbols(const Key& key, const std::string& typed);

/// The symbols in `typed` (read in ASCII) whose nonzero set value another parameter shares
/// to 1e-9 (the Euler angles' θ̇ and I₃, both 0.5), in the order typed: each as a
/// NumberForSymbol whose `number` is the symbol as printed ("θ̇ (thetadot)") and whose
/// candidates are the others. A symbol of the same value in another's place is right at the set
/// values only, as a number in a symbol's place is.
std::vector<NumberForSymbol> symbols_sharing_values(const Key& key, const std::string& typed);

/// The numbers in `typed` (read in ASCII) that may be degrees written without their mark, "90"
/// in "φ + 90" where the key has φ + π/2: of two digits or more (a single digit is a
/// coefficient), not an exponent, not followed by "deg" or "°", at most 360. Each has one
/// candidate, the number in radians as an expression ("(90*pi/180)") shown as "90°".
std::vector<NumberForSymbol> numbers_as_degrees(const std::string& typed);

/// sym::to_ascii(typed) with each of `numbers` replaced by its candidate numbered in `choice`
/// (one index per number; the count of its candidates leaves it as it is).
std::string with_symbols(const std::string& typed, const std::vector<NumberForSymbol>& numbers,
                         const std::vector<std::size_t>& choice);

}  // namespace wobble::check
