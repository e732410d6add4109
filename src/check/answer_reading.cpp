#include "check/answer_reading.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <tuple>
#include <vector>

#include "check/basis_vectors.hpp"
#include "check/brackets.hpp"
#include "check/latex_answer.hpp"
#include "check/names_run_together.hpp"
#include "check/rotations.hpp"
#include "check/text_terms.hpp"
#include "check/typed_text.hpp"
#include "check/unit_vector_sum.hpp"
#include "check/written_forms.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"
#include "symbolic/expression_guard.hpp"
#include "symbolic/glued_numbers.hpp"
#include "symbolic/unicode_notation.hpp"
#include "symbolic/units.hpp"

namespace wobble::check {

using detail::all_identifiers_of;
using detail::bases_named;
using detail::has_identifier_of;
using detail::is_factor_between;
using detail::is_one_term;
using detail::starts_term;
using detail::unit_vector_sum;
using detail::unit_vectors_marked;
using detail::unit_vectors_named;
using detail::with_one_in_place;

std::vector<std::pair<std::size_t, std::size_t>> identifiers(const std::string& s) {
  std::vector<std::pair<std::size_t, std::size_t>> out;  // (start, length)
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (!std::isalpha(c) && c != '_') {
      // Skip a number whole, "2e5" included: its exponent is no identifier.
      if (std::isdigit(c) || c == '.') {
        while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '.')) ++i;
      } else {
        ++i;
      }
      continue;
    }
    std::size_t j = i;
    while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
    out.emplace_back(i, j - i);
    i = j;
  }
  return out;
}

namespace {
std::string bracket_group(const std::string& group);

// MATLAB's rows, "a b c; d e f" -> "[[a, b, c], [d, e, f]]"; a column "a; b; c" -> "[a, b, c]",
// as a vector is wanted wherever a column is typed.
std::string semicolon_rows(const std::string& inside) {
  std::vector<std::string> rows;
  bool columns = true;
  for (const auto& row : top_level(inside, ';')) {
    if (row.empty()) continue;  // "[1 0 0; 0 1 0;]": a closing semicolon
    rows.push_back(bracket_group("[" + row + "]"));
    columns =
        columns && top_level(row, ',').size() == 1 && space_separated_entries(row).size() == 1;
  }
  if (columns) {
    for (auto& r : rows) r = r.substr(1, r.size() - 2);
  }
  return "[" + joined(rows) + "]";
}

// "[a b c]" -> "[a, b, c]", "[[a b] [c d]]" -> "[[a, b], [c, d]]", "[a b; c d]" as MATLAB's.
std::string bracket_group(const std::string& group) {
  const std::string inside = group.substr(1, group.size() - 2);
  if (top_level(inside, ';').size() > 1) return semicolon_rows(inside);
  std::vector<std::string> items = top_level(inside, ',');
  if (items.size() == 1) items = space_separated_entries(inside);
  for (auto& item : items) {
    if (wrapped(item, '[')) item = bracket_group(item);
  }
  return "[" + joined(items) + "]";
}

// The value's layout in reading form (see the header).
std::string layout(const std::string& value) {
  if (value.empty()) return value;
  if (top_level(value, ';').size() > 1) return semicolon_rows(value);
  // "(a, b, c)", and "(a; b; c)" as "[a; b; c]", a column.
  if (const std::string inside = wrapped(value, '(') ? value.substr(1, value.size() - 2) : "";
      top_level(inside, ',').size() > 1 || top_level(inside, ';').size() > 1) {
    return bracket_group("[" + inside + "]");
  }
  const auto groups = top_level(value, ' ');
  const bool all_groups = std::all_of(groups.begin(), groups.end(), [](const std::string& g) {
    return wrapped(g, '[') || wrapped(g, '(');
  });
  if (groups.size() > 1 && all_groups) {  // matrix rows as printed
    std::vector<std::string> rows;
    for (auto g : groups) {
      if (g.front() == '(') g = "[" + g.substr(1, g.size() - 2) + "]";
      rows.push_back(bracket_group(g));
    }
    return "[" + joined(rows) + "]";
  }
  if (wrapped(value, '[')) return bracket_group(value);
  if (const auto items = top_level(value, ','); items.size() > 1) {  // "5, 7, 10"
    std::vector<std::string> rows;
    for (const auto& i : items) rows.push_back(wrapped(i, '[') ? bracket_group(i) : i);
    return "[" + joined(rows) + "]";
  }
  return value;
}

// Whether `name` is no symbol but one of the table's in the other case ("r" for R).
bool differs_in_case_only(const std::string& name, const sym::SymbolTable& table) {
  return !table.contains(name) &&
         std::any_of(table.names().begin(), table.names().end(), [&](const std::string& known) {
           return ascii_lower(known) == ascii_lower(name);
         });
}

// "M R^2 psidot0/2" -> "M*R^2*psidot0/2": a '*' for each space between two factors; and a
// function's one-factor argument without parentheses, as books write it, in them: "M l g cos
// theta0" -> "M*l*g*cos(theta0)" (a name or a number, not one with a power: cos theta^2 is
// read by some as cos(theta^2)).
// Also a '*' where a bracket meets a factor without a space, as books write a product:
// "2(m + R)", "(1/4)m", "(m)(R^2)", and "m(R^2)" where m is one of the problem's symbols (a
// function's call stays one: "cos(a)", "atan2(y, x)").
std::string starred(const std::string& s, const sym::SymbolTable& table) {
  const std::vector<std::string>& kFunctions = bare_call_functions();
  // "4l^2", "0.5M": a number glued to one of the problem's symbols that spells no unit; or to
  // one that does, in a product with one that does not ("0.25m R^2"), or divided by a number
  // ("3h/4"). Alone, where m is a mass, "2m" is two masses or two metres, and refused. (pi and
  // functions: symbolic/glued_numbers.hpp.)
  const auto ids = identifiers(s);
  const bool symbol_spelling_no_unit = std::any_of(ids.begin(), ids.end(), [&](const auto& id) {
    const std::string name = s.substr(id.first, id.second);
    return table.contains(name) && !is_unit(name);
  });
  const auto number_against_name = [&](const std::string& before, std::size_t at) {
    if (!std::isalpha(static_cast<unsigned char>(s[at])) || !sym::ends_in_number(before) ||
        sym::starts_exponent(s, at))
      return false;
    const std::string name = sym::name_at(s, at);
    // "-3h/4" where h is a height: no unit is divided by a number, so h is the symbol.
    const std::size_t after = at + name.size();
    const bool over_number = after + 1 < s.size() && s[after] == '/' &&
                             std::isdigit(static_cast<unsigned char>(s[after + 1]));
    return table.contains(name) && (symbol_spelling_no_unit || !is_unit(name) || over_number);
  };
  const auto glued_product = [&](const std::string& before, char next) {
    const char last = before.back();
    if (last == ')')
      return next == '(' || next == '.' || std::isalnum(static_cast<unsigned char>(next));
    if (next != '(') return false;
    std::size_t k = before.size();
    while (k > 0 && (std::isalnum(static_cast<unsigned char>(before[k - 1])) ||
                     before[k - 1] == '_' || before[k - 1] == '.'))
      --k;
    const std::string factor = before.substr(k);
    if (factor.empty()) return false;
    if (factor.find_first_not_of("0123456789.") == std::string::npos) return true;  // "2("
    // A symbol or pi, never a function's name.
    return table.contains(factor) || factor == "pi" || factor == "Pi";
  };
  const auto factor_end = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == ')';
  };
  const auto factor_start = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '(' || c == '.';
  };
  const auto in_word = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
  };
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != ' ') {
      if (!out.empty() && (glued_product(out, s[i]) || number_against_name(out, i))) out += '*';
      out += s[i];
      continue;
    }
    const std::size_t next = s.find_first_not_of(' ', i);
    if (next == std::string::npos) break;
    std::size_t word = out.size();
    while (word > 0 && std::isalpha(static_cast<unsigned char>(out[word - 1]))) --word;
    std::size_t end = next;
    while (end < s.size() && in_word(s[end])) ++end;
    const bool function =
        std::find(kFunctions.begin(), kFunctions.end(), out.substr(word)) != kFunctions.end() &&
        (word == 0 || !in_word(out[word - 1]));
    if (function && end > next && (end == s.size() || (s[end] != '^' && s[end] != '('))) {
      out += "(" + s.substr(next, end - next) + ")";
      i = end - 1;
      continue;
    }
    if (!out.empty()) out += factor_end(out.back()) && factor_start(s[next]) ? '*' : ' ';
    i = next - 1;
  }
  return out;
}

