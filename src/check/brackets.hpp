#pragma once
/// @file
/// Brackets and entries in an answer's text: (), [] and {} all nest alike, since an answer may
/// write a vector in any of them and the reader rewrites them to one kind. ASCII text; no bracket
/// is checked for its kind against its partner (the expression reader does that).
#include <cstddef>
#include <string>
#include <vector>

namespace wobble::check {

bool opens(char c);
bool closes(char c);
bool is_operator(char c);  ///< + - * / ^

/// The pieces of `s` between the `sep` characters outside brackets, each trimmed (any whitespace
/// when sep is ' ', where empty pieces are dropped).
std::vector<std::string> top_level(const std::string& s, char sep);

/// The index of the bracket that closes the one at `open`, or npos.
std::size_t matching(const std::string& s, std::size_t open);

/// "0.7 0 -0.7" -> {"0.7", "0", "-0.7"}, but "1 - 2" and "2 * m" stay one entry: an operator
/// standing alone, ending a token or starting one (other than a sign) joins its neighbours.
std::vector<std::string> space_separated_entries(const std::string& s);

/// "a, b, c": entries joined as the reading form lists them.
std::string joined(const std::vector<std::string>& items);

/// Whether `text` leaves a list's bracket open, '[' or '{': a matrix pasted over lines, as NumPy
/// prints one, with rows to come. A '(' left open is a slip more often ("sqrt(2"), and is not.
bool list_left_open(const std::string& text);

/// The lines one answer so continued may take, in the worksheet and in a submission: a 3x3
/// matrix as NumPy prints it is three, as MATLAB shows one with its name and blank lines about
/// seven; the limit keeps a bracket never closed from taking every line after it.
constexpr int kMostAnswerLines = 12;

/// Whether s is one bracket group, opened by `open`: "[a, b]" but not "[a] [b]".
bool wrapped(const std::string& s, char open);

/// A list's items: `s` split at its top-level commas, or, where one bracket ((), [] or {})
/// holds it all, what is inside split so. "[a, b], [c, d]" and "[x + z, y]" are both lists of
/// two; `bracketed` says whether one bracket held them.
struct ListItems {
  std::vector<std::string> items;
  bool bracketed = false;
};
ListItems list_items(const std::string& s);

}  // namespace wobble::check
