#include "check/inequality.hpp"

#include <array>
#include <cctype>
#include <string_view>
#include <utility>
#include <vector>

#include "check/brackets.hpp"
#include "core/characters.hpp"

namespace wobble::check {

namespace {

// The signs, longest first where one begins another (">=" before ">", "\geqslant" before
// "\geq" before "\ge"); true for a "greater" sign.
constexpr std::array<std::pair<std::string_view, bool>, 14> kSigns{{
    {"≥", true},       {"⩾", true},       {">=", true},      {"\\geqslant", true},
    {"\\geq", true},   {"\\ge", true},    {">", true},       {"≤", false},
    {"⩽", false},      {"<=", false},     {"\\leqslant", false}, {"\\leq", false},
    {"\\le", false},   {"<", false},
}};

// The sign at `at` in `s`, if one is there: a LaTeX command only as a whole word ("\le", not
// the start of "\left").
const std::pair<std::string_view, bool>* sign_at(const std::string& s, std::size_t at) {
  // "E -> 7.37": an arrow, as Mathematica writes a rule, compares nothing.
  if (s[at] == '>' && at > 0 && s[at - 1] == '-') return nullptr;
  for (const auto& sign : kSigns) {
    if (s.compare(at, sign.first.size(), sign.first) != 0) continue;
    const std::size_t after = at + sign.first.size();
    if (sign.first[0] == '\\' && after < s.size() &&
        std::isalpha(static_cast<unsigned char>(s[after])))
      continue;
    return &sign;
  }
  return nullptr;
}

}  // namespace

namespace {
// A comparison's sign at the top level of a text: where it starts, and which.
struct SignAt {
  std::size_t at;
  const std::pair<std::string_view, bool>* sign;
};

// Every comparison sign at the top level of `text` (outside brackets), at most `most` + 1: more
// than `most` says only that there are too many.
std::vector<SignAt> signs_of(const std::string& text, std::size_t most) {
  std::vector<SignAt> found;
  int depth = 0;
  for (std::size_t i = 0; i < text.size() && found.size() <= most;) {
    const char c = text[i];
    if (opens(c) || closes(c)) {
      depth += opens(c) ? 1 : -1;
      ++i;
      continue;
    }
    const auto* sign = depth == 0 ? sign_at(text, i) : nullptr;
    if (sign == nullptr) {
      ++i;
      continue;
    }
    found.push_back({i, sign});
    i += sign->first.size();
  }
  return found;
}
}  // namespace

std::optional<Inequality> inequality_of(const std::string& text) {
  const std::vector<SignAt> signs = signs_of(text, 1);
  if (signs.size() != 1) return std::nullopt;  // "a < b < c": no one bound
  const auto [at, sign] = signs.front();
  Inequality q;
  q.left = trim(text.substr(0, at));
  q.right = trim(text.substr(at + sign->first.size()));
  q.left_greater = sign->second;
  q.sign = std::string(sign->first);
  if (q.left.empty() || q.right.empty()) return std::nullopt;
  return q;
}

namespace {
// "θ ∈ [30°, 44.7°]", "theta in [0.52, 0.78] rad": an interval, closed or open at either end,
// as the range it is, a unit after it each end's; nullopt for anything else.
std::optional<Range> interval_of(const std::string& text) {
  for (const std::string_view member : {"∈", " in "}) {
    const std::size_t at = text.find(member);
    if (at == std::string::npos) continue;
    const std::string quantity = trim(text.substr(0, at));
    const std::string interval = trim(text.substr(at + member.size()));
    if (quantity.empty() || interval.empty() || !opens(interval.front())) return std::nullopt;
    const std::size_t close = matching(interval, 0);
    if (close == std::string::npos) return std::nullopt;
    const std::string unit = trim(interval.substr(close + 1));
    std::vector<std::string> ends = top_level(interval.substr(1, close - 1), ',');
    if (ends.size() != 2 || ends[0].empty() || ends[1].empty()) return std::nullopt;
    for (std::string& end : ends) {
      if (!unit.empty()) end += " " + unit;
    }
    return Range{ends[0], quantity, ends[1], std::string(member == "∈" ? "∈" : "in")};
  }
  return std::nullopt;
}
}  // namespace

namespace {
// The three sides of a chain of two comparisons, each trimmed; nullopt where one is empty.
std::optional<std::array<std::string, 3>> chain_sides(const std::string& text,
                                                      const std::vector<SignAt>& signs) {
  const std::size_t first_end = signs[0].at + signs[0].sign->first.size();
  std::array<std::string, 3> sides{trim(text.substr(0, signs[0].at)),
                                   trim(text.substr(first_end, signs[1].at - first_end)),
                                   trim(text.substr(signs[1].at + signs[1].sign->first.size()))};
  for (const std::string& side : sides) {
    if (side.empty()) return std::nullopt;
  }
  return sides;
}
}  // namespace

std::optional<Range> range_of(const std::string& text) {
  const std::vector<SignAt> signs = signs_of(text, 2);
  if (signs.empty()) return interval_of(text);
  if (signs.size() != 2 || signs[0].sign->second != signs[1].sign->second) return std::nullopt;
  const auto sides = chain_sides(text, signs);
  if (!sides) return std::nullopt;
  const auto& [left, middle, right] = *sides;
  const bool descending = signs[0].sign->second;  // "44.7° ≥ θ ≥ 30°"
  return Range{descending ? right : left, middle, descending ? left : right,
               std::string(signs[0].sign->first)};
}

std::optional<std::string> range_both_ways(const std::string& text) {
  const std::vector<SignAt> signs = signs_of(text, 2);
  if (signs.size() != 2 || signs[0].sign->second == signs[1].sign->second) return std::nullopt;
  const auto sides = chain_sides(text, signs);
  if (!sides) return std::nullopt;
  const std::string sign(signs[0].sign->first);
  return (*sides)[0] + " " + sign + " " + (*sides)[1] + " " + sign + " " + (*sides)[2];
}

}  // namespace wobble::check
