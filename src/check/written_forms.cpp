#include "check/written_forms.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <set>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "check/brackets.hpp"
#include "check/judge.hpp"
#include "check/latex_answer.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"
#include "symbolic/expression_guard.hpp"
#include "symbolic/unicode_notation.hpp"
#include "symbolic/units.hpp"

namespace wobble::check {

namespace {
// The most entries a diagonal is written out with: a 3x3 matrix's.
constexpr std::size_t kMostDiagonalEntries = 3;

// The calls that make a diagonal matrix, the longest first so that "np.diag" is not read as
// "np." and "diag".
const std::array<std::string, 8>& diagonal_calls() {
  static const std::array<std::string, 8> calls{"DiagonalMatrix", "numpy.diag", "sympy.diag",
                                                "Matrix.diag",    "np.diag",    "sp.diag",
                                                "diagm",          "diag"};
  return calls;
}

// The call's name starting at `at` (and a bracket after it), or "".
std::string diagonal_call_at(const std::string& s, std::size_t at) {
  if (at > 0) {
    const char before = s[at - 1];
    if (std::isalnum(static_cast<unsigned char>(before)) || before == '_' || before == '.')
      return "";
  }
  for (const auto& name : diagonal_calls()) {
    if (s.compare(at, name.size(), name) != 0) continue;
    const std::size_t open = s.find_first_not_of(' ', at + name.size());
    if (open != std::string::npos && (s[open] == '(' || s[open] == '[')) return name;
  }
  return "";
}

// The diagonal's entries: "a, b, c", "[a, b, c]", "[a b c]" (MATLAB), "[a; b; c]".
std::vector<std::string> diagonal_entries(std::string inside) {
  inside = trim(inside);
  if (wrapped(inside, '[') || wrapped(inside, '('))
    inside = trim(inside.substr(1, inside.size() - 2));
  for (const char sep : {',', ';'}) {
    if (auto items = top_level(inside, sep); items.size() > 1) return items;
  }
  return space_separated_entries(inside);
}

// "0.5", "-1.25e-3", "+2.": a number as a program prints one, and nothing else.
bool is_plain_number(const std::string& token) {
  std::size_t i = token.size() > 1 && (token[0] == '-' || token[0] == '+') ? 1 : 0;
  std::size_t digits = 0;
  while (i < token.size() && (is_digit(token[i]) || token[i] == '.')) {
    digits += token[i] != '.';
    ++i;
  }
  if (digits == 0 || std::count(token.begin(), token.end(), '.') > 1) return false;
  if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
    ++i;
    if (i < token.size() && (token[i] == '-' || token[i] == '+')) ++i;
    const std::size_t exponent = i;
    while (i < token.size() && is_digit(token[i])) ++i;
    if (i == exponent) return false;
  }
  return i == token.size();
}

// The slots, if each is taken once.
std::optional<std::vector<std::size_t>> checked(const std::vector<std::size_t>& slots) {
  std::vector<std::size_t> sorted = slots;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    if (sorted[k] != k) return std::nullopt;
  }
  return slots;
}

// The slots of labels that are all among `names`, as many as they, in any order (each label's
// place in `names`); nullopt otherwise.
std::optional<std::vector<std::size_t>> slots_among(const std::vector<std::string>& labels,
                                                    const std::vector<std::string>& names) {
  if (labels.size() != names.size()) return std::nullopt;
  std::vector<std::size_t> slots;
  for (const auto& l : labels) {
    const auto at = std::find(names.begin(), names.end(), l);
    if (at == names.end()) return std::nullopt;
    slots.push_back(static_cast<std::size_t>(at - names.begin()));
  }
  return slots;
}

// Where labels of one length differ from the first, in increasing order; nullopt where their
// lengths differ.
std::optional<std::vector<std::size_t>> differing_places(const std::vector<std::string>& labels) {
  const std::string& first = labels.at(0);
  std::vector<std::size_t> places;
  for (const auto& l : labels) {
    if (l.size() != first.size()) return std::nullopt;
    for (std::size_t k = 0; k < l.size(); ++k) {
      if (l[k] != first[k] && std::find(places.begin(), places.end(), k) == places.end())
        places.push_back(k);
    }
  }
  std::sort(places.begin(), places.end());
  return places;
}

// Where each label's component goes: by the key's own names of the entries, Euler's angles by
// name ("phi, theta, psi", "alpha, beta, gamma", as a key orders them), or names alike but for
// one character, at one place, that says the component ("x", "omega_x", "x_cm", "I1"). nullopt
// where the labels say no order.
std::optional<std::vector<std::size_t>> component_slots(const std::vector<std::string>& labels,
                                                        const std::vector<std::string>& entry_names,
                                                        std::size_t entries) {
  std::vector<std::string> spelled;  // the key's names as labels are spelled
  for (const auto& n : entry_names) spelled.push_back(name_spelling(n));
  if (const auto slots = slots_among(labels, spelled)) {
    if (auto each_once = checked(*slots)) return each_once;
  }
  for (const auto& names : {std::vector<std::string>{"phi", "theta", "psi"},
                            std::vector<std::string>{"alpha", "beta", "gamma"}}) {
    if (const auto slots = slots_among(labels, names)) return checked(*slots);
  }
  const auto places = differing_places(labels);
  if (!places) return std::nullopt;
  // Three components, or two where the answer is a pair ("Ω₁ = 7.2, Ω₂ = −11.6").
  if (places->size() != 1 || labels.size() != (entries == 2 ? 2 : 3)) return std::nullopt;
  std::string axes;
  for (const auto& l : labels)
    axes += static_cast<char>(std::tolower(static_cast<unsigned char>(l[places->front()])));
  const std::string order = axes.find_first_of("xyz") != std::string::npos ? "xyz" : "123";
  std::vector<std::size_t> slots;
  for (const char a : axes) {
    if (order.find(a) == std::string::npos) return std::nullopt;
    slots.push_back(order.find(a));
  }
  return checked(slots);
}
}  // namespace

