#include "solvers/key.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

namespace wobble {

double Value::scale() const {
  double s = 0.0;
  for (double x : data) s = std::max(s, std::abs(x));
  return s;
}

namespace {
// The part asked for: by its id, or without one the part that asks for the answer `name`
// (among its answers or those absent at these values). nullptr if there is none.
const PartKey* find_part(const std::vector<PartKey>& parts, const std::string& part_id,
                         const std::string& name) {
  for (const auto& p : parts) {
    const bool holds = std::any_of(p.answers.begin(), p.answers.end(),
                                   [&](const Answer& a) { return a.name == name; }) ||
                       std::find(p.absent.begin(), p.absent.end(), name) != p.absent.end();
    if (part_id.empty() ? holds : p.id == part_id) return &p;
  }
  return nullptr;
}
}  // namespace

std::string answers_by_part(const Key& key) {
  std::vector<std::string> parts;
  for (const auto& p : key.parts) {
    if (!p.asked_names().empty())
      parts.push_back(fmt::format("({}) {}", p.id, fmt::join(p.asked_names(), ", ")));
  }
  return parts.empty() ? "none" : fmt::format("{}", fmt::join(parts, "; "));
}

bool asks_for(const Key& key, const std::string& name) {
  return std::any_of(key.parts.begin(), key.parts.end(), [&](const PartKey& p) {
    const std::vector<std::string> asked = p.asked_names();
    return std::find(asked.begin(), asked.end(), name) != asked.end();
  });
}

const Answer& find_answer(const Key& key, const std::string& part_id, const std::string& name,
                          const std::string& part_field, const std::string& name_field) {
  if (part_id.empty() && name.empty()) {
    throw InputError(part_field + " or " + name_field +
                     ": neither is given; name the part, the answer, or both (answers: " +
                     answers_by_part(key) + ")");
  }
  // Where the part goes, an answer's name as the key prints it ("check flying-plate I0 ..."). A
  // part's id comes first, should an answer bear the same name.
  if (!part_id.empty() && name.empty() && find_part(key.parts, part_id, name) == nullptr &&
      find_part(key.parts, "", part_id) != nullptr) {
    return find_answer(key, "", part_id, part_field, name_field);
  }
  // What was asked for is echoed at most this long: a message stays one line.
  const auto shown = [](const std::string& s) {
    return s.size() > 40 ? s.substr(0, 40) + "..." : s;
  };
  const PartKey* part = find_part(key.parts, part_id, name);
  if (part == nullptr && part_id.empty()) {
    std::vector<std::string> names;
    for (const auto& p : key.parts) {
      for (const auto& n : p.asked_names()) names.push_back(n);
    }
    throw AnswerNotFound(fmt::format("{}: problem {} has no answer '{}' (answers: {})", name_field,
                                     key.problem, shown(name), fmt::join(names, ", ")));
  }
  if (part == nullptr) {
    // The answers with their parts: the word may have been meant for an answer's name.
    throw AnswerNotFound(
        fmt::format("{}: problem {} has no part or answer '{}' (answers by part: {})", part_field,
                    key.problem, shown(part_id), answers_by_part(key)));
  }
  if (part->answers.empty()) {
    throw AnswerNotFound(fmt::format(
        "{}: part {} of {} has nothing to check at these values ({} do not exist; the key says "
        "why)",
        part_id.empty() ? name_field : part_field, part->id, key.problem,
        fmt::join(part->absent, ", ")));
  }
  for (const auto& a : part->answers) {
    if (a.name == name || (name.empty() && part->answers.size() == 1)) return a;
  }
  const std::string names = fmt::format("{}", fmt::join(part->asked_names(), ", "));
  if (name.empty()) {
    throw AnswerNotFound(
        fmt::format("{}: part {} has several answers; name one ({})", name_field, part->id, names));
  }
  const auto absent = std::find(part->absent.begin(), part->absent.end(), name);
  if (absent != part->absent.end()) {
    const auto i = static_cast<std::size_t>(absent - part->absent.begin());
    throw AnswerNotFound(fmt::format("{}: {}", name_field, part->absent_line(i, true)));
  }
  throw AnswerNotFound(fmt::format("{}: part {} has no answer '{}' (answers: {})", name_field,
                                   part->id, shown(name), names));
}

const char* kind_name(AnswerKind k) {
  switch (k) {
    case AnswerKind::scalar: return "scalar";
    case AnswerKind::angle: return "angle";
    case AnswerKind::rate: return "rate";
    case AnswerKind::vector: return "vector";
    case AnswerKind::matrix: return "matrix";
    case AnswerKind::tensor: return "tensor";
    case AnswerKind::principal_moments: return "principal_moments";
    case AnswerKind::principal_axes: return "principal_axes";
  }
  return "?";
}

const char* frame_name(AnswerFrame f) {
  switch (f) {
    case AnswerFrame::none: return "none";
    case AnswerFrame::body: return "body";
    case AnswerFrame::space: return "space";
    case AnswerFrame::primed: return "primed";
  }
  return "?";
}

const char* sign_name(SignConvention s) {
  switch (s) {
    case SignConvention::none: return "none";
    case SignConvention::sense_of_precession: return "sense_of_precession";
  }
  return "?";
}

std::vector<std::string> entry_names(const Answer& a) {
  if (a.value.shape != Value::Shape::vector || a.kind == AnswerKind::principal_moments) return {};
  if (!a.named_entries.empty()) return a.named_entries;
  if (a.value.data.size() != 3) return {};
  switch (a.frame) {
    case AnswerFrame::body:
      return {"e₁", "e₂", "e₃"};
    case AnswerFrame::primed:
      return {"e₁′", "e₂′", "e₃′"};
    case AnswerFrame::space:
    case AnswerFrame::none:
      break;
  }
  return {"x", "y", "z"};
}

std::string answer_form(const Answer& a) {
  const auto dots = [](std::size_t n, const char* entry) {
    return fmt::format("[{}]", fmt::join(std::vector<std::string>(n, entry), ", "));
  };
  if (a.kind == AnswerKind::principal_moments) return "three moments [.., .., ..], in any order";
  if (a.value.shape == Value::Shape::matrix) return "a matrix " + dots(a.value.rows, "[..]");
  if (a.value.shape != Value::Shape::vector) return "";
  const std::vector<std::string> names = entry_names(a);
  if (names.size() != a.value.data.size()) return "a vector " + dots(a.value.data.size(), "..");
  const std::string list = fmt::format("{}", fmt::join(names, ", "));
  if (a.frame == AnswerFrame::body || a.frame == AnswerFrame::primed)
    return "a vector " + dots(names.size(), "..") + " along " + list;
  return "a vector [" + list + "]";
}

const char* shape_name(Value::Shape s) {
  switch (s) {
    case Value::Shape::scalar: return "scalar";
    case Value::Shape::vector: return "vector";
    case Value::Shape::matrix: return "matrix";
  }
  return "?";
}

std::vector<std::string> PartKey::asked_names() const {
  std::vector<std::string> names;
  for (const auto& a : answers) names.push_back(a.name);
  names.insert(names.end(), absent.begin(), absent.end());
  return names;
}

std::string PartKey::absent_line(std::size_t i, bool name_part) const {
  const std::string why = i < absent_why.size() ? absent_why[i] : "";
  return fmt::format("{}{} does not exist at these values{}", absent.at(i),
                     name_part ? " (part " + id + ")" : "",
                     why.empty() ? "; the key says why" : ": " + why);
}

void append_steps(PartKey& part, const std::vector<Step>& steps) {
  for (const auto& s : steps) {
    bool seen = false;
    for (const auto& have : part.steps)
      seen = seen || (have.text == s.text && have.latex == s.latex);
    if (!seen) part.steps.push_back(s);
  }
}

std::string format_number(double x) {
  if (x == 0.0) return "0";  // also turns -0 into 0
  return fmt::format("{:.10g}", x);
}

std::string number_latex(double x) {
  // "4.440892099e-16" -> "4.440892099 \times 10^{-16}": a page shows no e-notation.
  const std::string n = format_number(x);
  const auto e = n.find('e');
  if (e == std::string::npos) return n;
  std::string exponent = n.substr(e + 1);
  if (!exponent.empty() && exponent[0] == '+') exponent.erase(0, 1);
  while (exponent.size() > 1 && (exponent[0] == '0' || (exponent[0] == '-' && exponent[1] == '0'))) {
    exponent.erase(exponent[0] == '-' ? 1 : 0, 1);
  }
  return n.substr(0, e) + " \\times 10^{" + exponent + "}";
}

std::string value_latex(const Value& v) {
  if (v.shape == Value::Shape::scalar) return number_latex(v.data.at(0));
  std::string s = "\\begin{pmatrix}";
  for (std::size_t i = 0; i < v.rows; ++i) {
    for (std::size_t j = 0; j < v.cols; ++j) s += (j ? " & " : " ") + number_latex(v.at(i, j));
    s += i + 1 < v.rows ? " \\\\" : "";
  }
  return s + " \\end{pmatrix}";
}

}  // namespace wobble
