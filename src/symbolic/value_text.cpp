#include "symbolic/value_text.hpp"

#include <algorithm>

#include "core/characters.hpp"

namespace wobble::sym {

namespace {

// Splits "[a, b, (c, d)]" into its top-level items; text must start with '[' and end with ']'.
std::vector<std::string> items(const std::string& text, const std::string& field) {
  std::vector<std::string> out;
  int depth = 0;
  std::string current;
  for (std::size_t i = 1; i + 1 < text.size(); ++i) {
    const char c = text[i];
    if (c == '[' || c == '(') ++depth;
    if (c == ']' || c == ')') --depth;
    if (depth < 0) throw ExpressionError(field + ": unbalanced brackets in \"" + text + "\"");
    if (c == ',' && depth == 0) {
      out.push_back(trim(current));
      current.clear();
    } else {
      current += c;
    }
  }
  if (depth != 0) throw ExpressionError(field + ": unbalanced brackets in \"" + text + "\"");
  out.push_back(trim(current));
  return out;
}

bool bracketed(const std::string& s) {
  return s.size() >= 2 && s.front() == '[' && s.back() == ']';
}
}  // namespace

ValueText parse_value_text(const std::string& raw, const SymbolTable& table,
                           const std::string& field) {
  // A 3x3 matrix of long entries is far below these; a vector of a million components, or a
  // megabyte of text, is refused before anything is parsed.
  constexpr std::size_t kMaxEntries = 100;
  if (raw.size() > 9 * kMaxExpressionLength) {
    throw ExpressionError(field + ": " + std::to_string(raw.size()) +
                          " characters; a value may have at most " +
                          std::to_string(9 * kMaxExpressionLength));
  }
  if (static_cast<std::size_t>(std::count(raw.begin(), raw.end(), ',')) >= kMaxEntries) {
    throw ExpressionError(field + ": more than " + std::to_string(kMaxEntries) +
                          " entries; a vector or matrix here has at most 9");
  }
  const std::string text = trim(raw);
  ValueText out;
  if (!bracketed(text)) {
    out.entries.push_back(table.parse(text, field));
    return out;
  }
  const auto rows = items(text, field);
  if (!rows.empty() && bracketed(rows[0])) {
    out.is_matrix = true;
    out.rows = rows.size();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      if (!bracketed(rows[i]))
        throw ExpressionError(field + ": row " + std::to_string(i) + " is not a [list]");
      const auto row = items(rows[i], field);
      if (i == 0) out.cols = row.size();
      if (row.size() != out.cols) throw ExpressionError(field + ": rows of different lengths");
      for (std::size_t j = 0; j < row.size(); ++j) {
        if (bracketed(row[j])) throw ExpressionError(field + ": nested deeper than a matrix");
        out.entries.push_back(
            table.parse(row[j], field + "[" + std::to_string(i) + "][" + std::to_string(j) + "]"));
      }
    }
    return out;
  }
  out.is_vector = true;
  out.rows = rows.size();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (bracketed(rows[i])) throw ExpressionError(field + ": mixed rows and numbers");
    out.entries.push_back(table.parse(rows[i], field + "[" + std::to_string(i) + "]"));
  }
  return out;
}

}  // namespace wobble::sym
