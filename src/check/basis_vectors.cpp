#include "check/basis_vectors.hpp"

#include <array>
#include <cctype>
#include <optional>
#include <string_view>
#include <utility>

#include "symbolic/units.hpp"

namespace wobble::check {

namespace {
// The marks that make a letter a unit vector in LaTeX, and the bold that names one (i, j, k and
// e are unit vectors in bold; x, y and z need a hat: a bold x is a position).
// An arrow, like bold, marks a vector: \vec{e}_1 is a unit vector, \vec{x} a position.
constexpr std::array<std::string_view, 2> kHats{"widehat", "hat"};
constexpr std::array<std::string_view, 5> kBolds{"boldsymbol", "mathbf", "bm", "mathbfit", "vec"};
constexpr std::array<std::string_view, 3> kSubscripts{"₁", "₂", "₃"};

// Each space unit vector as the answer reader knows it, for x, y, z and i, j, k.
std::string hatted(char letter) {
  switch (letter) {
    case 'x':
      return "x\u0302";
    case 'y':
      return "ŷ";
    case 'z':
      return "ẑ";
    case 'i':
      return "î";
    case 'j':
      return "ĵ";
    default:
      return "k\u0302";
  }
}

bool is_name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

struct Scan {
  const std::string& s;
  std::size_t i;

