#pragma once
/// @file
/// A least or greatest value given as the bound it is: "ω₃ ≥ 118.8 rad/s" for the least spin
/// at which the top sleeps, "θ ≤ 0.78 rad" for the largest tilt (the solver says which answers
/// are bounds: Answer::bound).
#include <optional>
#include <string>

namespace wobble::check {

/// One comparison at the top level of `text` (outside brackets): ≥ ⩾ >= > \geq \ge \geqslant,
/// ≤ ⩽ <= < \leq \le \leqslant, each side trimmed and not empty.
struct Inequality {
  std::string left, right;
  bool left_greater = false;  ///< L ≥ R (or L > R); else L ≤ R (or L < R)
  std::string sign;           ///< as written: "≥", ">=", "\geq", ...
};
/// nullopt where there is no comparison, more than one, or a side is empty.
std::optional<Inequality> inequality_of(const std::string& text);

/// A range as a chain of two comparisons that point the same way: "30° ≤ θ ≤ 44.7°" (or
/// "44.7° ≥ θ ≥ 30°") for the nutation's limits, each end trimmed and not empty.
struct Range {
  std::string lower, quantity, upper;
  std::string sign;  ///< the first as written: "≤", "<", "\leq", ...
};
/// Or an interval, "θ ∈ [30°, 44.7°]" or "theta in [0.52, 0.78]" (`sign` "∈" or "in"). nullopt
/// where `text` is no such chain (one comparison, three, or two that point both ways).
std::optional<Range> range_of(const std::string& text);

/// "30° ≤ θ ≥ 44.7°": two comparisons that point both ways, written as a range ("30° ≤ θ ≤
/// 44.7°", the first sign twice), for a message; nullopt otherwise.
std::optional<std::string> range_both_ways(const std::string& text);

}  // namespace wobble::check
