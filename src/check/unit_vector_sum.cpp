#include "check/unit_vector_sum.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <map>
#include <set>
#include <string_view>
#include <utility>
#include <vector>

#include "check/answer_reading.hpp"
#include "check/basis_vectors.hpp"
#include "check/brackets.hpp"
#include "check/latex_answer.hpp"
#include "check/text_terms.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"
#include "symbolic/unicode_notation.hpp"
#include "symbolic/units.hpp"

namespace wobble::check::detail {

namespace {
// The unit vectors written with a hat, precomposed or with a combining one, and the axis of each
// (0, 1, 2: x, y, z), and the body's e₁, e₂, e₃ and the primed e₁′, e₂′, e₃′ as
// basis_vectors_spelled writes them (3 to 5, 6 to 8: other bases, which a sum may not mix). The
// primed first, so that "ê₁′" is not found as "ê₁".
constexpr std::array<std::pair<std::string_view, int>, 16> kHattedUnitVectors{
    {{kBodyUnitVectors[3], 6},
     {kBodyUnitVectors[4], 7},
     {kBodyUnitVectors[5], 8},
     {"i\u0302", 0},
     {"x\u0302", 0},
     {"î", 0},
     {"j\u0302", 1},
     {"y\u0302", 1},
     {"ĵ", 1},
     {"ŷ", 1},
     {"k\u0302", 2},
     {"z\u0302", 2},
     {"ẑ", 2},
     {kBodyUnitVectors[0], 3},
     {kBodyUnitVectors[1], 4},
     {kBodyUnitVectors[2], 5}}};

// The unit vector written with a hat at `typed[at]`, the first of the list that matches there (the
// primed before their unprimed prefixes); end() if none.
auto hatted_at(const std::string& typed, std::size_t at) {
  return std::find_if(kHattedUnitVectors.begin(), kHattedUnitVectors.end(), [&](const auto& h) {
    return typed.compare(at, h.first.size(), h.first) == 0;
  });
}

// The axis (0, 1, 2) a bare letter at s[at] names as a unit vector, -1 if none: i, j or k where
// the problem has no such symbol; with `xyz`, x, y or z too, not an x before a number (a times
// sign: "7.2 x 10^-4").
int bare_axis(const std::string& s, std::size_t at, const sym::SymbolTable& table, bool xyz) {
  const char c = s[at];
  const bool ijk = c == 'i' || c == 'j' || c == 'k';
  if (!(ijk || (xyz && (c == 'x' || c == 'y' || c == 'z'))) || table.contains(std::string(1, c)))
    return -1;
  std::size_t next = at + 1;
  while (next < s.size() && s[next] == ' ') ++next;
  if (c == 'x' && next < s.size() && std::isdigit(static_cast<unsigned char>(s[next]))) return -1;
  return ijk ? c - 'i' : c - 'x';
}

// "0.5i + 1.5k" -> "0.5 i + 1.5 k": i, j or k (x, y, z with `xyz`) glued to the number before
// it, where the problem has no such symbol, set apart (a number swallows the letters after it
// when names are found).
std::string unit_vectors_unglued(const std::string& s, const sym::SymbolTable& table,
                                 bool xyz = false) {
  std::string out;
  for (std::size_t p = 0; p < s.size(); ++p) {
    const char c = s[p];
    const bool glued = bare_axis(s, p, table, xyz) >= 0 && p > 0 &&
                       (std::isdigit(static_cast<unsigned char>(s[p - 1])) || s[p - 1] == '.') &&
                       (p + 1 == s.size() ||
                        (!std::isalnum(static_cast<unsigned char>(s[p + 1])) && s[p + 1] != '_'));
    if (glued) out += ' ';
    out += c;
  }
  return out;
}
}  // namespace

// The unit vectors `typed` writes components along, for a message ("0.5 i + j + 1.5 k", "x̂ +
// 2ŷ"): a letter i, j, k, x, y or z with a hat (precomposed or combining), and i, j, k alone
// where the problem has no such symbol. "" if none.
std::string unit_vectors_named(const std::string& typed, const sym::SymbolTable& table) {
  std::map<std::string, std::size_t> first;  // each name and where it first stands
  const auto add = [&](std::size_t at, const std::string& name) {
    if (!first.count(name) || at < first[name]) first[name] = at;
  };
  // The hatted ones blanked, so that the k of "k̂" (k and a combining hat) is not named again.
  std::string blanked = typed;
  for (std::size_t at = 0; at < typed.size();) {
    const auto hatted = hatted_at(typed, at);
    if (hatted == kHattedUnitVectors.end()) {
      ++at;
    } else {
      add(at, std::string(hatted->first));
      blanked.replace(at, hatted->first.size(), hatted->first.size(), ' ');
      at += hatted->first.size();
    }
  }
  const std::string unglued = unit_vectors_unglued(blanked, table);
  for (const auto& [start, length] : identifiers(unglued)) {
    const std::string name = unglued.substr(start, length);
    if ((name == "i" || name == "j" || name == "k") && !table.contains(name)) add(start, name);
  }
  std::vector<std::pair<std::size_t, std::string>> in_order;
  for (const auto& [name, at] : first) in_order.emplace_back(at, name);
  std::sort(in_order.begin(), in_order.end());
  std::string found;
  for (const auto& [at, name] : in_order) found += (found.empty() ? "" : ", ") + name;
  return found;
}

// How many bases the unit vectors of unit_vectors_named's list are of (space x̂ ŷ ẑ, body ê₁,
// primed ê₁′): a sum over more than one is no vector's components in one basis.
std::size_t bases_named(const std::string& vectors) {
  std::set<int> bases;
  for (std::size_t from = 0; from < vectors.size();) {
    const std::size_t end = std::min(vectors.find(", ", from), vectors.size());
    const std::string name = vectors.substr(from, end - from);
    bases.insert(name.find("′") != std::string::npos   ? 2
                 : name.find("ê") != std::string::npos ? 1
                                                       : 0);
    from = end + 2;
  }
  return bases.size();
}

// `typed` with each unit vector as a marker "@0", "@1" or "@2" (x, y, z), spaced apart; bare x,
// y and z too with `xyz`.
std::string unit_vectors_marked(const std::string& typed, const sym::SymbolTable& table, bool xyz) {
  // One pass: replacing each in turn moved the text's tail once per unit vector, quadratic in a
  // sum of thousands.
  std::string s;
  for (std::size_t at = 0; at < typed.size();) {
    const auto hatted = hatted_at(typed, at);
    if (hatted == kHattedUnitVectors.end()) {
      s += typed[at++];
    } else {
      s += " @" + std::to_string(hatted->second) + " ";
      at += hatted->first.size();
    }
  }
  s = unit_vectors_unglued(s, table, xyz);
  std::string out;
  std::size_t done = 0;
  for (const auto& [start, length] : identifiers(s)) {
    const int axis = length == 1 ? bare_axis(s, start, table, xyz) : -1;
    if (axis < 0) continue;
    out += s.substr(done, start - done) + " @" + std::to_string(axis) + " ";
    done = start + length;
  }
  return out + s.substr(done);
}

namespace {
// `text`, or what is inside the brackets around it, if it is a unit ("rad/s", "(rad/s)"); "" if
// not. After a coefficient in the problem's symbols, one that names only symbols is a factor, as
// after an expression elsewhere ("ω e₃ m" where m is the mass; "m R² ω e₃ kg m²/s" has a unit);
// after a plain number, a unit ("0.0139 e₃ m").
std::string unit_after_term(const std::string& text, const std::string& coefficient,
                            const sym::SymbolTable& table) {
  std::string unit = text;
  if (unit.size() > 2 && unit.front() == '(' && unit.back() == ')')
    unit = trim(unit.substr(1, unit.size() - 2));
  if (unit.empty()) return "";
  if (has_identifier_of(coefficient, table) && all_identifiers_of(unit, table)) return "";
  try {
    // "kg m²/s", "s⁻¹", "\mathrm{rad\,s^{-1}}" as the reader takes them; LaTeX reads a unit
    // after a value only, so after a 1 here.
    std::string plain = sym::to_ascii(unit);
    if (looks_like_latex(unit)) {
      plain = trim(latex_as_text("1\\," + unit, table, "unit"));
      if (plain.empty() || plain[0] != '1') return "";
      plain.erase(0, 1);
    }
    (void)parse_unit(trim(plain), "unit");
    return unit;
  } catch (const InputError&) {
    return "";
  }
}

// A coefficient as plain ASCII text: "19.3\,\mathrm{rad/s}\," as "19.3 rad/s"; "" if its
// LaTeX does not read.
std::string plain_coefficient(const std::string& coefficient, const sym::SymbolTable& table) {
  if (!looks_like_latex(coefficient)) return sym::to_ascii(coefficient);
  try {
    return trim(latex_as_text(coefficient, table, "coefficient"));
  } catch (const InputError&) {
    return "";
  }
}
}  // namespace

// "0.5 i + j - 1.5 k", "(0.5 x̂ + 1.5 ẑ) m", "î/2 + (a/2) ĵ": a sum of terms, each a coefficient
// times one unit vector, written as "[0.5, 1, -1.5]" (with the unit after). A unit after the
// last term only is the whole sum's, as the bracketed form's ("2.59 î + 19.3 k̂ rad/s"); after
// every term, each component's ("2.59 î rad/s + 19.3 k̂ rad/s", or before each unit vector,
// "2.59 rad/s î + 19.3 rad/s k̂"). "" if `typed` is no such sum (a
// unit vector inside a bracket or function, two in one term, one divided by; a unit after
// some terms but not all, or on a component told twice).
std::string unit_vector_sum(const std::string& typed, const sym::SymbolTable& table, bool xyz) {
  if (typed.find('@') != std::string::npos) return "";  // the markers' own character
  std::string sum = trim(unit_vectors_marked(typed, table, xyz)), unit;
  // "x̂ − ẑ" as a PDF or a word processor sets the minus: the terms' sign.
  for (const std::string_view minus : {"\u2212", "\u2013"}) {
    for (auto at = sum.find(minus); at != std::string::npos; at = sum.find(minus, at))
      sum.replace(at, minus.size(), "-");
  }
  // LaTeX's tie, "-0.75~h~\hat{z}" (here with its hat respelled, ẑ): a space. Plain text has no
  // '~' inside a sum (an approximate answer's leading one is a relation, read before).
  std::replace(sum.begin(), sum.end(), '~', ' ');
  // LaTeX's "\left( .. \right)": brackets, their size aside.
  for (const std::string_view sizing : {"\\left", "\\right"}) {
    for (auto at = sum.find(sizing); at != std::string::npos; at = sum.find(sizing, at)) {
      const std::size_t next = at + sizing.size();
      if (next < sum.size() && std::string_view("()[]").find(sum[next]) != std::string_view::npos)
        sum.erase(at, sizing.size());
      else
        at = next;
    }
  }
  // "ω(sin α x̂ + cos α ẑ)", as a statement writes ω(0): a factor before the bracketed sum,
  // each component's. Not a sum before it ("a + (..)"), nor a division by the bracket.
  std::string factor;
  if (const std::size_t open = sum.find('('); open != std::string::npos && open > 0) {
    const std::size_t close = matching(sum, open);
    const bool all_inside =
        close != std::string::npos && sum.find('@') > open && sum.rfind('@') < close;
    const std::string before = trim(sum.substr(0, open));
    const bool one_factor = all_inside && !before.empty() &&
                            before.find_first_of("+-", 1) == std::string::npos &&
                            before.back() != '/' && before.find_first_of("([") == std::string::npos;
    if (one_factor) {
      factor = before.back() == '*' ? trim(before.substr(0, before.size() - 1)) : before;
      sum = sum.substr(open);
    }
  }
  bool in_brackets = false;
  if (!sum.empty() && sum[0] == '(') {  // "(..) m": the sum in brackets, a unit after
    std::size_t close = 0;
    for (int depth = 0; close < sum.size(); ++close) {
      if (sum[close] == '(') ++depth;
      if (sum[close] == ')' && --depth == 0) break;
    }
    if (close >= sum.size()) return "";
    // Not "(m R² ω sin α/4) e₁ + ..": a first term's coefficient in brackets, the unit vectors
    // after it.
    const std::string after = sum.substr(close + 1);
    if (after.find('@') == std::string::npos) {
      unit = trim(after);  // what it is, the reading of the vector says
      sum = sum.substr(1, close - 1);
      in_brackets = true;
    }
  }
  if (!factor.empty() && !in_brackets) return "";
  std::array<std::string, 3> components, component_units;
  int bases = 0;  // 1: the space basis's vectors, 2: the body's, 4: the primed
  std::size_t term_start = 0, terms = 0, terms_with_unit = 0;
  bool last_has_unit = false, unit_twice = false;
  int depth = 0;
  const auto add_term = [&](std::size_t end) {
    std::string term = trim(sum.substr(term_start, end - term_start));
    std::string sign = "+";
    if (!term.empty() && (term[0] == '+' || term[0] == '-')) {
      sign = term.substr(0, 1);
      term = trim(term.substr(1));
    }
    const std::size_t at = term.find('@');
    if (at == std::string::npos || term.find('@', at + 1) != std::string::npos) return false;
    if (at + 1 >= term.size() || term[at + 1] < '0' || term[at + 1] > '8') return false;
    const int axis = term[at + 1] - '0';
    bases |= 1 << (axis / 3);
    int inner = 0;  // the marker at the term's top level
    for (std::size_t i = 0; i < at; ++i) {
      if (term[i] == '(' || term[i] == '[') ++inner;
      if (term[i] == ')' || term[i] == ']') --inner;
    }
    std::string before = trim(term.substr(0, at));
    std::string after = trim(term.substr(at + 2));
    if (inner != 0 || !is_factor_between(before, after)) return false;
    const std::size_t n = static_cast<std::size_t>(axis % 3);
    // "19.3 k̂ rad/s": a unit after a coefficient, not a factor of it.
    std::string term_unit = before.empty() ? "" : unit_after_term(after, before, table);
    if (!term_unit.empty()) after.clear();
    if (term_unit.empty() && after.empty()) {
      // "19.3 rad/s k̂", as "F = 5 N x̂" is written: a unit between a number and its unit
      // vector (after an expression in the symbols, "m R² ω/2 ê₃", the letters stay factors).
      // A '*' joins a factor, not a unit: "2*h k̂" where h is a height is 2h along z, not hours.
      const auto [number, unit_text] = split_value_unit(plain_coefficient(before, table));
      if (!unit_text.empty() && !number.empty() && number.back() != '*' &&
          !has_identifier_of(number, table)) {
        before = number;
        term_unit = unit_text;
      }
    }
    ++terms;
    terms_with_unit += term_unit.empty() ? 0 : 1;
    last_has_unit = !term_unit.empty();
    unit_twice = unit_twice ||
                 (!components[n].empty() && !(term_unit.empty() && component_units[n].empty()));
    component_units[n] = term_unit;
    const std::string coefficient = with_one_in_place(before, after);
    std::string& component = components.at(n);
    component +=
        (component.empty() && sign == "+" ? "" : " " + sign + " ") + "(" + coefficient + ")";
    return true;
  };
  for (std::size_t i = 0; i < sum.size(); ++i) {
    const char c = sum[i];
    if (c == '(' || c == '[' || c == '{') ++depth;
    if (c == ')' || c == ']' || c == '}') --depth;
    if (depth != 0 || (c != '+' && c != '-') || !starts_term(sum, i)) continue;
    if (!add_term(i)) return "";
    term_start = i;
  }
  // "x̂ + ê₃" mixes two bases: more than one bit set.
  if (!add_term(sum.size()) || (bases & (bases - 1)) != 0) return "";
  const bool each_term = terms_with_unit == terms && terms > 1;
  if (terms_with_unit > 0) {
    // The whole sum's unit after the last term, or each term's: nothing else, and no unit
    // outside the brackets as well.
    const bool last_only = terms_with_unit == 1 && last_has_unit;
    if (!unit.empty() || unit_twice || !(last_only || each_term)) return "";
    if (!each_term) {
      for (auto& u : component_units) {
        if (!u.empty()) unit = u;
        u.clear();
      }
    }
  }
  if (!factor.empty() && terms_with_unit > 0) return "";  // "ω(x̂ rad/s + ..)"
  std::string vector = "[";
  for (std::size_t n = 0; n < 3; ++n) {
    const std::string component = components[n].empty() ? std::string("0")
                                  : factor.empty()      ? components[n]
                                                   : "(" + factor + ")*(" + components[n] + ")";
    vector +=
        (n ? ", " : "") + component + (component_units[n].empty() ? "" : " " + component_units[n]);
  }
  return vector + "]" + (unit.empty() ? "" : " " + unit);
}

}  // namespace wobble::check::detail
