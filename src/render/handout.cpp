#include "render/handout.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/characters.hpp"
#include "render/common.hpp"
#include "symbolic/plain_text.hpp"
#include "symbolic/unicode_notation.hpp"

namespace wobble {

namespace {
// "I0 [kg m²], I [kg m²]": the names `wobble check --name` takes, with their SI units, never
// their values.
std::string answer_names(const PartKey& part, bool markdown) {
  std::string out;
  const auto add = [&](const std::string& name, const std::string& unit) {
    if (!out.empty()) out += ", ";
    out += markdown ? "`" + name + "`" : name;
    if (!unit.empty()) out += " [" + detail::pretty(unit) + "]";
  };
  for (const auto& a : part.answers) {
    add(a.name, asked_unit(a));
    if (const std::string form = answer_form(a); !form.empty()) out += " (" + form + ")";
  }
  // Those that do not exist at these values are given too ("none"), in their units.
  for (std::size_t i = 0; i < part.absent.size(); ++i)
    add(part.absent[i], i < part.absent_unit.size() ? part.absent_unit[i] : "");
  return out;
}

std::string title_line(const Key& key, std::optional<long> variant) {
  return key.title + (variant ? fmt::format(" (variant {})", *variant) : "");
}
}  // namespace

std::string render_handout(const Key& key,
                           const std::vector<std::pair<std::string, std::string>>& shown,
                           std::optional<long> variant) {
  std::string out = "# " + title_line(key, variant) + "\n\n";
  out += key.statement;
  if (!out.empty() && out.back() != '\n') out += "\n";
  out += "\n| Parameter | Value | Unit | Meaning |\n|---|---|---|---|\n";
  for (const auto& p : key.parameters) {
    const auto [value, unit] = detail::shown_value(p, shown);
    out += fmt::format("| ${}$ | {} | {} | {} |\n", p.latex, value, unit,
                       detail::markdown_cell(p.description));
  }
  for (const auto& part : key.parts) {
    out += fmt::format("\n**({})** {}\n", part.id, part.question);
    if (!part.asked_names().empty()) {
      out += "\n*Answers to give (`wobble check` names):* " + answer_names(part, true) + "\n";
    }
  }
  return out;
}

std::string render_handout_text(const Key& key,
                                const std::vector<std::pair<std::string, std::string>>& shown,
                                std::optional<long> variant, bool with_questions) {
  std::string out = title_line(key, variant) + "\n\n" + plain_text(key.statement);
  if (!out.empty() && out.back() != '\n') out += "\n";
  out += "\nValues:\n";
  // The name to type, and the symbol the statement prints where that is another ("w1 (ω₁)":
  // its LaTeX is \omega_1); both read back.
  const auto shown_name = [](const ParameterValue& p) {
    const std::string name = detail::pretty(p.name);
    return p.latex.empty() || sym::typed_spelling(p.latex) == p.name
               ? name
               : name + " (" + math_to_unicode(p.latex) + ")";
  };
  std::size_t width = 0;
  for (const auto& p : key.parameters) {
    width = std::max(width, columns(shown_name(p)));
  }
  for (const auto& p : key.parameters) {
    const auto [value, unit] = detail::shown_value(p, shown);
    const std::string name = shown_name(p);
    out += fmt::format("  {}{} = {}{}{}\n", name, std::string(width - columns(name), ' '), value,
                       unit == "°" ? "°" : detail::unit_text(unit),
                       p.description.empty() ? "" : "   (" + plain_text(p.description) + ")");
  }
  if (with_questions) {
    for (const auto& part : key.parts) {
      out += fmt::format("\n({}) {}\n", part.id, plain_text(part.question));
      if (!part.asked_names().empty())
        out += "    answers to give: " + answer_names(part, false) + "\n";
    }
  }
  return out;
}

}  // namespace wobble