// Whether s names one of the problem's symbols that is no unit ("R^2 psidot0/2", not "m" or "g":
// after a number, "kg m^2" is a unit, whatever went wrong in it).
bool names_a_symbol(const std::string& s, const sym::SymbolTable& table) {
  for (const auto& [start, length] : identifiers(s)) {
    const std::string id = s.substr(start, length);
    if (table.contains(id) && !is_unit(id)) return true;
  }
  return false;
}

// Whether a text that did not read may be factors side by side: it has one of the problem's
// symbols, and no space between two numbers ("5 7 10" is a list, not 350). A vector's components
// may be such products when commas separate them ("[m R^2 w/4, 0, 0]"); without commas its
// spaces separate the components (layout), and it read before it got here. Without a space
// there is no list to mistake: "(1/4)(0.2)(0.12)^2" may be factors against brackets.
bool may_be_side_by_side(const std::string& s, const sym::SymbolTable& table) {
  const auto numeric = [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) || c == '.';
  };
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    if (s[i] != ' ' || i == 0) continue;
    const std::size_t next = s.find_first_not_of(' ', i);
    // The number before the space: its last character a digit, not the end of a name (R2).
    std::size_t start = i;
    while (start > 0 && (numeric(s[start - 1]))) --start;
    const bool number_before =
        start < i && (start == 0 || !std::isalpha(static_cast<unsigned char>(s[start - 1])));
    if (number_before && next != std::string::npos && numeric(s[next])) return false;
  }
  const auto ids = identifiers(s);
  // "1/6 pi", "0.25 pi"; a number before a call, "10 sin(0.2618)", as a calculator's result is
  // written out: no unit is named so.
  const bool names_pi = std::any_of(ids.begin(), ids.end(), [&](const auto& id) {
    const std::string name = s.substr(id.first, id.second);
    return name == "pi" || name == "Pi" || sym::is_function_name(name);
  });
  // "(0, 0, -3h/4)": a symbol glued to a number is no identifier of the text as written.
  return names_pi || has_identifier_of(s, table) || s.find(' ') == std::string::npos ||
         has_identifier_of(starred(s, table), table);
}

