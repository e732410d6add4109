#include <stdexcept>

#include "render/render.hpp"

namespace wobble {

namespace {
nlohmann::ordered_json value_json(const Value& v) {
  using J = nlohmann::ordered_json;
  switch (v.shape) {
    case Value::Shape::scalar:
      return v.data.at(0);
    case Value::Shape::vector:
      return J(v.data);
    case Value::Shape::matrix: {
      J rows = J::array();
      for (std::size_t i = 0; i < v.rows; ++i) {
        J row = J::array();
        for (std::size_t j = 0; j < v.cols; ++j) row.push_back(v.at(i, j));
        rows.push_back(row);
      }
      return rows;
    }
  }
  return nullptr;
}
}  // namespace

Format format_from_name(std::string_view name) {
  if (name == "text") return Format::text;
  if (name == "markdown") return Format::markdown;
  if (name == "latex") return Format::latex;
  if (name == "json") return Format::json;
  throw std::invalid_argument("unknown format '" + std::string(name) +
                              "' (expected text, markdown, latex or json)");
}

nlohmann::ordered_json key_to_json(const Key& key) {
  using J = nlohmann::ordered_json;
  J j;
  j["problem"] = key.problem;
  j["title"] = key.title;
  if (key.variant) j["variant"] = *key.variant;  // only for a student's variant
  j["source"] = key.source;
  j["statement"] = key.statement;
  j["notes"] = key.notes;
  J params = J::object();
  for (const auto& p : key.parameters) params[p.name] = {{"value", p.value}, {"unit", p.unit}};
  j["parameters"] = params;
  J parts = J::array();
  for (const auto& part : key.parts) {
    J answers = J::array();
    for (const auto& a : part.answers) {
      J entry{{"name", a.name}};
      if (a.quantity != a.name) entry["quantity"] = a.quantity;
      // What the answer is (solvers/key.hpp): an export reads these, never the name.
      entry["kind"] = kind_name(a.kind);
      if (a.frame != AnswerFrame::none) entry["frame"] = frame_name(a.frame);
      if (a.sign != SignConvention::none) entry["sign"] = sign_name(a.sign);
      if (!a.named_entries.empty()) entry["entries"] = a.named_entries;
      entry["symbolic"] = a.symbolic.empty() ? J(nullptr) : J(a.symbolic);
      entry["latex"] = a.latex;
      entry["value"] = value_json(a.value);
      entry["unit"] = a.unit;
      entry["notes"] = a.notes;
      answers.push_back(entry);
    }
    J steps = J::array();
    for (const auto& s : part.steps) steps.push_back({{"text", s.text}, {"latex", s.latex}});
    J entry{{"id", part.id}, {"question", part.question}, {"answers", answers}, {"steps", steps}};
    // Only when some answer does not exist at these values: the stored keys stay as they were.
    if (!part.absent.empty()) entry["absent"] = part.absent;
    parts.push_back(entry);
  }
  j["parts"] = parts;
  return j;
}

std::string render_json(const Key& key) {
  return key_to_json(key).dump(2) + "\n";
}

std::string render(const Key& key, Format format, std::size_t width) {
  switch (format) {
    case Format::text:
      return render_text(key, width);
    case Format::markdown:
      return render_markdown(key);
    case Format::latex:
      return render_latex(key);
    case Format::json:
      return render_json(key);
  }
  return "";
}

}  // namespace wobble
