#include "check/names_run_together.hpp"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "core/characters.hpp"
#include "symbolic/expression_guard.hpp"
#include "symbolic/unicode_notation.hpp"
#include "symbolic/units.hpp"

namespace wobble::check {

namespace {
bool word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

// A name that means something of its own, and so is never taken apart. A unit's letters only
// without digits: the unit reader takes "Mm1m2" for megametres times square metres, where the
// three-atom molecule's M, m1 and m2 run together.
bool means_itself(const std::string& name, const sym::SymbolTable& table) {
  const bool digits = std::any_of(
      name.begin(), name.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
  return table.contains(name) || (!digits && is_unit(name)) || sym::is_function_name(name) ||
         name == "pi" || name == "Pi" || sym::greek_letters().count(ascii_lower(name)) != 0;
}

// Names longer than any a student runs together are left whole (nor searched).
constexpr std::size_t kLongestSplit = 64;

// The one way `name` splits into the table's names, as "m*R"; "" where there is none or more
// than one. ways[i] counts the splits of name[i..] (stopping at two) and first[i] is the length
// of the first name of one of them: a pass from the end, linear in the places however the names
// overlap.
std::string only_split(const std::string& name, const sym::SymbolTable& table) {
  const std::size_t n = name.size();
  std::vector<int> ways(n + 1, 0);
  std::vector<std::size_t> first(n + 1, 0);
  ways[n] = 1;
  for (std::size_t i = n; i-- > 0;) {
    for (std::size_t length = 1; i + length <= n && ways[i] < 2; ++length) {
      if (ways[i + length] == 0 || !table.contains(name.substr(i, length))) continue;
      ways[i] = std::min(2, ways[i] + ways[i + length]);
      first[i] = length;
    }
  }
  if (ways[0] != 1) return "";
  std::string product;
  for (std::size_t i = 0; i < n; i += first[i])
    product += (product.empty() ? "" : "*") + name.substr(i, first[i]);
  return product;
}

// The one way `name` splits into the table's names, a function's name and at most one name
// after it, its argument ("phidotcos" -> "phidot cos", "phidotcostheta" -> "phidot cos theta",
// as "φ̇cosθ" reads in ASCII): "" where there is none. The function set apart by spaces, so
// that its argument may follow without brackets; with no argument in the run, only where one
// follows it (`argument_follows`).
std::string only_split_around_call(const std::string& name, const sym::SymbolTable& table,
                                   bool argument_follows) {
  std::string found;
  for (std::size_t at = 0; at < name.size(); ++at) {
    for (std::size_t length = 2; at + length <= name.size(); ++length) {
      const std::string function = name.substr(at, length), tail = name.substr(at + length);
      if (!sym::is_function_name(function)) continue;
      if (tail.empty() ? !argument_follows : !table.contains(tail)) continue;
      const std::string head = name.substr(0, at);
      const std::string product =
          head.empty() || table.contains(head) ? head : only_split(head, table);
      if (!head.empty() && product.empty()) continue;
      if (!found.empty()) return "";  // two ways
      found = (product.empty() ? "" : product + " ") + function + (tail.empty() ? "" : " " + tail);
    }
  }
  return found;
}
}  // namespace

std::string names_apart(const std::string& text, const sym::SymbolTable& table) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (!word_char(text[i])) {
      out += text[i++];
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && word_char(text[end])) ++end;
    // A number's digits before the letters ("2mR"): kept as they are; one with an exponent
    // ("2e5", "1.5E3") is a number whole.
    std::size_t letters = i;
    while (letters < end &&
           (std::isdigit(static_cast<unsigned char>(text[letters])) || text[letters] == '.'))
      ++letters;
    const bool exponent = letters > i && letters + 1 < end &&
                          (text[letters] == 'e' || text[letters] == 'E') &&
                          std::isdigit(static_cast<unsigned char>(text[letters + 1]));
    const std::string name = text.substr(letters, end - letters);
    out += text.substr(i, letters - i);
    const bool whole = exponent || name.empty() || name.size() > kLongestSplit ||
                       name.find('_') != std::string::npos ||
                       std::isdigit(static_cast<unsigned char>(name[0])) ||
                       means_itself(name, table);
    // Before a call or an argument ("phidotcos(theta)", "phidotcos theta"), a function may end
    // the run.
    std::size_t next = end;
    while (next < text.size() && text[next] == ' ') ++next;
    const bool argument_follows =
        next < text.size() && (text[next] == '(' || word_char(text[next]));
    std::string product = whole ? "" : only_split(name, table);
    if (!whole && product.find('*') == std::string::npos)
      product = only_split_around_call(name, table, argument_follows);
    out += product.find_first_of("* ") != std::string::npos ? product : name;
    i = end;
  }
  return out;
}

}  // namespace wobble::check
