#include "check/rotations.hpp"

#include <algorithm>
#include <array>
#include <string_view>
#include <vector>

#include "check/brackets.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"

namespace wobble::check {

namespace {
// A 3x3 matrix of expressions as text; "0" and "1" are kept as such, so that products of them
// write nothing.
using Text3 = std::array<std::array<std::string, 3>, 3>;

Text3 turn(char axis, const std::string& angle) {
  const std::string c = "cos(" + angle + ")", s = "sin(" + angle + ")",
                    ms = "(-sin(" + angle + "))";
  if (axis == 'x') return {{{"1", "0", "0"}, {"0", c, ms}, {"0", s, c}}};
  if (axis == 'y') return {{{c, "0", s}, {"0", "1", "0"}, {ms, "0", c}}};
  return {{{c, ms, "0"}, {s, c, "0"}, {"0", "0", "1"}}};
}

std::string times(const std::string& a, const std::string& b) {
  if (a == "1") return b;
  if (b == "1") return a;
  return "(" + a + ")*(" + b + ")";
}

Text3 product(const Text3& a, const Text3& b) {
  Text3 p;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      std::string sum;
      for (std::size_t k = 0; k < 3; ++k) {
        if (a[i][k] == "0" || b[k][j] == "0") continue;
        sum += (sum.empty() ? "" : " + ") + times(a[i][k], b[k][j]);
      }
      p[i][j] = sum.empty() ? "0" : sum;
    }
  }
  return p;
}

// A turn's angle as the answer reader takes it inside a function: "40°" and "40 deg" as
// "(40)*pi/180", a unit being no part of an expression.
std::string in_radians(const std::string& angle) {
  for (const std::string_view mark : {"°", "deg"}) {
    if (angle.size() > mark.size() &&
        angle.compare(angle.size() - mark.size(), mark.size(), mark) == 0) {
      return "(" + trim(angle.substr(0, angle.size() - mark.size())) + ")*pi/180";
    }
  }
  return angle;
}

// After a factor, besides the transpose marks, those of its inverse and the prime as a page
// sets it: for a turn each is the turn back.
constexpr std::array<std::string_view, 5> kInverseMarks{"^{-1}", "^(-1)", "^-1", "⁻¹", "′"};

// One pair of brackets around all of `s`, dropped: "(Rz(φ) Ry(θ))" -> "Rz(φ) Ry(θ)".
std::string unwrapped(const std::string& s) {
  if (s.size() < 2 || s.front() != '(' || s.back() != ')') return s;
  int depth = 0;
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    depth += s[i] == '(' ? 1 : s[i] == ')' ? -1 : 0;
    if (depth == 0) return s;  // "(a)(b)": the first bracket closes before the end
  }
  return trim(s.substr(1, s.size() - 2));
}
// The calls that transpose or invert a whole product, as programs write them: MATLAB's and
// NumPy's, Mathematica's in square brackets.
constexpr std::array<std::string_view, 9> kInvertingCalls{
    "transpose(",       "inverse(",          "inv(",       "np.transpose(", "np.linalg.inv(",
    "numpy.transpose(", "numpy.linalg.inv(", "Transpose[", "Inverse["};

// The product inside a mark or a call that transposes or inverts all of it ("(Rz(φ) Ry(θ))⁻¹",
// "transpose(Rz(φ) Ry(θ))", "Inverse[..]", NumPy's "(..).T"); nullopt if `s` is no such thing.
// For turns transposing is inverting: both are the turns back in reverse order.
std::optional<std::string> inverted_whole(const std::string& s) {
  for (const std::string_view call : kInvertingCalls) {
    if (s.compare(0, call.size(), call) != 0) continue;
    const char close = call.back() == '[' ? ']' : ')';
    // The call's bracket closes at the end, not before.
    if (s.back() != close || matching(s, call.size() - 1) != s.size() - 1) return std::nullopt;
    return trim(s.substr(call.size(), s.size() - call.size() - 1));
  }
  if (s.empty() || s.front() != '(') return std::nullopt;
  const std::size_t close = matching(s, 0);
  if (close == std::string::npos) return std::nullopt;
  const std::string_view mark = std::string_view(s).substr(close + 1);
  const auto is_mark = [&](const auto& marks) {
    return std::find(marks.begin(), marks.end(), mark) != marks.end();
  };
  if (!is_mark(kTransposeMarks) && !is_mark(kInverseMarks) && mark != ".T") return std::nullopt;
  return trim(s.substr(1, close - 1));
}
}  // namespace