// Reads factors side by side into p, a '*' for each space between two factors, where they may
// be such (may_be_side_by_side) and then read; returns whether they did.
bool read_side_by_side(const std::string& value, const sym::SymbolTable& table,
                       const std::string& field, ReadAnswer& p) {
  if (!may_be_side_by_side(value, table)) return false;
  try {
    p.value = sym::parse_value_text(layout(starred(value, table)), table, field);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

// Whether a text with its stars written in has a function with no parentheses ("cos*theta0^2"):
// no advice to paste.
bool has_bare_function(const std::string& written) {
  return std::any_of(
      bare_call_functions().begin(), bare_call_functions().end(), [&](const std::string& f) {
        for (auto at = written.find(f); at != std::string::npos; at = written.find(f, at + 1)) {
          if (at > 0 && std::isalnum(static_cast<unsigned char>(written[at - 1]))) continue;
          std::size_t k = at + f.size();  // "cos*", or "sin^2*" with a power on the name
          if (k < written.size() && written[k] == '^') {
            ++k;
            while (k < written.size() && std::isdigit(static_cast<unsigned char>(written[k]))) ++k;
          }
          if (k < written.size() && written[k] == '*') return true;
        }
        return false;
      });
}

// The rate of the angle `name` (no underscores) as the problem names it: "phi" -> "phidot",
// "theta0" -> "thetadot0", where the problem has that symbol; "psi" -> "psidot" too where it
// has psidot0 only (the reader then refuses psidot naming psidot0, as it does when typed); ""
// for a name with no such rate.
std::string rate_symbol(const std::string& name, const sym::SymbolTable& table) {
  std::size_t digits = name.size();
  while (digits > 0 && is_digit(name[digits - 1])) --digits;
  if (digits == 0) return "";
  const std::string rate = name.substr(0, digits) + "dot" + name.substr(digits);
  const bool initial_only = digits == name.size() && table.contains(rate + "0");
  return table.contains(rate) || initial_only ? rate : "";
}

// "dphi/dt", "dφ/dt" (read "d phi/dt"), "dθ₀/dt": a rate in Leibniz's notation, as the
// problem's rate symbol (phidot, thetadot0), where the problem has one (or its value at t = 0)
// and no symbol "dt".
std::string leibniz_rates(const std::string& s, const sym::SymbolTable& table) {
  if (table.contains("dt")) return s;
  const auto ids = identifiers(s);
  std::string out;
  std::size_t done = 0;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const auto [start, length] = ids[k];
    if (s[start] != 'd' || (start > 0 && (is_letter(s[start - 1]) || is_digit(s[start - 1])))) {
      continue;
    }
    // The name after the d: glued on ("dphi") or after one space ("d phi").
    std::size_t name_k = k, name_from = start + 1;
    if (length == 1) {
      if (k + 1 >= ids.size() || ids[k + 1].first != start + 2 || s[start + 1] != ' ') continue;
      name_k = k + 1;
      name_from = ids[k + 1].first;
    }
    const std::size_t name_end = ids[name_k].first + ids[name_k].second;
    std::string name = s.substr(name_from, name_end - name_from);
    name.erase(std::remove(name.begin(), name.end(), '_'), name.end());
    std::size_t i = name_end;
    while (i < s.size() && s[i] == ' ') ++i;
    if (i >= s.size() || s[i] != '/') continue;
    ++i;
    while (i < s.size() && s[i] == ' ') ++i;
    if (name_k + 1 >= ids.size() || ids[name_k + 1].first != i || ids[name_k + 1].second != 2 ||
        s.compare(i, 2, "dt") != 0) {
      continue;
    }
    const std::string rate = rate_symbol(name, table);
    if (rate.empty() || table.contains(s.substr(start, length))) continue;
    out += s.substr(done, start - done) + rate;
    done = i + 2;
    k = name_k + 1;
  }
  return out + s.substr(done);
}

// "theta'", "phi'": a rate in Lagrange's notation, a prime after the name, as the problem's rate
// symbol (thetadot; theta0' as thetadot0), where it has one, or has it at t = 0 only (then as
// "psidot", which the reader refuses naming psidot0, as for "dpsi/dt"). A prime names nothing
// else here: "E'" (the heavy top's E′), "e1'" (a turned axis) have no rate and stay, and "30'"
// (minutes of arc) follows no name. Two primes (a second derivative) stay too.
std::string lagrange_rates(const std::string& s, const sym::SymbolTable& table) {
  std::string out;
  std::size_t done = 0;
  for (const auto& [start, length] : identifiers(s)) {
    // The prime as typed, "'", or as set, "′" (U+2032, copied from a page).
    const std::size_t after = start + length;
    const std::size_t prime = s.compare(after, 1, "'") == 0        ? 1
                              : s.compare(after, 3, "\u2032") == 0 ? 3
                                                                   : 0;
    if (prime == 0 || s.compare(after + prime, 1, "'") == 0 ||
        s.compare(after + prime, 3, "\u2032") == 0) {
      continue;
    }
    std::string name = s.substr(start, length);
    name.erase(std::remove(name.begin(), name.end(), '_'), name.end());
    const std::string rate = rate_symbol(name, table);
    if (rate.empty()) continue;
    out += s.substr(done, start - done) + rate;
    done = after + prime;
  }
  return out + s.substr(done);
}

// The problem's symbols by the names their LaTeX spells, where that is not the name: w1 by
// "omega1" when its LaTeX is \omega_1, so "ω₁" as the question prints it reads. Not a spelling
// two symbols share, nor one that is a symbol, a unit, pi or a function itself.
std::map<std::string, std::string> names_by_spelling(const sym::SymbolTable& table) {
  std::map<std::string, std::string> by_spelling;
  std::set<std::string> shared;
  for (const auto& name : table.names()) {
    const std::string spelling = sym::typed_spelling(table.latex_of(name));
    if (spelling == name || spelling.empty() || table.contains(spelling) || is_unit(spelling) ||
        spelling == "pi" || spelling == "Pi" || sym::is_function_name(spelling)) {
      continue;
    }
    if (!by_spelling.emplace(spelling, name).second) shared.insert(spelling);
  }
  for (const auto& spelling : shared) by_spelling.erase(spelling);
  return by_spelling;
}

// "psidot_0" for the problem's psidot0, "theta_0" for theta0: a subscript as LaTeX writes it.
// Only where the name with the underscore is not a symbol itself and the one without it is.
// Then "omega1" and "omega_1" for w1 whose LaTeX is \omega_1 (names_by_spelling).
std::string symbols_as_spelled(const std::string& s, const sym::SymbolTable& table) {
  const auto by_spelling = names_by_spelling(table);
  std::string out;
  std::size_t done = 0;
  for (const auto& [start, length] : identifiers(s)) {
    std::string id = s.substr(start, length), bare = id;
    bare.erase(std::remove(bare.begin(), bare.end(), '_'), bare.end());
    out += s.substr(done, start - done);
    if (table.contains(id)) {
      out += id;
    } else if (table.contains(bare)) {
      out += bare;
    } else if (const auto named = by_spelling.find(bare); named != by_spelling.end()) {
      out += named->second;
    } else {
      out += id;
    }
    done = start + length;
  }
  return out + s.substr(done);
}

// "[0.5, 1, 1.5]m", "(0.5, 1, 1.5)m/s": a unit glued to a vector's bracket, where the unit has
// no letters the problem uses as a symbol. {s, ""} when s is not such a pair.
std::pair<std::string, std::string> split_bracket_unit(const std::string& s,
                                                       const sym::SymbolTable& table) {
  if (s.empty() || (s[0] != '[' && s[0] != '(')) return {s, ""};
  const std::size_t close = matching(s, 0);
  if (close == std::string::npos || close + 1 >= s.size()) return {s, ""};
  const std::string inside = s.substr(1, close - 1), unit = trim(s.substr(close + 1));
  const bool vector = top_level(inside, ',').size() > 1 || top_level(inside, ';').size() > 1 ||
                      space_separated_entries(inside).size() > 1;
  if (!vector || !std::isalpha(static_cast<unsigned char>(unit[0])) || !is_unit(unit))
    return {s, ""};
  for (const auto& [start, length] : identifiers(unit)) {
    if (table.contains(unit.substr(start, length))) return {s, ""};
  }
  return {s.substr(0, close + 1), unit};
}

// "45deg", "0.21kg", "3.1rad/s": a plain number with its unit glued on, where the unit has no
// letters the problem uses as a symbol ("2m" is 2 metres in the heavy top, but 2 m, refused as
// such, where m is a mass). {s, ""} when s is not such a pair.
std::pair<std::string, std::string> split_glued_unit(const std::string& s,
                                                     const sym::SymbolTable& table) {
  const std::size_t digits = !s.empty() && (s[0] == '-' || s[0] == '+') ? 1 : 0;  // "-20deg"
  std::size_t k = digits;
  while (k < s.size() && (std::isdigit(static_cast<unsigned char>(s[k])) || s[k] == '.')) ++k;
  if (k == digits || k >= s.size()) return {s, ""};
  // An exponent belongs to the number: "5e7g" is 5e7 grams, "2e" no number with a unit.
  if ((s[k] == 'e' || s[k] == 'E') && k + 1 < s.size()) {
    std::size_t e = k + 1;
    if (s[e] == '+' || s[e] == '-') ++e;
    if (e < s.size() && std::isdigit(static_cast<unsigned char>(s[e]))) {
      while (e < s.size() && std::isdigit(static_cast<unsigned char>(s[e]))) ++e;
      k = e;
    }
  }
  const std::string number = s.substr(0, k), glued = trim(s.substr(k));
  // "4.995/s", "4.995 /s": a reciprocal unit without its 1.
  const bool per = !glued.empty() && glued[0] == '/';
  const std::string unit = per ? "1" + glued : glued;
  if (unit.empty() || !(per || std::isalpha(static_cast<unsigned char>(glued[0]))) ||
      !is_unit(unit))
    return {s, ""};
  for (const auto& [start, length] : identifiers(unit)) {
    if (table.contains(unit.substr(start, length))) return {s, ""};
  }
  return {number, unit};
}

// "2*65deg" -> "2*65", "deg": the degree sign of an expression's last number, glued to it above
// (units_per_entry) as to a lone number's, is the whole entry's unit, as "2*65 deg" alone reads
// (2*65 in degrees). Not where degrees come earlier too ("360deg - 20deg", below).
std::pair<std::string, std::string> split_last_degrees(const std::string& s) {
  constexpr std::string_view kDeg = "deg";
  if (s.size() <= kDeg.size() + 1 || s.compare(s.size() - kDeg.size(), kDeg.size(), kDeg) != 0)
    return {s, ""};
  const std::string number = s.substr(0, s.size() - kDeg.size());
  if (!std::isdigit(static_cast<unsigned char>(number.back())) ||
      number.find(kDeg) != std::string::npos)
    return {s, ""};
  return {number, std::string(kDeg)};
}

// Whether an entry is a zero as typed ("0", "-0.0"): a component that needs no unit.
bool is_zero_literal(const std::string& s) {
  const std::string t = trim(s);
  const std::size_t digits = t.find_first_not_of("+-");
  return digits != std::string::npos && t.find_first_not_of("0.", digits) == std::string::npos &&
         t.find('0', digits) != std::string::npos;
}

// A vector or matrix whose numbers each carry a unit: "(40 deg, 30 deg, 70 deg)" (as "(40°, 30°,
// 70°)" reads), "[2.6 rad/s, 0, 19.3 rad/s]", as a student writes angles and a table's cells show
// values. `value` has the units taken out, the other entries converted into the first entry's
// `unit` exactly where theirs differs; both are empty unless every entry but a zero has a unit.
// An expression in the symbols may carry an SI unit ("[phidot rad/s, 0, 11.7 rad/s]").
// `refusal` says what is wrong where only some have one ("[40 deg, 30, 70 deg]"), their
// dimensions differ or an expression has a unit not SI: the message if the text reads no other
// way ("40, 30, 70 deg" does).
struct EntryUnits {
  std::string value, unit, refusal;
};
EntryUnits units_per_entry(const std::string& text, const sym::SymbolTable& table,
                           const std::string& field) {
  // "[40 deg 30 deg 70 deg]" (as "[40° 30° 70°]" reads): each degree sign glued back to its
  // number, so that spaces still separate the entries.
  std::string glued;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const bool degree_sign =
        i > 0 && text[i] == ' ' && std::isdigit(static_cast<unsigned char>(text[i - 1])) &&
        text.compare(i + 1, 3, "deg") == 0 &&
        (i + 4 >= text.size() || !std::isalnum(static_cast<unsigned char>(text[i + 4])));
    if (!degree_sign) glued += text[i];
  }
  const std::string laid = layout(glued);
  if (!wrapped(laid, '[')) return {};
  std::optional<Unit> first;
  std::string first_text, without, other_dimension, not_si;  // the first entry of each kind
  const auto strip = [&](const auto& self, const std::string& group) -> std::string {
    std::vector<std::string> items = top_level(group.substr(1, group.size() - 2), ',');
    for (auto& item : items) {
      if (wrapped(item, '[')) {
        item = self(self, item);
        continue;
      }
      auto [number, unit] = split_unit(item);
      if (unit.empty()) std::tie(number, unit) = split_glued_unit(item, table);
      if (unit.empty()) std::tie(number, unit) = split_last_degrees(item);
      // "360deg - 20deg", "15deg/2": arithmetic on angles in degrees is an angle in radians, as
      // in an answer of one entry.
      if (unit.empty() && degrees_joined(item)) {
        number = degrees_in_expression(item, [](const std::string&) { return false; });
        unit = "rad";
      }
      // "2 d^2 m" where m is a mass: a tail of the problem's symbols after an expression in
      // them is a factor, as after a whole answer (read_answer), not metres.
      if (!unit.empty() && has_identifier_of(number, table) && all_identifiers_of(unit, table))
        unit.clear();
      if (unit.empty()) {
        if (without.empty() && !is_zero_literal(item)) without = item;
        continue;
      }
      const Unit u = parse_unit(unit, field);
      // An expression in the symbols is in SI: an SI unit after it says what it is
      // ("(phidot rad/s, ..)", as after a whole expression); another would ask for a conversion
      // the expression does not say how to apply.
      if (has_identifier_of(number, table) && u.to_si_exact != "1" && not_si.empty()) {
        not_si = field + ": the entry \"" + item +
                 "\" is an expression in the problem's symbols, in SI already; drop its unit '" +
                 unit + "'";
      }
      if (!first) {
        first = u;
        first_text = unit;
      } else if (!u.same_dimension(*first) && other_dimension.empty()) {
        other_dimension = field + ": the entries' units " + first_text + " and " + unit +
                          " measure different things (" + first->dimension_words() + ", " +
                          u.dimension_words() + ")";
      }
      item = unit == first_text
                 ? number
                 : "(" + number + ")*(" + u.to_si_exact + ")/(" + first->to_si_exact + ")";
    }
    return "[" + joined(items) + "]";
  };
  const std::string stripped = strip(strip, laid);
  if (!first) return {};
  if (!other_dimension.empty()) return {"", "", other_dimension};
  if (!not_si.empty()) return {"", "", not_si};
  if (!without.empty()) {
    return {"", "",
            field + ": the entry \"" + without + "\" has no unit where another has " + first_text +
                (has_identifier_of(without, table)
                     ? ": an expression in the symbols is in SI; write its SI unit after it "
                       "too, or give the numbers in SI without units"
                     : ": give each number its unit (a zero may go without), or one unit after "
                       "the whole")};
  }
  return {stripped, first_text, ""};
}

