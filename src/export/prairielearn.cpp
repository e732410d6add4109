#include "export/prairielearn.hpp"

#include <fmt/format.h>

#include <boost/uuid/name_generator_sha1.hpp>
#include <boost/uuid/uuid_io.hpp>
#include <nlohmann/json.hpp>

#include "check/diagnosis.hpp"
#include "check/judge.hpp"
#include "export/html_text.hpp"
#include "export/prairielearn_server_py.hpp"

namespace wobble::exports {

namespace {
using nlohmann::json;

json answer_json(const GradedAnswer& g) {
  const Answer& a = g.answer;
  json mistakes = json::array();
  for (const auto& m : g.mistakes) {
    mistakes.push_back({{"mistake", m.mistake}, {"values", m.values}, {"message", m.message}});
  }
  // The judge's own names of the entries ("entry e₁", "c₁"), for the grader's feedback.
  json entries = json::array();
  if (a.value.data.size() > 1) {
    for (std::size_t i = 0; i < a.value.data.size(); ++i)
      entries.push_back(check::entry_name(a, i));
  }
  return {{"input", input_name(g)},
          {"name", a.name},
          {"part", g.part},
          {"kind", kind_name(a.kind)},
          {"frame", frame_name(a.frame)},
          {"shape", shape_name(a.value.shape)},
          {"rows", a.value.rows},
          {"cols", a.value.cols},
          {"unit", a.unit},
          {"value", a.value.data},
          {"entries", entries},
          {"whole_turns", check::angles_up_to_turns(a)},
          {"rel_tol", g.rel_tol},
          {"zero_scale", g.zero_scale},
          {"eigenspaces", g.eigenspaces},
          {"mistakes", mistakes}};
}

// One input per answer, with its name and unit beside it; the feedback under it after grading.
std::string answer_input(const GradedAnswer& g) {
  const Answer& a = g.answer;
  const std::string name = input_name(g);
  const std::string unit = asked_unit(a).empty() ? "" : unit_html(asked_unit(a));
  std::string html;
  if (a.value.shape == Value::Shape::scalar) {
    html = fmt::format(
        "<pl-number-input answers-name=\"{}\" label=\"<code>{}</code> =\" suffix=\"{}\" "
        "show-help-text=\"false\"></pl-number-input>\n",
        name, html_escape(a.name), unit);
  } else {
    html = fmt::format(
        "<p><code>{}</code>{} =</p>\n<pl-matrix-component-input answers-name=\"{}\" rows=\"{}\" "
        "columns=\"{}\"></pl-matrix-component-input>\n{}",
        html_escape(a.name), a.frame == AnswerFrame::none ? "" : fmt::format(" ({} frame)", frame_name(a.frame)),
        name, a.value.rows, a.value.cols, unit.empty() ? "" : "<p>in " + unit + "</p>\n");
  }
  html += fmt::format(
      "<pl-submission-panel>{{{{#feedback.{0}}}}}<p><code>{1}</code>: {{{{feedback.{0}}}}}</p>"
      "{{{{/feedback.{0}}}}}</pl-submission-panel>\n",
      name, html_escape(a.name));
  return html;
}

// A part's hint, shown as wobble's worksheet and page show it: after the second submission of
// the variant (PrairieLearn counts submissions of the whole question, not of a part).
std::string hint_html(const std::string& part_id, const std::string& hint) {
  if (hint.empty()) return "";
  return fmt::format(
      "<pl-hidden-hints>\n<pl-hint show-after-submission=\"2\" hint-name=\"Hint for ({})\">{}"
      "</pl-hint>\n</pl-hidden-hints>\n",
      part_id, mustache_safe(inline_html(hint, "$", "$")));
}

std::string question_html(const Problem& problem, const VariantSet& set) {
  std::string html = "<pl-question-panel>\n" +
                     mustache_safe(statement_html(problem.statement, "$", "$")) +
                     "<p>Your values (variant {{params.variant}}):</p>\n"
                     "<table class=\"table table-sm w-auto\">\n"
                     "{{#params.values}}<tr><td>${{latex}}$</td><td>{{text}}</td></tr>"
                     "{{/params.values}}\n</table>\n</pl-question-panel>\n";
  const GradedVariant& first = set.variants.front();
  for (const auto& part : first.key.parts) {
    html += fmt::format("<p><strong>({})</strong> {}</p>\n", part.id,
                        mustache_safe(inline_html(part.question, "$", "$")));
    for (const auto& g : first.answers) {
      if (g.part == part.id) html += answer_input(g);
    }
    html += hint_html(part.id, problem.hint(part.id));
  }
  return html;
}
}  // namespace

std::string mustache_safe(const std::string& html) {
  std::string out;
  // A brace written as a brace after one written as a brace: the second of a "{{".
  for (const char c : html)
    out += c == '{' && !out.empty() && out.back() == '{' ? "&#123;" : std::string(1, c);
  return out;
}

std::string input_name(const GradedAnswer& a) { return a.part + "_" + a.answer.name; }

std::string question_uuid(const std::string& problem_id) {
  boost::uuids::name_generator_sha1 generate(boost::uuids::ns::url());
  return boost::uuids::to_string(generate("wobble/problem/" + problem_id));
}

std::string variants_json(const VariantSet& set, const check::Options& options) {
  json variants = json::array();
  for (const auto& v : set.variants) {
    json values = json::array();
    for (const auto& [name, text] : v.values) {
      std::string latex = name;
      for (const auto& p : v.key.parameters) {
        if (p.name == name) latex = p.latex;
      }
      values.push_back({{"name", name}, {"latex", latex}, {"text", text}});
    }
    json answers = json::array();
    for (const auto& g : v.answers) answers.push_back(answer_json(g));
    variants.push_back({{"number", v.number}, {"values", values}, {"answers", answers}});
  }
  json rules = {{"half_unit_slack", check::kHalfUnitSlack}};
  rules["sigfigs"] = options.sigfigs ? json(*options.sigfigs) : json(nullptr);
  return json{{"rules", rules}, {"variants", variants}}.dump(1) + "\n";
}

std::vector<OutputFile> prairielearn_question(const Problem& problem, const VariantSet& set,
                                              const check::Options& options) {
  const json info = {{"uuid", question_uuid(problem.id)},
                     {"title", problem.title},
                     {"topic", "Rigid-body rotation"},
                     {"tags", {"wobble", problem.id}},
                     {"type", "v3"},
                     {"singleVariant", set.variants.size() == 1}};
  return {{kPrairieLearnFiles[0], info.dump(2) + "\n"},
          {kPrairieLearnFiles[1], question_html(problem, set)},
          {kPrairieLearnFiles[2], std::string(kPrairieLearnServerPy)},
          {kPrairieLearnFiles[3], variants_json(set, options)}};
}

}  // namespace wobble::exports