  bool at(std::string_view text) const { return s.compare(i, text.size(), text) == 0; }
  void spaces() {
    while (i < s.size() && s[i] == ' ') ++i;
  }
  // "\hat", "\mathbf" at i (not the start of a longer command): its name, and i past it.
  std::optional<std::string_view> command(const std::string_view* names, std::size_t count) {
    for (std::size_t k = 0; k < count; ++k) {
      const std::string_view n = names[k];
      const std::size_t end = i + 1 + n.size();
      if (at("\\") && s.compare(i + 1, n.size(), n) == 0 &&
          (end >= s.size() || !std::isalpha(static_cast<unsigned char>(s[end])))) {
        i = end;
        return n;
      }
    }
    return std::nullopt;
  }
  // A subscript 1, 2 or 3: "_1", "_{1}", "₁", or a digit right after the letter ("e1").
  std::optional<int> subscript(bool bare_digit) {
    const std::size_t start = i;
    if (at("_")) {
      ++i;
      spaces();
      const bool braced = at("{");
      if (braced) ++i;
      spaces();
      if (i < s.size() && s[i] >= '1' && s[i] <= '3') {
        const int n = s[i++] - '1';
        spaces();
        if (!braced || at("}")) {
          if (braced) ++i;
          return n;
        }
      }
    } else {
      for (int n = 0; n < 3; ++n) {
        if (at(kSubscripts[static_cast<std::size_t>(n)])) {
          i += kSubscripts[static_cast<std::size_t>(n)].size();
          return n;
        }
      }
      if (bare_digit && i < s.size() && s[i] >= '1' && s[i] <= '3') return s[i++] - '1';
    }
    i = start;
    return std::nullopt;
  }
};

// A unit vector written at `start`, its end and its spelling; nullopt if none starts there.
std::optional<std::pair<std::size_t, std::string>> unit_vector_at(const std::string& s,
                                                                  std::size_t start) {
  Scan p{s, start};
  bool hat = false, bold = false;
  int open = 0;
  for (int marks = 0; marks < 3; ++marks) {  // "\hat{\mathbf{e}}": marks nest a few deep
    if (p.command(kHats.data(), kHats.size())) {
      hat = true;
    } else if (p.command(kBolds.data(), kBolds.size())) {
      bold = true;
    } else {
      break;
    }
    p.spaces();
    if (p.at("{")) {
      ++p.i;
      ++open;
      p.spaces();
    }
  }
  char letter = 0;
  if (p.at("\\imath") || p.at("\\jmath")) {
    letter = s[p.i + 1] == 'i' ? 'i' : 'j';
    p.i += 6;
  } else if (p.at("ê") || p.at("e\u0302")) {
    letter = 'e';
    hat = true;
    p.i += p.at("ê") ? std::string_view("ê").size() : std::string_view("e\u0302").size();
  } else if (p.i < s.size() && std::string_view("xyzijke").find(s[p.i]) != std::string::npos) {
    letter = s[p.i++];
  } else {
    return std::nullopt;
  }
  const bool wrapped = hat || bold;
  std::optional<int> axis = letter == 'e' ? p.subscript(!wrapped) : std::nullopt;
  for (; open > 0; --open) {
    p.spaces();
    if (!p.at("}")) return std::nullopt;
    ++p.i;
  }
  if (letter == 'e' && !axis) axis = p.subscript(false);
  // A prime makes it the primed basis's ("e_2'", "e₂′", "e_2^\prime", "e_{2}^{\prime}").
  bool primed = false;
  for (const std::string_view prime : {"'", "′", "’", "\u02b9", "^\\prime", "^{\\prime}", "^{'}"}) {
    if (!primed && p.at(prime)) {
      primed = true;
      p.i += prime.size();
    }
  }
  // What follows a unit vector ends its name.
  if (p.i < s.size() && (is_name_char(s[p.i]) || s[p.i] == '^')) return std::nullopt;
  if (letter == 'e') {
    if (!axis) return std::nullopt;
    return std::make_pair(p.i, std::string(kBodyUnitVectors[*axis + (primed ? 3 : 0)]));
  }
  if (primed) return std::nullopt;  // "x̂′" is no basis of any problem
  // x, y, z need a hat; i, j, k without one or bold are the answer reader's own to judge.
  const bool ijk = letter == 'i' || letter == 'j' || letter == 'k';
  if (!(hat || (bold && ijk))) return std::nullopt;
  return std::make_pair(p.i, hatted(letter));
}
}  // namespace

// The end of a unit vector spelt in ASCII at typed[i], as plain text and chat write one, and
// its letter: "ihat", "i_hat", "i-hat", "x^" (before a sign, a bracket's end, a comma, a unit or
// the end: no power), "e_x"; nullopt if none is there. Only where the letter is no symbol of the
// problem: then none of these can be an expression in it.
std::optional<std::pair<std::size_t, char>> ascii_unit_vector_at(const std::string& typed,
                                                                 std::size_t i,
                                                                 const sym::SymbolTable& table) {
  const auto ends_name = [&](std::size_t end) {
    return end >= typed.size() || !is_name_char(typed[end]);
  };
  constexpr std::string_view kLetters = "ijkxyz";
  const char c = typed[i];
  if (c == 'e' && typed.compare(i, 2, "e_") == 0 && i + 2 < typed.size()) {
    const char l = typed[i + 2];
    if ((l == 'x' || l == 'y' || l == 'z') && ends_name(i + 3) &&
        !table.contains(typed.substr(i, 3)))
      return std::make_pair(i + 3, l);
    return std::nullopt;
  }
  if (kLetters.find(c) == std::string_view::npos || table.contains(std::string(1, c)))
    return std::nullopt;
  for (const std::string_view hat : {"_hat", "-hat", "hat"}) {
    const std::size_t end = i + 1 + hat.size();
    if (typed.compare(i + 1, hat.size(), hat) == 0 && ends_name(end)) return std::make_pair(end, c);
  }
  if (i + 1 < typed.size() && typed[i + 1] == '^') {
    std::size_t k = i + 2;
    while (k < typed.size() && typed[k] == ' ') ++k;
    const std::string_view after = "+-),]";
    if (k >= typed.size() || after.find(typed[k]) != std::string_view::npos ||
        is_unit(typed.substr(k)))
      return std::make_pair(i + 2, c);
  }
  return std::nullopt;
}

std::string basis_vectors_spelled(const std::string& typed, const sym::SymbolTable& table) {
  // A problem with its own e1, e2 or e3 keeps them: there "e1" is its symbol.
  const bool own_e = table.contains("e1") || table.contains("e2") || table.contains("e3");
  std::string out;
  std::size_t done = 0;
  for (std::size_t i = 0; i < typed.size();) {
    const char c = typed[i];
    const bool command = c == '\\';
    // A name before it: "ae1", "\beta" are no unit vectors. Nor is "2e1", a number (20); but
    // "0.5e₁" and "0.5e_1" are a component glued to its unit vector.
    const bool after_number =
        i > 0 && (std::isdigit(static_cast<unsigned char>(typed[i - 1])) || typed[i - 1] == '.');
    const bool exponent =
        after_number && c == 'e' && i + 1 < typed.size() &&
        (std::isdigit(static_cast<unsigned char>(typed[i + 1])) || typed[i + 1] == '-' ||
         typed[i + 1] == '+');
    const bool after_name = i > 0 && !after_number &&
                            (is_name_char(typed[i - 1]) || typed[i - 1] == '\\');
    if (!after_name && !exponent) {
      if (const auto ascii = ascii_unit_vector_at(typed, i, table)) {
        out += typed.substr(done, i - done) + hatted(ascii->second);
        i = done = ascii->first;
        continue;
      }
    }
    const bool e_hat = typed.compare(i, std::string_view("ê").size(), "ê") == 0;
    if ((command || c == 'e' || e_hat) && !after_name && !exponent) {
      if (const auto found = unit_vector_at(typed, i)) {
        const bool bare_e = !command && own_e;
        if (!bare_e) {
          out += typed.substr(done, i - done) + found->second;
          i = done = found->first;
          continue;
        }
      }
    }
    ++i;
  }
  return done == 0 ? typed : out + typed.substr(done);
}

}  // namespace wobble::check