std::optional<std::string> rotations_multiplied(const std::string& typed,
                                                const std::string& field) {
  std::string s = unwrapped(trim(typed));
  const std::optional<std::string> inside = inverted_whole(s);
  if (inside) s = unwrapped(*inside);
  std::vector<std::pair<char, std::string>> turns;
  for (std::size_t i = 0; i < s.size();) {
    bool joined = false;  // spaces or a product's sign between factors
    for (const std::string_view sep : {" ", "*", "·", "⋅", "\\cdot", "\\,", "\\;"}) {
      if (s.compare(i, sep.size(), sep) == 0) {
        i += sep.size();
        joined = true;
        break;
      }
    }
    if (joined) continue;
    // "Rz(", "R_z(", "R_{z}(" and the angle up to the bracket that closes it.
    if (s[i] != 'R') return std::nullopt;
    std::size_t j = i + 1;
    const bool braced = s.compare(j, 2, "_{") == 0;
    j += braced ? 2 : s.compare(j, 1, "_") == 0 ? 1 : 0;
    if (j >= s.size() || (s[j] != 'x' && s[j] != 'y' && s[j] != 'z')) return std::nullopt;
    const char axis = s[j++];
    if (braced && (j >= s.size() || s[j++] != '}')) return std::nullopt;
    if (j >= s.size() || s[j] != '(') return std::nullopt;
    int depth = 0;
    std::size_t close = j;
    for (; close < s.size(); ++close) {
      depth += s[close] == '(' ? 1 : s[close] == ')' ? -1 : 0;
      if (depth == 0) break;
    }
    if (close >= s.size() || close == j + 1) return std::nullopt;
    if (close - j - 1 > kLongestTurnAngle) {
      throw InputError(field + ": a turn's angle of " + std::to_string(close - j - 1) +
                       " characters; at most " + std::to_string(kLongestTurnAngle) +
                       " (write the matrix's entries instead)");
    }
    std::string angle = in_radians(trim(s.substr(j + 1, close - j - 1)));
    i = close + 1;
    // A turn transposed or inverted is the turn back: "Rz(ψ)ᵀ", "R_z(\psi)^T", "Rz(ψ)⁻¹".
    const auto marked = [&](const auto& marks) {
      for (const std::string_view mark : marks) {
        if (s.compare(i, mark.size(), mark) != 0) continue;
        i += mark.size();
        return true;
      }
      return false;
    };
    if (marked(kTransposeMarks) || marked(kInverseMarks)) angle = "-(" + angle + ")";
    turns.emplace_back(axis, angle);
  }
  if (turns.empty()) return std::nullopt;
  if (inside) {  // (A B C)⁻¹ = C⁻¹ B⁻¹ A⁻¹, each turn back
    std::reverse(turns.begin(), turns.end());
    for (auto& turn : turns) turn.second = "-(" + turn.second + ")";
  }
  if (turns.size() > static_cast<std::size_t>(kMostTurns)) {
    throw InputError(field + ": " + std::to_string(turns.size()) + " turns in a product; at most " +
                     std::to_string(kMostTurns) + " (Euler's angles take three)");
  }
  Text3 m = turn(turns[0].first, turns[0].second);
  for (std::size_t k = 1; k < turns.size(); ++k)
    m = product(m, turn(turns[k].first, turns[k].second));
  std::string text = "[";
  for (std::size_t i = 0; i < 3; ++i)
    text += std::string(i ? ", " : "") + "[" + m[i][0] + ", " + m[i][1] + ", " + m[i][2] + "]";
  return text + "]";
}

}  // namespace wobble::check