std::string diagonals_written_out(const std::string& ascii, const std::string& field) {
  std::string out;
  std::size_t i = 0;
  while (i < ascii.size()) {
    const std::string name = diagonal_call_at(ascii, i);
    if (name.empty()) {
      out += ascii[i++];
      continue;
    }
    const std::size_t open = ascii.find_first_not_of(' ', i + name.size());
    const std::size_t close = matching(ascii, open);
    if (close == std::string::npos) {  // the reader names the unbalanced bracket
      out += ascii.substr(i);
      break;
    }
    const std::vector<std::string> entries =
        diagonal_entries(ascii.substr(open + 1, close - open - 1));
    if (entries.size() > kMostDiagonalEntries) {
      throw InputError(field + ": " + name + "(..) with " + std::to_string(entries.size()) +
                       " entries; wobble's matrices are 3x3");
    }
    if (entries.size() < 2 || std::any_of(entries.begin(), entries.end(),
                                          [](const std::string& e) { return e.empty(); })) {
      out += ascii.substr(i, close + 1 - i);  // no diagonal: the reader says what it is
    } else {
      out += '[';
      for (std::size_t r = 0; r < entries.size(); ++r) {
        out += r ? ", [" : "[";
        for (std::size_t c = 0; c < entries.size(); ++c)
          out += (c ? ", " : "") + (r == c ? entries[r] : std::string("0"));
        out += ']';
      }
      out += ']';
    }
    i = close + 1;
  }
  return out;
}

namespace {
std::optional<std::string> rows_of_numbers(const std::string& typed);
}

std::optional<std::string> number_rows(const std::string& typed) {
  if (auto rows = rows_of_numbers(typed)) return rows;
  // "(0.5 1 1.5)": a row in parentheses, where no expression has two numbers side by side.
  const std::string t = trim(typed);
  const auto unbracketed = [](const std::string& v) {
    return wrapped(v, '(') ? v.substr(1, v.size() - 2) : v;
  };
  if (wrapped(t, '(')) return rows_of_numbers(unbracketed(t));
  // "[4.33 -0.5 -0.75\n -0.5 3.33 -1.5\n ...]": MATLAB's literal, a row on each line.
  const bool on_lines = t.find('\n') != std::string::npos;
  if (on_lines && wrapped(t, '[')) return rows_of_numbers(t.substr(1, t.size() - 2));
  // "0.5 1 1.5 m", "(0.5 1 1.5) m": a unit after the row is the whole vector's.
  const auto [row, unit] = split_unit(t);
  if (unit.empty()) return std::nullopt;
  const std::string inside =
      on_lines && wrapped(row, '[') ? row.substr(1, row.size() - 2) : unbracketed(row);
  if (auto rows = rows_of_numbers(inside)) return *rows + " " + unit;
  return std::nullopt;
}

namespace {
std::optional<std::string> rows_of_numbers(const std::string& typed) {
  const bool on_lines = typed.find('\n') != std::string::npos;
  std::vector<std::vector<std::string>> rows;
  std::size_t start = 0;
  while (start <= typed.size()) {
    const std::size_t end = std::min(typed.find('\n', start), typed.size());
    std::string line = trim(typed.substr(start, end - start));
    if (on_lines) {
      // "4.33, -0.5, -0.75;": on lines, commas may part a row's entries and a ';' or ',' end it
      // ("-0.75,\n -0.5" is two entries, not -0.75 - 0.5).
      while (!line.empty() && (line.back() == ';' || line.back() == ',')) line.pop_back();
      std::replace(line.begin(), line.end(), ',', ' ');
    }
    std::vector<std::string> row;
    for (const auto& token : top_level(line, ' ')) {
      if (!is_plain_number(token)) return std::nullopt;
      row.push_back(token);
    }
    if (!row.empty()) rows.push_back(std::move(row));
    start = end + 1;
  }
  if (rows.empty()) return std::nullopt;
  const std::size_t columns = rows[0].size();
  for (const auto& r : rows) {
    if (r.size() != columns) return std::nullopt;
  }
  if (rows.size() == 1 && columns == 1) return std::nullopt;  // one number
  std::vector<std::string> entries;                           // a row or a column: a vector
  if (rows.size() == 1 || columns == 1) {
    for (const auto& r : rows) entries.insert(entries.end(), r.begin(), r.end());
    return "[" + joined(entries) + "]";
  }
  for (const auto& r : rows) entries.push_back("[" + joined(r) + "]");
  return "[" + joined(entries) + "]";
}
}  // namespace

std::pair<std::string, std::string> split_unit(const std::string& s) {
  for (std::size_t sp = s.find(' '); sp != std::string::npos; sp = s.find(' ', sp + 1)) {
    const std::string right = trim(s.substr(sp + 1));
    if (right.empty() || right[0] == '*' || right[0] == '/') continue;
    // As typed ("kg m²") or as read ("kg m^2"): the unit parser reads the latter. A unit is a
    // few words: a longer right side is not rewritten first, or a long answer would be rewritten
    // at each of its spaces.
    constexpr std::size_t kLongestTypedUnit = 48;
    const bool ascii = std::all_of(right.begin(), right.end(),
                                   [](char c) { return static_cast<unsigned char>(c) < 0x80; });
    if (is_unit(ascii || right.size() > kLongestTypedUnit ? right : sym::to_ascii(right)))
      return {trim(s.substr(0, sp)), right};
  }
  return {s, ""};
}

