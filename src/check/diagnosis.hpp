#pragma once
/// @file
/// Diagnosing a wrong number: which known mistake it is (a table of predicate and message), else
/// how far off each entry is. The judge (judge.hpp) decides that an answer is wrong and hands
/// over what it found as data; nothing here decides right or wrong.
///
/// The mistakes, tried in this order (the first that matches is named): products of inertia
/// with the wrong sign; a reversed sign (for a signed precession rate: what its sign means);
/// degrees for radians; turns per second for rad/s; 2π times a rate (Hz taken as rad/s); the
/// components in another frame (answer kind and frame, solvers/key.hpp); another answer of the
/// key; a factor 2, 1/2, 4, 1/4, 12, 1/12, 3 or 1/3.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "check/units.hpp"
#include "solvers/key.hpp"

namespace wobble::check {

/// What the judge found: the typed and expected values (SI, in the key's order), and how it
/// decides that two values agree (the tolerance of this answer).
struct Finding {
  const Answer& answer;
  const Key& key;  ///< for the other answers a wrong value may be
  std::vector<double> typed, expected;
  Unit key_unit;
  std::function<bool(double typed, double expected)> close;
  double zero_scale = 1.0;  ///< what a zero is judged against (judge.hpp)

  bool all_close(const std::vector<double>& v, const std::vector<double>& k) const;
  std::vector<double> expected_times(double factor) const;
};

/// One known mistake: its name (for tests and the README) and a test that returns the message
/// when the finding shows it.
struct Mistake {
  std::string name;
  std::function<std::optional<std::string>(const Finding&)> message_if_seen;
};

/// The known mistakes, in the order they are tried.
const std::vector<Mistake>& known_mistakes();

/// The first known mistake's message, else how far off the value (or each wrong entry) is.
std::vector<std::string> diagnose(const Finding& finding);

}  // namespace wobble::check