// Whether e has one of the problem's symbols. (Not by evalf: GiNaC evaluates EllipticK(1)
// forever, and an answer's range is checked only where it is evaluated, sym::evaluate.)
bool has_symbols(const GiNaC::ex& e) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) return true;
  for (std::size_t i = 0; i < e.nops(); ++i) {
    if (has_symbols(e.op(i))) return true;
  }
  return false;
}

// Refuses what the rearranging would only slow down (it recurses into brackets and scans each
// level): the same bounds the expression reader applies afterwards, checked first.
void check_bounds(const std::string& typed, const std::string& field) {
  if (typed.size() > 9 * sym::kMaxExpressionLength) {
    throw InputError(field + ": " + std::to_string(typed.size()) +
                     " characters; an answer may have at most " +
                     std::to_string(9 * sym::kMaxExpressionLength));
  }
  int depth = 0;
  for (const char c : typed) {
    if (opens(c)) ++depth;
    if (closes(c)) --depth;
    if (depth > sym::kMaxExpressionDepth) {
      throw InputError(field + ": brackets nested deeper than " +
                       std::to_string(sym::kMaxExpressionDepth) + " levels");
    }
  }
}
// The answer read, with its unit (if any) and whether it is an expression in the symbols.
ReadAnswer finished(ReadAnswer p, const std::string& unit, const std::string& field) {
  if (!unit.empty()) p.unit = parse_unit(unit, field);
  for (const auto& e : p.value.entries) p.symbolic = p.symbolic || has_symbols(e);
  // "atan(tan(α)/2) rad", "m R^2/4 kg m^2": an expression in the symbols is in SI, so an SI
  // unit after it says what it is (the judge checks its dimension); any other unit (g cm^2,
  // deg) would ask for a conversion the expression does not say how to apply.
  if (p.symbolic && p.unit && p.unit->to_si_exact != "1") {
    throw InputError(field +
                     ": an expression in the problem's symbols is in SI already; drop "
                     "the unit '" +
                     unit + "'");
  }
  return p;
}

}  // namespace

