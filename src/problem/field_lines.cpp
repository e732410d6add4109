#include "problem/field_lines.hpp"

#include <optional>

#include "core/work_budget.hpp"

namespace wobble {

namespace {
// The line of `field` or, for an element of an array held as one field, of the array.
std::optional<int> line_of(const Problem& problem, std::string field) {
  while (true) {
    if (const auto it = problem.field_lines.find(field); it != problem.field_lines.end())
      return it->second;
    if (field.empty() || field.back() != ']') return std::nullopt;
    const auto open = field.rfind('[');
    if (open == std::string::npos || open == 0) return std::nullopt;
    field.erase(open);
  }
}
}  // namespace

std::string placed_in_file(const Problem& problem, const std::string& message) {
  if (problem.from_catalog || problem.field_lines.empty()) return message;
  // "FILE: body: ..." (a solver's message that names the file) gains the line as well.
  const std::string file = problem.file.string();
  const bool named = message.compare(0, file.size() + 2, file + ": ") == 0;
  const std::string rest = named ? message.substr(file.size() + 2) : message;
  // The field, then ':' or a remark in brackets: "...mistakes[0].value (at the problem's
  // defaults): expression is not real".
  const auto end =
      rest.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.[]");
  if (end == 0 || end == std::string::npos) return message;
  if (rest.compare(end, 2, ": ") != 0 && rest.compare(end, 2, " (") != 0) return message;
  const auto line = line_of(problem, rest.substr(0, end));
  if (!line) return message;
  return file + ":" + std::to_string(*line) + ": " + rest;
}

std::string field_in_file(const Problem& problem, const std::string& field) {
  const auto line = line_of(problem, field);
  return problem.file.string() + (line ? ":" + std::to_string(*line) : "") + ": " + field;
}

void rethrow_placed_in_file(const Problem& problem) {
  try {
    throw;
  } catch (const WorkLimitReached&) {
    throw;
  } catch (const InputError& e) {
    std::string placed = placed_in_file(problem, e.what());
    if (placed == e.what()) throw;
    throw InputError(std::move(placed));
  }
}

}  // namespace wobble
