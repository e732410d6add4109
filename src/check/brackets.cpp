#include "check/brackets.hpp"

#include <cctype>

#include "core/characters.hpp"

namespace wobble::check {

bool opens(char c) {
  return c == '[' || c == '(' || c == '{';
}
bool closes(char c) {
  return c == ']' || c == ')' || c == '}';
}

bool is_operator(char c) {
  return c == '+' || c == '-' || c == '*' || c == '/' || c == '^';
}

std::vector<std::string> top_level(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  int depth = 0;
  for (const char c : s) {
    if (opens(c)) ++depth;
    if (closes(c)) --depth;
    const bool split =
        depth == 0 && (sep == ' ' ? std::isspace(static_cast<unsigned char>(c)) != 0 : c == sep);
    if (split) {
      if (sep != ' ' || !trim(cur).empty()) out.push_back(trim(cur));
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (sep != ' ' || !trim(cur).empty()) out.push_back(trim(cur));
  return out;
}

bool list_left_open(const std::string& text) {
  std::string open;
  for (const char c : text) {
    if (opens(c)) open += c;
    if (closes(c) && !open.empty()) open.pop_back();
  }
  return open.find_first_of("[{") != std::string::npos;
}

std::size_t matching(const std::string& s, std::size_t open) {
  int depth = 0;
  for (std::size_t i = open; i < s.size(); ++i) {
    if (opens(s[i])) ++depth;
    if (closes(s[i]) && --depth == 0) return i;
  }
  return std::string::npos;
}

std::vector<std::string> space_separated_entries(const std::string& s) {
  std::vector<std::string> entries;
  for (const auto& t : top_level(s, ' ')) {
    const bool joins =
        !entries.empty() &&
        ((t.size() == 1 && is_operator(t[0])) || t[0] == '*' || t[0] == '/' || t[0] == '^' ||
         t[0] == ')' || is_operator(entries.back().back()) || entries.back().back() == '(');
    if (joins) {
      entries.back() += " " + t;
    } else {
      entries.push_back(t);
    }
  }
  return entries;
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t k = 0; k < items.size(); ++k) out += (k ? ", " : "") + items[k];
  return out;
}

bool wrapped(const std::string& s, char open) {
  return s.size() >= 2 && s.front() == open && matching(s, 0) == s.size() - 1;
}

ListItems list_items(const std::string& s) {
  const std::string t = trim(s);
  ListItems list{top_level(t, ','), false};
  if (list.items.size() == 1 && (wrapped(t, '[') || wrapped(t, '(') || wrapped(t, '{')))
    list = {top_level(t.substr(1, t.size() - 2), ','), true};
  return list;
}

}  // namespace wobble::check