std::string without_closing_punctuation(const std::string& typed) {
  std::string s = trim(typed);
  while (!s.empty() && s.back() == ';') s = trim(s.substr(0, s.size() - 1));
  if (s.size() >= 2 && s.back() == '.' && s[s.size() - 2] != '.')
    s = trim(s.substr(0, s.size() - 1));
  return s;
}

std::string reading_form(const std::string& typed) {
  check_bounds(typed, "answer");
  const auto [value, unit] = split_unit(prepared(without_closing_punctuation(typed), "answer"));
  return layout(value) + (unit.empty() ? "" : " " + unit);
}

namespace {
// The one bracket at the top level of `s` that holds a vector or matrix: '[' or '{', or '(' with
// a comma inside that is no function's call ("atan2(y, x)" is one). npos if none or several.
std::pair<std::size_t, std::size_t> vector_group(const std::string& s,
                                                 const sym::SymbolTable& table) {
  std::pair<std::size_t, std::size_t> found{std::string::npos, std::string::npos};
  int depth = 0;
  std::size_t open = 0;
  bool comma = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '(' || c == '[' || c == '{') {
      if (depth++ == 0) {
        open = i;
        comma = false;
      }
    } else if (c == ')' || c == ']' || c == '}') {
      if (--depth < 0) return {std::string::npos, std::string::npos};
      if (depth > 0) continue;
      // "atan2(y, x)" is a call; "omega(sin alpha, 0, 2 cos alpha)", the problem's symbol against
      // the bracket, a factor outside a vector, as books write one.
      std::size_t name = open;
      while (name > 0 &&
             (std::isalnum(static_cast<unsigned char>(s[name - 1])) || s[name - 1] == '_'))
        --name;
      const std::string before = s.substr(name, open - name);
      // A number against the bracket ("a^2(3, 0; ..)", "2(1, 0, 1)") is no name: no call either.
      const bool call = s[open] == '(' && !before.empty() &&
                        !std::isdigit(static_cast<unsigned char>(before[0])) &&
                        !(table.contains(before) && !sym::is_function_name(before));
      if (s[open] != '(' || (comma && !call)) {
        if (found.first != std::string::npos) return {std::string::npos, std::string::npos};
        found = {open, i};
      }
    } else if ((c == ',' || c == ';') && depth == 1) {
      comma = true;
    }
  }
  return depth == 0 ? found : std::pair{std::string::npos, std::string::npos};
}

// "M/12 [[b^2 + c^2, 0, 0], ..]", "1/2 (a, b, c)", "[a, b, c]/2": a vector or matrix with a
// factor outside, as books write a common factor. The bracket is read as an answer of its own,
// the rest, with 1 in the bracket's place, as a number or expression; false if `value` is no
// such product or either part does not read.
bool read_with_factor(const std::string& value, const sym::SymbolTable& table,
                      const std::string& field, ReadAnswer& p) {
  const auto [open, close] = vector_group(value, table);
  if (open == std::string::npos || (open == 0 && close + 1 == value.size())) return false;
  // A product only, decided from the text: judging it by algebra on the rest (is it k X?) could
  // take GiNaC's normal() on a hostile expression.
  const std::string before = trim(value.substr(0, open)), after = trim(value.substr(close + 1));
  if (!is_one_term(value) || !is_factor_between(before, after)) return false;
  const std::string rest = with_one_in_place(before, after);
  try {
    ReadAnswer bracket = read_answer(value.substr(open, close - open + 1), table, field);
    if (!bracket.value.is_vector && !bracket.value.is_matrix) return false;
    const ReadAnswer one = read_answer(rest, table, field);
    if (one.value.is_vector || one.value.is_matrix || one.unit) return false;
    const GiNaC::ex factor = one.value.entries.at(0);
    for (auto& e : bracket.value.entries) e = factor * e;
    bracket.symbolic = bracket.symbolic || one.symbolic;
    p = std::move(bracket);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

// The terms of `s` at its top level, each with its sign: "a [1, 0] - b [0, 1]" -> "a [1, 0]",
// "- b [0, 1]".
std::vector<std::string> top_level_terms(const std::string& s) {
  std::vector<std::string> terms;
  int depth = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '(' || c == '[' || c == '{') ++depth;
    if (c == ')' || c == ']' || c == '}') --depth;
    // LaTeX's "\begin{pmatrix} -a \\ b \end{pmatrix}": a bracket, its signs the entries'.
    if (s.compare(i, 7, "\\begin{") == 0) ++depth;
    if (s.compare(i, 5, "\\end{") == 0) --depth;
    if (depth == 0 && (c == '+' || c == '-') && starts_term(s, i)) {
      terms.push_back(trim(s.substr(start, i - start)));
      start = i;
    }
  }
  terms.push_back(trim(s.substr(start)));
  return terms;
}

// "φ̇ (0, 0, 1) + θ̇ (−sin φ, cos φ, 0) + ψ̇ (sin θ cos φ, sin θ sin φ, cos θ)": vectors (or
// matrices) of one shape added, each with a factor outside or none, as ω is built from the
// Euler angles' rates along their axes. Each term is read as an answer of its own, without a
// unit; false if `value` is no such sum or a term does not read.
// A sum of vectors as a hand writes one has a few terms (ω from three rates, a centre of mass
// edge by edge); each term is read as a whole answer, so a sum of thousands is not tried.
constexpr std::size_t kMostVectorTerms = 12;

bool read_vector_sum(const std::string& value, const sym::SymbolTable& table,
                     const std::string& field, ReadAnswer& p) {
  const std::vector<std::string> terms = top_level_terms(value);
  if (terms.size() < 2 || terms.size() > kMostVectorTerms) return false;
  ReadAnswer sum;
  try {
    for (const std::string& term : terms) {
      const std::string unsigned_term = term[0] == '+' ? trim(term.substr(1)) : term;
      ReadAnswer one = read_answer(unsigned_term, table, field);
      if (one.unit || !(one.value.is_vector || one.value.is_matrix)) return false;
      if (sum.value.entries.empty()) {
        sum = std::move(one);
        continue;
      }
      if (one.value.rows != sum.value.rows || one.value.cols != sum.value.cols ||
          one.value.is_matrix != sum.value.is_matrix)
        return false;
      for (std::size_t i = 0; i < sum.value.entries.size(); ++i)
        sum.value.entries[i] += one.value.entries[i];
      sum.symbolic = sum.symbolic || one.symbolic;
    }
  } catch (const InputError&) {
    return false;
  }
  p = std::move(sum);
  return true;
}
}  // namespace

