#include "web/problem_view.hpp"

#include <nlohmann/json.hpp>

namespace wobble::web {

namespace {
using nlohmann::json;

const char* shape_name(Value::Shape s) {
  switch (s) {
    case Value::Shape::scalar:
      return "scalar";
    case Value::Shape::vector:
      return "vector";
    case Value::Shape::matrix:
      return "matrix";
  }
  return "scalar";
}

const PartSpec* spec_of(const Problem& problem, const std::string& id) {
  for (const auto& p : problem.parts) {
    if (p.id == id) return &p;
  }
  return nullptr;
}
}  // namespace

std::string student_view_json(const Problem& problem, const Key& key,
                              std::optional<long> variant) {
  json parameters = json::array();
  for (const auto& p : key.parameters) {
    parameters.push_back({{"name", p.name},
                          {"latex", p.latex},
                          {"value", format_number(p.value)},
                          {"unit", p.unit},
                          {"description", p.description}});
  }
  json parts = json::array();
  for (const auto& part : key.parts) {
    json answers = json::array();
    for (const auto& a : part.answers) {
      answers.push_back({{"name", a.name},
                         {"unit", a.unit},
                         {"kind", kind_name(a.kind)},
                         {"frame", frame_name(a.frame)},
                         {"shape", shape_name(a.value.shape)},
                         {"rows", a.value.rows},
                         {"cols", a.value.cols}});
    }
    const PartSpec* spec = spec_of(problem, part.id);
    parts.push_back({{"id", part.id},
                     {"question", part.question},
                     {"answers", answers},
                     {"absent", part.absent},
                     {"has_hint", spec != nullptr && !spec->hint.empty()}});
  }
  json view = {{"id", problem.id},     {"title", problem.title},
               {"statement", problem.statement}, {"notes", key.notes},
               {"parameters", parameters}, {"parts", parts}};
  view["variant"] = variant ? json(*variant) : json(nullptr);
  return view.dump();
}

std::string problem_list_json(const std::vector<Problem>& problems) {
  json list = json::array();
  for (const auto& p : problems) list.push_back({{"id", p.id}, {"title", p.title}});
  return list.dump();
}

}  // namespace wobble::web
