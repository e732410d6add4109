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

}  // namespace wobble::check