namespace {
ReadAnswer read_as_written(const std::string& typed, const sym::SymbolTable& table,
                           const std::string& field);
ReadAnswer read_transposed(const std::string& typed, const sym::SymbolTable& table,
                           const std::string& field);

// `typed` without a transpose mark (rotations.hpp) after its last bracket at the top level, and
// whether it had one: "[0.5 1 1.5]ᵀ m" -> "[0.5 1 1.5] m", true. As typed otherwise: two marks,
// or a mark with a bracket after it, which marks one factor ("Rz(ψ)ᵀ Ry(θ)⁻¹ Rz(φ)⁻¹", whose
// turns are the product's to read), not the whole answer.
std::pair<std::string, bool> without_transpose(const std::string& typed) {
  int depth = 0;
  std::size_t found = std::string::npos, length = 0;
  for (std::size_t i = 0; i < typed.size(); ++i) {
    const char c = typed[i];
    if (c == '(' || c == '[' || c == '{') {
      if (depth == 0 && found != std::string::npos) return {typed, false};
      ++depth;
    }
    if (c != ')' && c != ']' && c != '}') continue;
    if (--depth != 0) continue;
    for (const std::string_view mark : kTransposeMarks) {
      if (typed.compare(i + 1, mark.size(), mark) != 0) continue;
      // Not the start of a longer word ("^Theta") or of a name's prime.
      const std::size_t end = i + 1 + mark.size();
      if (end < typed.size() && std::isalnum(static_cast<unsigned char>(typed[end]))) continue;
      if (found != std::string::npos) return {typed, false};
      found = i + 1;
      length = mark.size();
      i = end - 1;  // past the mark: the brace of "^{T}" opens no bracket after it
      break;
    }
  }
  if (found == std::string::npos) return {typed, false};
  return {typed.substr(0, found) + typed.substr(found + length), true};
}
}  // namespace

namespace {
// Whether unit_vectors_named's list ("i, k", "x̂, ẑ") names bare i, j or k only: letters that
// may be names of the student's own ("k'^2", "4K(k)/λ") rather than unit vectors.
bool only_bare_letters(const std::string& vectors) {
  for (std::size_t at = 0; at < vectors.size();) {
    const std::size_t end = std::min(vectors.find(", ", at), vectors.size());
    const std::string name = vectors.substr(at, end - at);
    if (name != "i" && name != "j" && name != "k") return false;
    at = end + 2;
  }
  return true;
}

// "0.5 i + j + 1.5 k", "0.5 ê₁ + 1.5 ê₃" (unit vectors as basis_vectors_spelled writes them): the
// components read as a vector, or, if they do not, a message that says what to write, not that
// "i + j" is no unit (UnitVectorsUnread, carrying `as_written`: "" unless bare i, j, k).
ReadAnswer read_along_unit_vectors(const std::string& spelled, const std::string& vectors,
                                   const sym::SymbolTable& table, const std::string& field,
                                   const std::string& as_written) {
  if (const std::string components = unit_vector_sum(spelled, table); !components.empty()) {
    try {
      return read_transposed(components, table, field);
    } catch (const InputError&) {
    }
  }
  // "ω = φ̇ ẑ + θ̇ ê₂′ + ψ̇ ê₃": a sum over bases, which no one vector's components are.
  if (bases_named(vectors) > 1) {
    throw InputError(field + ": components along " + vectors +
                     " mix bases (space x̂ ŷ ẑ, body e₁ e₂ e₃, primed e₁′ e₂′ e₃′); give the "
                     "components in one basis, or the vector [x, y, z]");
  }
  throw UnitVectorsUnread(field + ": cannot read the components along unit vectors (" + vectors +
                              ") as a sum of a number or expression times each; write the "
                              "vector as [x, y, z]",
                          as_written);
}
}  // namespace

