#include "web/problem_view.hpp"

#include <nlohmann/json.hpp>

#include "web/motion.hpp"

namespace wobble::web {

namespace {
using nlohmann::json;
}  // namespace

std::string student_view_json(const Problem& problem, const Key& key, std::optional<long> variant,
                              const std::vector<std::string>& assignments, bool with_hints) {
  json parameters = json::array();
  for (const auto& p : key.parameters) {
    json row = {{"name", p.name},
                {"latex", p.latex},
                {"value", format_number(p.value)},
                {"unit", p.unit},
                {"description", p.description}};
    for (const auto& a : assignments) {
      const auto eq = a.find('=');
      const std::string drawn = a.substr(eq + 1);
      if (a.substr(0, eq) != p.name || drawn.size() < 4 ||
          drawn.compare(drawn.size() - 3, 3, "deg") != 0) {
        continue;
      }
      // An angle drawn in whole degrees: as the handout shows it.
      row["shown"] = drawn.substr(0, drawn.size() - 3) + "° = " + format_number(p.value) + " rad";
    }
    parameters.push_back(row);
  }
  json parts = json::array();
  for (const auto& part : key.parts) {
    json answers = json::array();
    for (const auto& a : part.answers) {
      answers.push_back({{"name", a.name},
                         {"unit", a.unit},
                         {"asked_unit", asked_unit(a)},
                         {"form", answer_form(a)},
                         {"kind", kind_name(a.kind)},
                         {"frame", frame_name(a.frame)},
                         {"shape", shape_name(a.value.shape)},
                         {"entries", entry_names(a)},
                         {"rows", a.value.rows},
                         {"cols", a.value.cols}});
    }
    const std::string& hint = problem.hint(part.id);
    parts.push_back({{"id", part.id},
                     {"question", part.question},
                     {"answers", answers},
                     // Names only: why one is absent is a step of the key, and may hold
                     // its numbers (a slow top's reason gives ω3, part c's answer).
                     {"absent", part.absent},
                     {"absent_units", part.absent_unit},
                     {"has_hint", !hint.empty()}});
    if (with_hints && !hint.empty()) parts.back()["hint"] = hint;
  }
  json view = {{"id", problem.id},     {"title", problem.title},
               {"statement", problem.statement}, {"notes", key.notes},
               {"parameters", parameters}, {"parts", parts},
               {"has_motion", has_motion(problem)}};
  view["variant"] = variant ? json(*variant) : json(nullptr);
  return view.dump();
}

std::string problem_list_json(const std::vector<Problem>& problems) {
  json list = json::array();
  for (const auto& p : problems) list.push_back({{"id", p.id}, {"title", p.title}});
  return list.dump();
}

}  // namespace wobble::web