namespace {
// The axis an index character names (x, y, z or 1, 2, 3 as 0, 1, 2), or -1.
int axis_index(char c) {
  const std::size_t at = std::string_view("xyz123").find(
      static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  return at == std::string_view::npos ? -1 : static_cast<int>(at % 3);
}

// "I_xx = .., I_yy = .., I_zz = .., I_xy = ..": a tensor's entries by their two indices, names
// alike but for two characters side by side (xx, xy, .. or 11, 12, ..). An entry not given is
// its mirror's, the tensor being symmetric, else zero ("I_xx = I_yy = .., I_zz = ..": a
// diagonal tensor told by its diagonal). nullopt where the labels are no such entries.
std::optional<std::string> tensor_entries(const std::vector<std::string>& labels,
                                          const std::vector<std::string>& values) {
  if (labels.size() < 2 || labels.size() > 9) return std::nullopt;
  const std::string& first = labels[0];
  const auto found = differing_places(labels);
  if (!found || first.size() < 2) return std::nullopt;
  const std::vector<std::size_t>& places = *found;
  if (places.empty() || places.size() > 2 || places.back() - places.front() > 1)
    return std::nullopt;
  // The two indices: the places themselves, or one of them and its neighbour.
  for (const std::size_t at : {places.front(), places.front() == 0 ? 0 : places.front() - 1}) {
    if (at + 1 >= first.size() || places.back() > at + 1) continue;
    std::array<std::array<std::string, 3>, 3> m;
    bool fits = true;
    const bool digits = std::isdigit(static_cast<unsigned char>(first[at])) != 0;
    for (std::size_t k = 0; k < labels.size() && fits; ++k) {
      const char a = labels[k][at], b = labels[k][at + 1];
      const int r = axis_index(a), c = axis_index(b);
      fits = r >= 0 && c >= 0 && (std::isdigit(static_cast<unsigned char>(a)) != 0) == digits &&
             (std::isdigit(static_cast<unsigned char>(b)) != 0) == digits;
      if (!fits) break;
      std::string& entry = m[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
      fits = entry.empty();  // each entry once
      entry = values[k];
    }
    if (!fits) continue;
    std::string out = "[";
    for (std::size_t r = 0; r < 3; ++r) {
      out += r ? ", [" : "[";
      for (std::size_t c = 0; c < 3; ++c) {
        const std::string& v = !m[r][c].empty() ? m[r][c] : !m[c][r].empty() ? m[c][r] : "0";
        out += (c ? ", " : "") + v;
      }
      out += "]";
    }
    return out + "]";
  }
  return std::nullopt;
}
}  // namespace

std::optional<LabelledComponents> labelled_components(const std::string& text,
                                                      const std::string& field,
                                                      const std::vector<std::string>& entry_names,
                                                      std::size_t entries) {
  // A label: one word, no operator or bracket in it ("I₁", "omega_x", "α").
  const auto label_like = [](const std::string& side) {
    const std::string t = trim(side);
    return !t.empty() && t.find_first_of(" +-*/^()[]{}.,") == std::string::npos;
  };
  std::vector<std::string> items = top_level(text, ',');
  // "φ=130° θ=30° ψ=-20°": items parted by spaces alone, each side between two '=' a value and
  // the next label; read so only where the labels place the components (below).
  bool spaced = false;
  if (const std::vector<std::string> sides = top_level(text, '=');
      items.size() == 1 && sides.size() >= 3) {
    std::vector<std::string> parted{trim(sides[0])};
    for (std::size_t k = 1; k + 1 < sides.size(); ++k) {
      const std::string side = trim(sides[k]);
      const std::size_t space = side.find_last_of(' ');
      if (space == std::string::npos || !label_like(side.substr(space + 1))) break;
      parted.back() += " = " + trim(side.substr(0, space));
      parted.push_back(side.substr(space + 1));
    }
    if (parted.size() == sides.size() - 1) {
      parted.back() += " = " + trim(sides.back());
      items = parted;
      spaced = true;
    }
  }
  // One item only where its labels are all the components: "I1 = I2 = I3 = 0.006" (a sphere).
  const bool one_chain = items.size() == 1;
  if (one_chain && top_level(text, '=').size() < 3) return std::nullopt;
  std::vector<std::string> labels, values, notes;
  for (const auto& item : items) {
    const std::vector<std::string> sides = top_level(item, '=');
    if (sides.size() < 2 || sides[0].empty() || sides.back().empty()) return std::nullopt;
    // "I₁ = I₂ = 3M(4R² + h²)/80": equal components told once, as a degenerate pair is. After
    // the labels, formulas before the value, "I₃ = I₁ + I₂ = 5.5" (the plane body's
    // perpendicular axes), in a list of several items: read past, said so.
    std::size_t named = sides.size() == 2 ? 1 : 0;  // one label: as it is written
    while (named + 1 < sides.size() && label_like(sides[named])) ++named;
    if (named == 0 || (named + 1 < sides.size() && (one_chain || spaced))) return std::nullopt;
    for (std::size_t k = named; k + 1 < sides.size(); ++k)
      notes.push_back(fmt::format("{} (before {}'s value) is not judged: its value is",
                                  trim(sides[k]), trim(sides[0])));
    for (std::size_t k = 0; k < named; ++k) {
      labels.push_back(name_spelling(sides[k]));
      values.push_back(sides.back());
    }
  }
  // "x = 0.5, y = 1, z = 1.5 m": a unit after the last value, and none after the others, is
  // the whole vector's, as after a list in brackets; the last told once for several labels,
  // "I_xy = −0.5, I_xx = I_yy = I_zz = 3 kg m²", is one value.
  std::string unit;
  if (const auto [last, after] = split_unit(trim(values.back())); !after.empty()) {
    const bool others_bare = std::all_of(
        values.begin(), values.end() - 1,
        [&](const std::string& v) { return v == values.back() || split_unit(v).second.empty(); });
    if (others_bare) {
      unit = " " + after;
      for (auto& v : values) {
        if (v == values.back()) v = last;  // equal components told once share the value
      }
    }
  }
  if (entries == 9) {  // a matrix: its entries by two indices
    if (auto tensor = tensor_entries(labels, values))
      return LabelledComponents{*tensor + unit, false, notes};
  }
  const std::optional<std::vector<std::size_t>> slots =
      component_slots(labels, entry_names, entries);
  // "L = I0 = 0.00072": a key's line, labelled; "L = I0 ω = 0.00072", no components spaced.
  if (!slots && (one_chain || spaced)) return std::nullopt;
  if (!slots) {
    throw InputError(field +
                     ": components given one by one need one label for each, the same name "
                     "with x, y, z or 1, 2, 3 in it (x = 0.5, y = 1, z = 1.5), the key's names "
                     "of the entries" +
                     (entry_names.empty() ? std::string() : " (" + joined(entry_names) + ")") +
                     ", or Euler's angles by name; or write the vector [x, y, z]");
  }
  std::vector<std::string> in_order(labels.size());
  for (std::size_t k = 0; k < labels.size(); ++k) in_order[(*slots)[k]] = values[k];
  // "e1 = (..), e2 = (..), e3 = (..)": vectors labelled so are a matrix's columns, as the key's
  // principal axes are; written as its rows, transposed.
  const bool columns = std::all_of(in_order.begin(), in_order.end(), [](const std::string& v) {
    return wrapped(v, '(') || wrapped(v, '[');
  });
  std::string vector = "[";
  for (std::size_t k = 0; k < in_order.size(); ++k) {
    const std::string& v = in_order[k];
    vector += (k ? ", " : "") + (columns ? "[" + v.substr(1, v.size() - 2) + "]" : v);
  }
  return LabelledComponents{vector + (columns ? "]^T" : "]") + unit, columns, notes};
}

namespace {
// The axis (0, 1, 2) a label of one component names (in ASCII, its underscores kept), or -1: x,
// y or z alone, first before an underscore ("z_cm"), or last after one letter or a Greek
// letter's name ("L_z", "Lz", "omega_3" as ω₃ is spelled, "omega3′" with a primed basis's prime;
// not "Omega_body", whose y is no axis).
int axis_of_label(std::string label) {
  // "ω₃′": a primed basis's component is labelled with its prime after the index.
  for (const std::string prime : {"′", "'"}) {
    while (label.size() > prime.size() && label.ends_with(prime))
      label.erase(label.size() - prime.size());
  }
  if (label.empty()) return -1;
  const bool xyz = label.size() == 1 || label[1] == '_';
  if (xyz && std::string_view("xyz").find(label[0]) != std::string_view::npos)
    return axis_index(label[0]);
  if (label.size() < 2 || std::string_view("xyz123").find(label.back()) == std::string_view::npos)
    return -1;
  std::string name = label.substr(0, label.size() - 1);
  if (name.back() == '_') name.pop_back();
  const bool letter = name.size() == 1 && std::isalpha(static_cast<unsigned char>(name[0]));
  return letter || sym::greek_letters().count(ascii_lower(name)) ? axis_index(label.back()) : -1;
}
}  // namespace

std::string rules_as_equations(const std::string& text) {
  std::string t = trim(text);
  if (t.find("->") == std::string::npos && t.find("→") == std::string::npos) return text;
  // Solve's answer: a list of solutions, each a list of rules.
  while (t.size() >= 2 && t.front() == '{' && matching(t, 0) == t.size() - 1)
    t = trim(t.substr(1, t.size() - 2));
  std::string out;
  for (const std::string& item : top_level(t, ',')) {
    std::size_t at = item.find("->"), width = 2;
    if (const std::size_t unicode = item.find("→"); unicode < at) {
      at = unicode;
      width = std::string_view("→").size();
    }
    if (at == std::string::npos) return text;
    const std::string left = trim(item.substr(0, at)), right = trim(item.substr(at + width));
    if (left.empty() || right.empty() || right.find("->") != std::string::npos ||
        right.find("→") != std::string::npos)
      return text;
    out += (out.empty() ? "" : ", ") + left + " = " + right;
  }
  return out;
}

// The unit after a rule's zero, "(kg m²)", "in kg m²" or "kg m²": the whole list's, as a unit in
// brackets after its last value is; "" where nothing follows the zero; nullopt where what follows
// is no unit.
std::optional<std::string> unit_after_rule(const std::string& tail) {
  std::string unit = trim(tail);
  if (unit.empty()) return std::string();
  if (unit.size() > 2 && unit.front() == '(' && unit.back() == ')')
    unit = trim(unit.substr(1, unit.size() - 2));
  if (ascii_lower(unit.substr(0, 3)) == "in ") unit = trim(unit.substr(3));
  try {
    (void)parse_unit(sym::to_ascii(unit), "unit");
  } catch (const InputError&) {
    return std::nullopt;
  }
  return unit;
}

std::string without_others_zero(const std::string& text) {
  const std::vector<std::string> items = top_level(text, ',');
  if (items.size() < 2) return text;
  const std::string& rule = items.back();
  static const std::set<std::string> kZero{"0", "zero", "vanish", "vanishes"};
  static const std::set<std::string> kRest{"others", "other", "rest"};
  static const std::set<std::string> kFiller{
      "all", "the", "are", "is", "entries", "elements", "components", "products", "off-diagonal"};
  // The rule's words up to its zero ('=' parts them as a space does: "all others = 0"), each
  // a rest word or filler, and where the zero ends.
  bool rest = false;
  std::size_t i = 0, zero_end = std::string::npos;
  while (i < rule.size() && zero_end == std::string::npos) {
    if (rule[i] == ' ' || rule[i] == '=') {
      ++i;
      continue;
    }
    const std::size_t end = rule.find_first_of(" =", i);
    const std::string word = ascii_lower(rule.substr(i, end - i));
    if (kZero.count(word) && i > 0) {
      zero_end = end == std::string::npos ? rule.size() : end;
    } else if (kRest.count(word)) {
      rest = true;
    } else if (!kFiller.count(word)) {
      return text;
    }
    i = end == std::string::npos ? rule.size() : end;
  }
  if (zero_end == std::string::npos || !rest) return text;
  const std::optional<std::string> unit = unit_after_rule(rule.substr(zero_end));
  const bool labelled = std::any_of(items.begin(), items.end() - 1, [](const std::string& item) {
    return item.find('=') != std::string::npos;
  });
  if (!unit || !labelled) return text;
  const std::string listed = text.substr(0, text.rfind(','));
  return unit->empty() ? listed : listed + " (" + *unit + ")";
}

std::optional<SomeComponents> some_components(const std::string& text) {
  const std::vector<std::string> items = top_level(text, ',');
  if (items.size() > 2) return std::nullopt;
  std::vector<std::string> labels, values;
  for (const auto& item : items) {
    const std::vector<std::string> sides = top_level(item, '=');
    if (sides.size() != 2) return std::nullopt;
    const std::string label = trim(sides[0]), value = trim(sides[1]);
    if (label.empty() || value.empty() ||
        label.find_first_of(" +-*/^()[]{}.,") != std::string::npos)
      return std::nullopt;
    labels.push_back(sym::to_ascii(label));
    values.push_back(value);
  }
  std::array<std::string, 3> in_place;
  std::vector<int> axes;
  for (const auto& label : labels) axes.push_back(axis_of_label(label));
  if (labels.size() == 2) {  // alike but for the axis's character
    const auto places = differing_places(labels);
    if (!places || places->size() != 1) return std::nullopt;
    for (std::size_t k = 0; k < 2; ++k) {
      const int axis = axis_index(labels[k][places->front()]);
      if (axis < 0 || (axes[k] >= 0 && axes[k] != axis)) return std::nullopt;
      axes[k] = axis;
    }
  }
  for (std::size_t k = 0; k < labels.size(); ++k) {
    if (axes[k] < 0 || !in_place[static_cast<std::size_t>(axes[k])].empty()) return std::nullopt;
    in_place[static_cast<std::size_t>(axes[k])] = values[k];
  }
  // A unit after the last value alone is the whole vector's, as with every component given.
  std::string unit;
  if (const auto [last, after] = split_unit(values.back());
      !after.empty() && std::all_of(values.begin(), values.end() - 1, [](const std::string& v) {
        return split_unit(v).second.empty();
      })) {
    unit = " " + after;
    for (auto& v : in_place) {
      if (v == values.back()) v = last;
    }
  }
  SomeComponents out{"[", {}};
  for (std::size_t k = 0; k < 3; ++k) {
    out.text += (k ? ", " : "") + (in_place[k].empty() ? std::string("0") : in_place[k]);
    if (in_place[k].empty()) out.missing.push_back(k);
  }
  out.text += "]" + unit;
  return out;
}

std::string without_colon_labels(const std::string& typed) {
  // A label: words of letters (any Unicode one), digits and underscores, a letter first.
  const auto label_like = [](const std::string& side) {
    const std::string t = trim(side);
    if (t.empty() || !(is_letter(t[0]) || static_cast<unsigned char>(t[0]) >= 0x80)) return false;
    int words = 1;
    for (std::size_t i = 0; i < t.size(); ++i) {
      const auto c = static_cast<unsigned char>(t[i]);
      if (t[i] == ' ') {
        words += t[i - 1] != ' ';
      } else if (!(std::isalnum(c) || t[i] == '_' || c >= 0x80 || t[i] == '\'')) {
        return false;
      }
    }
    return words <= 4;
  };
  const std::vector<std::string> items = top_level(typed, ',');
  // "I1: 0.569, I2: 4.209, I3: 4.556": each item labelled.
  if (items.size() >= 2 && std::all_of(items.begin(), items.end(), [&](const std::string& item) {
        const auto colon = item.find(':');
        return colon != std::string::npos && item.find(':', colon + 1) == std::string::npos &&
               label_like(item.substr(0, colon)) && !trim(item.substr(colon + 1)).empty();
      })) {
    std::string out;
    for (const auto& item : items) {
      const auto colon = item.find(':');
      out += (out.empty() ? "" : ", ") + trim(item.substr(0, colon)) + " = " +
             trim(item.substr(colon + 1));
    }
    return out;
  }
  // "eigenvalues: 0.569, 4.209, 4.556": one label before the whole.
  const auto colon = typed.find(':');
  if (colon == std::string::npos || typed.find(':', colon + 1) != std::string::npos ||
      !label_like(typed.substr(0, colon)) || trim(typed.substr(colon + 1)).empty())
    return typed;
  return trim(typed.substr(colon + 1));
}

namespace {
// LaTeX's spacing around a word in text: "\quad", "\qquad", "\,", "\;", "\:", "\ ", "~" and
// spaces; the length of such spacing that ends at `end` (before) or starts at `at` (after).
constexpr std::array<std::string_view, 8> kLatexSpaces{"\\qquad", "\\quad", "\\,", "\\;",
                                                       "\\:",     "\\ ",    "~",   " "};
std::size_t spacing_before(const std::string& s, std::size_t end) {
  std::size_t at = end;
  for (bool more = true; more;) {
    more = false;
    for (const std::string_view space : kLatexSpaces) {
      if (at >= space.size() && s.compare(at - space.size(), space.size(), space) == 0) {
        at -= space.size();
        more = true;
        break;
      }
    }
  }
  return end - at;
}
std::size_t spacing_after(const std::string& s, std::size_t at) {
  std::size_t end = at;
  for (bool more = true; more;) {
    more = false;
    for (const std::string_view space : kLatexSpaces) {
      if (s.compare(end, space.size(), space) == 0) {
        end += space.size();
        more = true;
        break;
      }
    }
  }
  return end - at;
}

// "-11.89 \text{ and } -7.2", "x = 1,\quad\text{and}\quad y = 2": LaTeX's word in text, with
// the spacing around it, as a comma.
std::string latex_and_as_comma(const std::string& typed) {
  std::string out = typed;
  for (const std::string_view command : {"\\text{", "\\textrm{", "\\mathrm{"}) {
    for (std::size_t at = out.find(command); at != std::string::npos; at = out.find(command, at)) {
      const std::size_t close = out.find('}', at);
      if (close == std::string::npos) break;
      const std::size_t inside = at + command.size();
      if (trim(out.substr(inside, close - inside)) != "and") {
        at = close;
        continue;
      }
      std::size_t from = at - spacing_before(out, at);
      const std::size_t to = close + 1 + spacing_after(out, close + 1);
      if (from > 0 && out[from - 1] == ',') --from;  // ", \text{and}": the comma is there
      out.replace(from, to - from, ", ");
      at = from + 2;
    }
  }
  return out;
}
}  // namespace

std::string and_as_comma(const std::string& typed) {
  if (looks_like_latex(typed)) return latex_and_as_comma(typed);
  std::string out;
  for (std::size_t at = 0; at < typed.size();) {
    // The word alone, spaces on both sides, in any case ("AND" as a shouted list has it).
    const bool word = at > 0 && typed[at - 1] == ' ' && at + 4 <= typed.size() &&
                      ascii_lower(typed.substr(at, 3)) == "and" && typed[at + 3] == ' ';
    if (!word) {
      out += typed[at++];
      continue;
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    if (!out.empty() && out.back() != ',') out += ',';  // ", and": the comma is there
    out += ' ';
    at += 4;
  }
  return out;
}

std::string without_comments(const std::string& s) {
  std::string out;
  bool in_comment = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '\n') in_comment = false;
    const bool percent = c == '%' && (i == 0 || s[i - 1] == ' ' || s[i - 1] == '\t' ||
                                      s[i - 1] == ';' || s[i - 1] == '\n');
    if (c == '#' || percent) in_comment = true;
    if (!in_comment) out += c;
  }
  return out;
}

std::string in_units_of_written(const std::string& typed) {
  std::string t = trim(typed);
  const bool bracketed = !t.empty() && t.back() == ')';
  if (bracketed) t = trim(t.substr(0, t.size() - 1));
  // "in units of X"; in brackets also "(in X)", "(times X)", "(× X)", "(all × X)", "(each
  // times X)".
  std::size_t at = ascii_lower(t).rfind("in units of ");
  std::size_t phrase = std::string_view("in units of ").size();
  if (bracketed && (at == std::string::npos || at == 0)) {
    const std::size_t open = t.rfind('(');
    const std::string inside = open == std::string::npos ? "" : ascii_lower(t.substr(open + 1));
    for (const std::string_view factor :
         {"in ", "times ", "× ", "×", "all times ", "all × ", "each times ", "each × "}) {
      if (inside.compare(0, factor.size(), factor) == 0) {
        at = open + 1;
        phrase = factor.size();
        break;
      }
    }
  }
  if (at == std::string::npos || at == 0) return typed;
  const std::string unit = trim(t.substr(at + phrase));
  std::string before = trim(t.substr(0, at));
  if (bracketed) {
    if (before.empty() || before.back() != '(') return typed;
    before = trim(before.substr(0, before.size() - 1));
  }
  if (unit.empty() || before.empty()) return typed;
  // "Ixx = 3, Ixy = -0.5, others 0 (in g cm²)": the unit is the whole list's, which the rule's
  // reading takes; here it would be the last item's, rule and all.
  if (without_others_zero(before) != before) return typed;
  // The value after the last '=' at the top level; a label before it stays.
  const std::vector<std::string> sides = top_level(before, '=');
  const std::string value = trim(sides.back());
  if (value.empty()) return typed;
  const std::string label = trim(before.substr(0, before.size() - sides.back().size()));
  // "303.6 days (in units of days)": a value with its unit already says it; the words are a
  // remark. So is "(in SI)", "(in SI units)": a bare number is read in the key's unit, an SI one.
  const std::string lower_unit = ascii_lower(unit);
  if (!split_unit(value).second.empty() || lower_unit == "si" || lower_unit == "si units")
    return label + (label.empty() ? "" : " ") + value;
  const bool one_bracket = opens(value.front()) && matching(value, 0) == value.size() - 1;
  // "(0.0737) * 100 J": a number is joined by '*', as a number beside a number is no product.
  const bool number = std::isdigit(static_cast<unsigned char>(unit[0])) != 0 || unit[0] == '.';
  return label + (label.empty() ? "" : " ") + (one_bracket ? value : "(" + value + ")") +
         (number ? " * " : " ") + unit;
}

std::string without_remark(const std::string& typed,
                           const std::function<bool(const std::string&)>& is_known) {
  const std::string t = trim(typed);
  if (t.size() < 2 || t.back() != ')') return typed;
  const std::size_t open = t.rfind('(');
  if (open == std::string::npos || open == 0 || t[open - 1] != ' ') return typed;
  const std::string inside = t.substr(open + 1, t.size() - open - 2);
  std::vector<std::string> words(1);
  for (const char c : inside) {
    if (is_letter(c)) {
      words.back() += c;
    } else if (c == ' ' || c == ',' || c == '-' || c == '\'') {
      if (!words.back().empty()) words.emplace_back();
    } else {
      return typed;  // a digit, an operator, a Unicode letter: mathematics, not a remark
    }
  }
  if (words.back().empty()) words.pop_back();
  const bool unknown_word = std::any_of(words.begin(), words.end(), [&](const std::string& w) {
    return w.size() >= 3 && !is_known(w);
  });
  if (words.size() < 2 || !unknown_word) return typed;
  return trim(t.substr(0, open));
}

namespace {
// "2.047 rad/s, stable", "1.772 1/s; unstable", "1.772 1/s unstable": the last word and the
// answer before it, a comma, a semicolon or a dash between taken off; nullopt where the text
// does not end in a word after a space or one of those.
std::optional<std::pair<std::string, std::string>> last_word(const std::string& t) {
  std::size_t start = t.size();
  while (start > 0 && (is_letter(t[start - 1]) || t[start - 1] == '.')) --start;
  if (start == 0 || start == t.size()) return std::nullopt;
  std::string answer = t.substr(0, start);
  const std::size_t before_separator = answer.size();
  while (!answer.empty() && (answer.back() == ' ' || answer.back() == ',' || answer.back() == ';' ||
                             answer.back() == '-'))
    answer.pop_back();
  for (const char* dash : {"—", "–"}) {  // an em or en dash, spaced
    const std::string d(dash);
    if (answer.size() >= d.size() && answer.compare(answer.size() - d.size(), d.size(), d) == 0)
      answer = trim(answer.substr(0, answer.size() - d.size()));
  }
  if (answer.size() == before_separator) return std::nullopt;  // glued on: "2.05stable"
  return std::pair{answer, t.substr(start)};
}
}  // namespace

std::optional<WordRemark> word_remark(const std::string& typed) {
  const std::string t = trim(typed);
  if (t.size() < 3) return std::nullopt;
  static const std::set<std::string> kWords{
      "stable",   "unstable",   "oscillating", "oscillates",       "oscillatory",
      "growing",  "grows",      "exponential", "prolate",          "oblate",
      "prograde", "retrograde", "clockwise",   "counterclockwise", "anticlockwise",
      "approx",   "approx.",    "approximate", "approximately",    "exact",
      "exactly",  "rounded",    "estimate",    "estimated"};
  std::string word, answer, said;
  bool bracketed = false;
  if (const std::size_t open = t.rfind('(');
      t.back() == ')' && open != std::string::npos && open > 0 && t[open - 1] == ' ') {
    word = ascii_lower(trim(t.substr(open + 1, t.size() - open - 2)));
    answer = trim(t.substr(0, open));
    said = t.substr(open);
    bracketed = true;
  } else if (const auto last = last_word(t)) {
    std::tie(answer, said) = *last;
    word = ascii_lower(said);
  }
  if (kWords.count(word) == 0 || answer.empty()) return std::nullopt;
  static const std::set<std::string> kStable{"stable", "oscillating", "oscillates", "oscillatory"},
      kUnstable{"unstable", "growing", "grows", "exponential"};
  std::optional<bool> says_stable, says_with_spin;
  if (kStable.count(word)) says_stable = true;
  if (kUnstable.count(word)) says_stable = false;
  if (word == "prograde" || word == "oblate") says_with_spin = true;
  if (word == "retrograde" || word == "prolate") says_with_spin = false;
  return WordRemark{answer, said, bracketed, says_stable, says_with_spin};
}

std::optional<Restatement> restatement_of(const std::string& typed) {
  const std::string t = trim(typed);
  if (t.size() < 3 || t.back() != ')') return std::nullopt;
  // The '(' that the last ')' closes: "(about 1.5 (rad/s))" is one bracket.
  std::size_t open = t.size() - 1;
  for (int depth = 0;; --open) {
    if (t[open] == ')') ++depth;
    if (t[open] == '(' && --depth == 0) break;
    if (open == 0) return std::nullopt;
  }
  if (open == 0 || t[open - 1] != ' ') return std::nullopt;
  const std::string inside = trim(t.substr(open + 1, t.size() - open - 2));
  static const std::array<const char*, 20> kLeads{
      "about ",   "approx. ",  "approx ", "approximately ",
      "roughly ", "around ",   "circa ",  "ca. ",
      "nearly ",  "i.e. ",     "i.e., ",  "ie ",
      "that is ", "that is, ", "or ",     "=",
      "≈",        "≃",         "∼",       "~"};
  for (const char* lead : kLeads) {
    const std::string l = lead;
    if (inside.size() <= l.size() || ascii_lower(inside.substr(0, l.size())) != l) continue;
    const std::string again = trim(inside.substr(l.size()));
    const bool number =
        !again.empty() && (is_digit(again[0]) || again[0] == '.' || again[0] == '-' ||
                           again[0] == '+' || again.rfind("−", 0) == 0);
    if (!number) return std::nullopt;
    return Restatement{trim(t.substr(0, open)), again, t.substr(open)};
  }
  return std::nullopt;
}

std::string without_output_label(const std::string& s) {
  const std::string t = trim(s);
  if (t.compare(0, 4, "Out[") != 0) return s;
  std::size_t i = 4;
  while (i < t.size() && is_digit(t[i])) ++i;
  if (i == 4 || i >= t.size() || t[i] != ']') return s;
  ++i;
  // "Out[3]//N=": Mathematica names the function a result was passed through.
  if (t.compare(i, 2, "//") == 0) {
    i += 2;
    while (i < t.size() && is_letter(t[i])) ++i;
  }
  while (i < t.size() && t[i] == ' ') ++i;
  if (i >= t.size() || (t[i] != '=' && t[i] != ':')) return s;
  return t.substr(i + 1);
}

namespace {
bool name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// Whether `s` has a name, outside its numbers, that `takes` takes.
bool names_symbol(const std::string& s, const std::function<bool(const std::string&)>& takes) {
  for (std::size_t i = 0; i < s.size();) {
    if (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.') {
      i = std::max(number_end(s, i), i + 1);
    } else if (name_char(s[i])) {
      std::size_t j = i;
      while (j < s.size() && name_char(s[j])) ++j;
      if (takes(s.substr(i, j - i))) return true;
      i = j;
    } else {
      ++i;
    }
  }
  return false;
}
}  // namespace

// Whether a '/' at `at` divides by a number ("15 deg/2"), not by a unit ("10 deg/s").
bool divides_by_number(const std::string& s, std::size_t at) {
  if (at >= s.size() || s[at] != '/') return false;
  std::size_t k = at + 1;
  while (k < s.size() && s[k] == ' ') ++k;
  return k < s.size() &&
         (std::isdigit(static_cast<unsigned char>(s[k])) || s[k] == '.' || s[k] == '(');
}

// Whether `s` is arithmetic on angles in degrees: two numbers in degrees or more joined by a '+'
// or '-' ("15 deg - 7.63 deg"), or one divided by a number ("15 deg/2"); and no list or vector
// (no comma, semicolon or square or curly bracket: "[15 deg -30 deg 45 deg]" is three entries).
bool degrees_joined(const std::string& s) {
  if (s.find_first_of(",;[]{}\n") != std::string::npos) return false;
  std::size_t count = 0, first_end = std::string::npos;
  for (std::size_t at = s.find("deg"); at != std::string::npos; at = s.find("deg", at + 3)) {
    std::size_t k = at;
    while (k > 0 && s[k - 1] == ' ') --k;
    if (k == 0 || !std::isdigit(static_cast<unsigned char>(s[k - 1]))) continue;
    std::size_t after = at + 3;
    while (after < s.size() && s[after] == ' ') ++after;
    if (divides_by_number(s, after)) return true;
    if (count++ == 0) first_end = at + 3;
  }
  return count >= 2 && s.find_first_of("+-", first_end) != std::string::npos;
}

std::size_t number_end(const std::string& s, std::size_t at) {
  std::size_t k = at;
  while (k < s.size() && (std::isdigit(static_cast<unsigned char>(s[k])) || s[k] == '.')) ++k;
  if (k == at) return at;
  if (k < s.size() && (s[k] == 'e' || s[k] == 'E')) {  // an exponent, if digits follow
    std::size_t e = k + 1;
    if (e < s.size() && (s[e] == '+' || s[e] == '-')) ++e;
    if (e < s.size() && std::isdigit(static_cast<unsigned char>(s[e]))) {
      while (e < s.size() && std::isdigit(static_cast<unsigned char>(s[e]))) ++e;
      k = e;
    }
  }
  return k;
}

std::string degrees_in_expression(const std::string& ascii,
                                  const std::function<bool(const std::string&)>& in_expression) {
  if (ascii.find("deg") == std::string::npos ||
      !(names_symbol(ascii, in_expression) || degrees_joined(ascii)))
    return ascii;
  std::string out;
  for (std::size_t i = 0; i < ascii.size();) {
    const bool starts_number =
        (std::isdigit(static_cast<unsigned char>(ascii[i])) || ascii[i] == '.') &&
        (i == 0 || !name_char(ascii[i - 1]));
    const std::size_t end = starts_number ? number_end(ascii, i) : i;
    if (end == i) {
      // A name whole, so that its digits are no number ("x2 deg").
      std::size_t j = i + 1;
      if (name_char(ascii[i]))
        while (j < ascii.size() && name_char(ascii[j])) ++j;
      out += ascii.substr(i, j - i);
      i = j;
      continue;
    }
    std::size_t k = end;
    while (k < ascii.size() && ascii[k] == ' ') ++k;
    const bool degrees =
        ascii.compare(k, 3, "deg") == 0 && (k + 3 == ascii.size() || !name_char(ascii[k + 3]));
    std::size_t after = k + 3;
    while (degrees && after < ascii.size() && ascii[after] == ' ') ++after;
    // "10 deg/s", "deg^2": the degrees of a unit; "15 deg/2" halves an angle.
    const bool bound =
        degrees && after < ascii.size() &&
        ((ascii[after] == '/' && !divides_by_number(ascii, after)) || ascii[after] == '^');
    if (degrees && !bound) {
      // "sin 15 deg": the call's bracket against its name, as "sin(" is read.
      std::size_t name_end = out.size();
      while (name_end > 0 && out[name_end - 1] == ' ') --name_end;
      std::size_t name_start = name_end;
      while (name_start > 0 && name_char(out[name_start - 1])) --name_start;
      if (name_end < out.size() && name_start < name_end &&
          sym::is_function_name(out.substr(name_start, name_end - name_start)))
        out.erase(name_end);
      out += "(" + ascii.substr(i, end - i) + "*pi/180)";
      i = k + 3;
    } else {
      out += ascii.substr(i, end - i);
      i = end;
    }
  }
  return out;
}

std::string elliptic_integral_named(const std::string& ascii,
                                    const std::function<bool(const std::string&)>& is_symbol) {
  if (ascii.find("K") == std::string::npos || is_symbol("K")) return ascii;
  std::string out;
  for (std::size_t i = 0; i < ascii.size(); ++i) {
    // A K that ends no longer name ("4K" is a number's factor, "MK" a name), before a bracket.
    bool alone = ascii[i] == 'K' && (i == 0 || !name_char(ascii[i - 1]) ||
                                     std::isdigit(static_cast<unsigned char>(ascii[i - 1])));
    if (alone) {
      std::size_t open = i + 1;
      while (open < ascii.size() && ascii[open] == ' ') ++open;
      alone = open < ascii.size() && ascii[open] == '(';
    }
    if (!alone) {
      out += ascii[i];
      continue;
    }
    // "4K(k)", "4 K(k)", "(..)K(k)": the factor before it multiplies it.
    const std::size_t before = out.find_last_not_of(' ');
    if (before != std::string::npos && (std::isdigit(static_cast<unsigned char>(out[before])) ||
                                        out[before] == '.' || out[before] == ')'))
      out = out.substr(0, before + 1) + '*';
    out += "EllipticK";
  }
  return out;
}

std::string days_written_d(const std::string& ascii,
                           const std::function<bool(const std::string&)>& is_symbol) {
  if (ascii.find('d') == std::string::npos || is_symbol("d")) return ascii;
  const auto is_day = [&](std::size_t i) {
    // Alone after it: the end, a space, a list's or a bracket's end; not a name's next letter,
    // a call's bracket or a derivative's "d/dt".
    const std::size_t after = i + 1;
    if (after < ascii.size() &&
        (name_char(ascii[after]) || ascii[after] == '(' || ascii[after] == '/'))
      return false;
    // Before it (spaces apart or not): a number ("303.6", "3.036e2") or a bracket's end.
    std::size_t p = i;
    while (p > 0 && ascii[p - 1] == ' ') --p;
    if (p == 0) return false;
    if (ascii[p - 1] == ')') return true;
    if (p == i && !std::isdigit(static_cast<unsigned char>(ascii[p - 1]))) return false;
    std::size_t start = p;
    while (start > 0 && (name_char(ascii[start - 1]) || ascii[start - 1] == '.')) --start;
    return std::isdigit(static_cast<unsigned char>(ascii[start])) || ascii[start] == '.';
  };
  // One pass, so that a text of many d's is read in linear time.
  std::string out;
  for (std::size_t i = 0; i < ascii.size(); ++i)
    out += ascii[i] == 'd' && is_day(i) ? std::string("day") : std::string(1, ascii[i]);
  return out;
}

}  // namespace wobble::check