namespace {
// "0.001863 x + 0.01391 z", as the statements write ω(0) = ω(sin α x + cos α z): bare x, y and z
// where the problem has no such symbols, read as unit vectors only where nothing else reads and
// the whole answer is a sum of two terms or more along them ("m x R^2" stays an x too many).
std::optional<ReadAnswer> along_bare_axes(const std::string& typed, const sym::SymbolTable& table,
                                          const std::string& field) {
  const std::string marked = unit_vectors_marked(typed, table, true);
  if (std::count(marked.begin(), marked.end(), '@') < 2) return std::nullopt;
  const std::string components = unit_vector_sum(typed, table, true);
  if (components.empty()) return std::nullopt;
  try {
    return read_transposed(components, table, field);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

// read_answer, but for a list of vectors each read on its own.
ReadAnswer read_whole(const std::string& typed, const sym::SymbolTable& table,
                      const std::string& field) {
  // "\hat{x}", "e₁" respelled: such a text is read as respelled, never as written ("0.5e₁"
  // would be 5 there, its subscript a digit), and so as its Unicode twin reads: "\dot\phi \hat z
  // + \dot\theta (-\sin\phi, \cos\phi, 0)" as "φ̇ ẑ + θ̇ (−sin φ, cos φ, 0)", a sum of vectors.
  const std::string spelled = basis_vectors_spelled(typed, table);
  std::string as_written;
  try {
    return read_transposed(spelled, table, field);
  } catch (const InputError& e) {
    if (spelled == typed && unit_vectors_named(typed, table).empty()) {
      if (auto along = along_bare_axes(typed, table, field)) return *along;
      throw;
    }
    as_written = e.what();
  }
  // Bare i, j, k only: what reading as written said goes with the answer (answer_reading.hpp).
  const std::string vectors = unit_vectors_named(spelled, table);
  if (!only_bare_letters(vectors)) as_written.clear();
  ReadAnswer along = read_along_unit_vectors(spelled, vectors, table, field, as_written);
  along.as_written_error = as_written;
  return along;
}

// `item` of a list of vectors with a lone bare x, y or z, as the statements write e₁ = x, given
// its hat ("−z" is "−ẑ"), where the letter is no symbol of the problem: alone in a list of
// vectors it reads as nothing else. `item` itself otherwise.
std::string lone_axis_hatted(const std::string& item, const sym::SymbolTable& table) {
  const std::string t = trim(item);
  const std::size_t sign = t.rfind("−", 0) == 0 ? std::string_view("−").size()
                           : !t.empty() && (t[0] == '-' || t[0] == '+') ? 1
                                                                        : 0;
  const std::string letter = trim(t.substr(sign));
  if (letter != "x" && letter != "y" && letter != "z") return item;
  if (table.contains(letter)) return item;
  return t.substr(0, sign) + letter + "\u0302";
}

// "(1, 0, 1)/√2, (1, 0, −1)/√2, (0, 1, 0)", "x̂ + ẑ, x̂ − ẑ, ŷ": a matrix's rows, as principal
// axes are listed, each vector written as it reads alone (a factor outside its bracket, along
// unit vectors), in one bracket or not (list_items, as the judge's listed axes). nullopt where
// `typed` is no list of two or three such vectors of one length, with one unit or none.
std::optional<ReadAnswer> rows_read_each(const std::string& typed, const sym::SymbolTable& table,
                                         const std::string& field) {
  const std::vector<std::string> items = list_items(typed).items;
  if (items.size() < 2 || items.size() > 3) return std::nullopt;
  ReadAnswer rows;
  for (std::size_t k = 0; k < items.size(); ++k) {
    ReadAnswer row;
    try {
      row = read_whole(lone_axis_hatted(items[k], table), table, field);
    } catch (const InputError&) {
      return std::nullopt;
    }
    if (!row.value.is_vector || row.value.is_matrix ||
        (k > 0 && row.value.entries.size() != rows.value.cols) ||
        (k > 0 && (row.unit.has_value() != rows.unit.has_value() ||
                   (row.unit && row.unit->text != rows.unit->text))))
      return std::nullopt;
    if (k == 0) {
      rows.unit = row.unit;
      rows.value.cols = row.value.entries.size();
    }
    rows.symbolic = rows.symbolic || row.symbolic;
    rows.value.entries.insert(rows.value.entries.end(), row.value.entries.begin(),
                              row.value.entries.end());
  }
  rows.value.rows = items.size();
  rows.value.is_matrix = true;
  return rows;
}
}  // namespace

ReadAnswer read_answer(const std::string& typed, const sym::SymbolTable& table,
                       const std::string& field) {
  check_bounds(typed, field);
  try {
    return read_whole(typed, table, field);
  } catch (const InputError&) {
    if (auto rows = rows_read_each(typed, table, field)) return *rows;
    throw;
  }
}

namespace {
// read_answer, with a transpose mark read.
// "transpose(X)", as MATLAB, NumPy (np.transpose) and Mathematica (Transpose[X]) write it: "(X)ᵀ",
// what follows (a unit) kept; "Rᵀ", a name alone marked so, "(R)ᵀ" (a name may be an earlier
// answer's matrix; "R^T" reads as a power until then). `typed` itself otherwise.
std::string transpose_called(const std::string& typed) {
  const std::string t = trim(typed);
  constexpr std::string_view kMark = kTransposeMarks[0];
  if (t.size() > kMark.size() && t.ends_with(kMark)) {
    const std::string name = t.substr(0, t.size() - kMark.size());
    if (std::isalpha(static_cast<unsigned char>(name[0])) &&
        std::all_of(name.begin(), name.end(),
                    [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }))
      return "(" + name + ")" + std::string(kMark);
  }
  for (const std::string_view name : {"transpose", "Transpose", "np.transpose"}) {
    if (!t.starts_with(name) || t.size() == name.size() || !opens(t[name.size()])) continue;
    const std::size_t close = matching(t, name.size());
    if (close == std::string::npos) break;
    return "(" + t.substr(name.size() + 1, close - name.size() - 1) + ")ᵀ" + t.substr(close + 1);
  }
  return typed;
}

// "([[a, b], [c, d]])" -> "[[a, b], [c, d]]": round brackets about one vector or matrix, as a
// transpose mark needs them about a name ("(R)ᵀ"), taken off; what follows (a unit) kept.
std::string list_unwrapped(const std::string& text) {
  std::string t = trim(text);
  while (!t.empty() && t[0] == '(') {
    const std::size_t close = matching(t, 0);
    if (close == std::string::npos) break;
    const std::string inner = trim(t.substr(1, close - 1));
    if (!wrapped(inner, '[') && !wrapped(inner, '(')) break;
    t = inner + t.substr(close + 1);
  }
  return t;
}

ReadAnswer read_transposed(const std::string& typed, const sym::SymbolTable& table,
                           const std::string& field) {
  const auto [untransposed, transposed] = without_transpose(transpose_called(typed));
  if (!transposed) return read_as_written(typed, table, field);
  ReadAnswer p = read_as_written(list_unwrapped(untransposed), table, field);
  // "(1 + x)^T" with T a symbol is a power: only a vector or matrix is transposed.
  if (!p.value.is_vector && !p.value.is_matrix) return read_as_written(typed, table, field);
  // A column or a row is the same vector; a matrix is read as the transpose it asks for.
  if (p.value.is_matrix) {
    std::vector<GiNaC::ex> entries(p.value.entries.size());
    for (std::size_t r = 0; r < p.value.rows; ++r) {
      for (std::size_t c = 0; c < p.value.cols; ++c)
        entries[c * p.value.rows + r] = p.value.entries[r * p.value.cols + c];
    }
    p.value.entries = std::move(entries);
    std::swap(p.value.rows, p.value.cols);
  }
  return p;
}

ReadAnswer read_as_written(const std::string& typed, const sym::SymbolTable& table,
                           const std::string& field) {
  // "0.5 1 1.5", or lines of numbers as MATLAB shows a matrix: a vector or a matrix.
  std::string answer = number_rows(typed).value_or(without_closing_punctuation(typed));
  // "Rz(φ) Ry(θ) Rz(ψ)": turns about the axes, multiplied out.
  if (const auto turns = rotations_multiplied(answer, field)) answer = *turns;
  // "\frac{m R^{2}}{4}": as a LaTeX key prints it, products written out. A sum of vectors with
  // one along a unit vector ("\dot\phi \hat z + \dot\theta (-\sin\phi, \cos\phi, 0)", the
  // hat spelled ẑ, which is no LaTeX) is read term by term, as its Unicode twin is below.
  std::string source = answer;
  if (looks_like_latex(answer)) {
    try {
      source = latex_as_text(answer, table, field);
    } catch (const InputError&) {
      // Not over two bases ("\dot\phi \hat z + \dot\psi \hat e_3"): the caller says so.
      ReadAnswer sum;
      if (bases_named(unit_vectors_named(answer, table)) <= 1 &&
          read_vector_sum(answer, table, field, sum)) {
        return finished(sum, "", field);
      }
      throw;
    }
  }
  // "44°41′37″", "303 days 15 h": a quantity in parts, as their sum; "φ + 90°", "cos(30°)":
  // degrees in an expression, as radians; "303.6 d", days where d is no symbol.
  const auto in_expression = [&](const std::string& name) {
    return (table.contains(name) || sym::is_function_name(name)) && !table.contains("deg");
  };
  const auto is_symbol = [&](const std::string& name) { return table.contains(name); };
  const std::string text = compound_quantity(days_written_d(
      degrees_in_expression(
          sexagesimal_degrees(
              names_apart(symbols_as_spelled(
                              lagrange_rates(leibniz_rates(elliptic_integral_named(
                                                               prepared(source, field), is_symbol),
                                                           table),
                                             table),
                              table),
                          table),
              field),
          in_expression),
      is_symbol));
  if (text.empty()) {
    throw InputError(field +
                     ": empty; type a number (with a unit if you like), a vector [x, y, "
                     "z], a matrix [[..], [..], [..]] or an expression");
  }
  // A unit on each number first: "40 deg, 30 deg, 70 deg" is no vector in degrees whose entries
  // are "40 deg", "30 deg" and 70.
  const EntryUnits entry_units = units_per_entry(text, table, field);
  auto [value, unit] = std::pair{entry_units.value, entry_units.unit};
  if (unit.empty()) std::tie(value, unit) = split_bracket_unit(text, table);
  if (unit.empty()) std::tie(value, unit) = split_unit(text);
  if (unit.empty()) std::tie(value, unit) = split_glued_unit(text, table);
  // "M g", "2 M l g": an expression in the problem's symbols is in SI already, so a tail of its
  // symbols that also spell a unit (g, m, s) is a factor, not grams or metres.
  if (!unit.empty() && has_identifier_of(value, table) && all_identifiers_of(unit, table)) {
    value = text;
    unit.clear();
  }
  ReadAnswer p;
  try {
    p.value = sym::parse_value_text(layout(value), table, field);
  } catch (const InputError& e) {
    if (read_with_factor(value, table, field, p)) {
      if (p.unit && !unit.empty())
        throw InputError(field + ": units inside the bracket and after it; give them in one place");
      return finished(p, unit, field);
    }
    if (read_vector_sum(value, table, field, p)) return finished(p, unit, field);
    // "omega * m" is an expression, not omega in metres.
    if (!unit.empty()) {
      try {
        p.value = sym::parse_value_text(layout(text), table, field);
        unit.clear();
      } catch (const InputError&) {
      }
      // "m R^2/4 kg m^2", "m R^2/4 g cm^2": factors side by side with a unit, read with it (an SI
      // unit) or so as to say what is wrong with it, not that the factors need their '*'.
      if (p.value.entries.empty()) read_side_by_side(value, table, field, p);
    }
    // "[40 deg, 30, 70 deg]": what is wrong is the units, not that "40 deg" is no expression.
    if (p.value.entries.empty() && !entry_units.refusal.empty())
      throw InputError(entry_units.refusal);
    if (unit.empty() && p.value.entries.empty()) {
      // Factors side by side, as LaTeX sets a product and as a student writes one ("M g l",
      // "M l g cos theta0"), and a bracket against a factor ("2(m + R)", "(1/4)(m)(R^2)").
      if (read_side_by_side(value, table, field, p)) return finished(p, unit, field);
      // "0.16 parsecs": a value and something that is not a unit; say so, not "cannot read".
      if (const auto sp = value.find(' '); sp != std::string::npos) {
        bool left_reads = true;
        try {
          (void)sym::parse_value_text(layout(trim(value.substr(0, sp))), table, field);
        } catch (const InputError&) {
          left_reads = false;
        }
        const std::string right = trim(value.substr(sp + 1));
        const std::string written = starred(value, table);
        // "M R^2 (psidot0 + 1/2"; not where no '*' could be written in ("1/2 [a, b").
        if (left_reads && names_a_symbol(right, table) && written != value) {
          // Where the stars would not make it read either ("H ω cos α/(1-h)", h no symbol),
          // what is wrong is that, not the stars.
          const bool bare_function = has_bare_function(written);
          if (!bare_function) (void)sym::parse_value_text(layout(written), table, field);
          throw InputError(field + ": cannot read \"" + value + "\": " +
                           (bare_function
                                ? "products need '*' and a function's argument parentheses "
                                  "(M*g*cos(theta)^2)"
                                : "products need '*' (" + written + ", not " + value + ")"));
        }
        // "0.16 parsecs": throws its error; not for a bracket ("1/2 [a, b": the reader says),
        // nor for mathematics ("2π/Ω", Ω no symbol: the reader names Ω, not a unit "pi/Omega").
        // Nor for what follows an operator ("I1*(thetadot^2) + omega3": no unit starts so), nor
        // a Greek letter with an index ("omega3").
        const auto ids = identifiers(right);
        const bool mathematics =
            right.find_first_of("+-*/^=") == 0 ||
            std::any_of(ids.begin(), ids.end(), [&](const auto& id) {
              std::string name = right.substr(id.first, id.second);
              if (name == "pi" || name == "Pi" || sym::is_function_name(name)) return true;
              // "m r^2/4" where the radius is R: a symbol in the other case, not a unit.
              if (!is_unit(name) && differs_in_case_only(name, table)) return true;
              while (!name.empty() &&
                     (std::isdigit(static_cast<unsigned char>(name.back())) || name.back() == '_'))
                name.pop_back();
              return sym::greek_letters().count(ascii_lower(name)) > 0;
            });
        // Nor for a list ("5/2 ma^2, 3ma^2, ..": no unit has a comma).
        if (left_reads && !mathematics && right.find_first_of("([{") != 0 &&
            right.find(',') == std::string::npos)
          (void)parse_unit(right, field);
      }
      // Where the stars written in leave a name the problem does not have ("½I₁(..) + ½I₃ω₃²",
      // ω₃ no symbol), that name is what is wrong, not the stars. So is what they leave where
      // the text as written failed only for a call without its brackets, which the stars mend:
      // "[sin β, 1, q′]" is refused for its q′, not for the sin β of its first entry.
      if (const std::string written = starred(value, table); written != value) {
        try {
          (void)sym::parse_value_text(layout(written), table, field);
        } catch (const InputError& x) {
          const bool bare_call =
              std::string(e.what()).find("is a function: its argument comes in parentheses") !=
              std::string::npos;
          if (bare_call || std::string(x.what()).find("undefined symbol") != std::string::npos)
            throw;
        }
      }
      const bool glued = !value.empty() && std::isdigit(static_cast<unsigned char>(value[0])) &&
                         value.find(' ') == std::string::npos &&
                         value.find_first_of("*/+-^()") == std::string::npos &&
                         std::any_of(value.begin(), value.end(), [](char c) {
                           return std::isalpha(static_cast<unsigned char>(c));
                         });
      const bool refused = std::string(e.what()).find("is refused") != std::string::npos;
      std::string hint;
      const std::size_t letters = value.find_first_not_of("0123456789.");
      if (!refused && letters != std::string::npos && letters > 0 &&
          std::isdigit(static_cast<unsigned char>(value[0])) &&
          std::isalpha(static_cast<unsigned char>(value[letters])) &&
          value.find(' ') == std::string::npos) {
        const std::string number = value.substr(0, letters);
        const std::string tail = value.substr(letters);
        std::size_t word_end = letters;
        while (word_end < value.size() && std::isalnum(static_cast<unsigned char>(value[word_end])))
          ++word_end;
        const std::string word = value.substr(letters, word_end - letters);
        if (glued && is_unit(tail) && table.contains(tail)) {
          // "0.16m" where m is a mass: a unit's letters the problem also uses as a symbol.
          hint = " (" + tail + " is one of the problem's symbols here: " + number + "*" + tail +
                 " for it, " + number + " " + tail + " for the unit)";
        } else if (units_run_together(word) && !table.contains(word)) {
          // "0.094kgm^2/s", "5Nms": units run together, and against the number.
          hint = " (a number and its units are written apart: '" + number + " " +
                 units_apart(word) + value.substr(word_end) + "')";
        } else if (glued && tail != "i" && tail != "j" && tail != "k") {
          // (not "9.13i": the i is no unit, and what it reads as is said after)
          hint = " (put a space between a number and its unit: '0.21 kg m^2')";
        }
      }
      throw InputError(std::string(e.what()) + hint);
    }
    if (p.value.entries.empty()) throw;
  }
  return finished(p, unit, field);
}
}  // namespace

}  // namespace wobble::check
