#include "check/inequality.hpp"

#include <array>
#include <cctype>
#include <string_view>
#include <utility>

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

std::optional<Inequality> inequality_of(const std::string& text) {
  std::optional<Inequality> found;
  int depth = 0;
  for (std::size_t i = 0; i < text.size();) {
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
    if (found) return std::nullopt;  // "a < b < c": no one bound
    Inequality q;
    q.left = trim(text.substr(0, i));
    q.right = trim(text.substr(i + sign->first.size()));
    q.left_greater = sign->second;
    q.sign = std::string(sign->first);
    found = std::move(q);
    i += sign->first.size();
  }
  if (found && (found->left.empty() || found->right.empty())) return std::nullopt;
  return found;
}

}  // namespace wobble::check
