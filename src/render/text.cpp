#include <fmt/format.h>

#include "core/characters.hpp"
#include "core/word_wrap.hpp"
#include "render/common.hpp"
#include "render/prose.hpp"
#include "render/render.hpp"
#include "symbolic/plain_text.hpp"

namespace wobble {

namespace {
// "Parameters: M = 0.5 kg; R = 0.05 m; ..": at a width, broken between the values, never inside
// one ("θ0 = 30° = 0.5235987756 rad" stays whole).
std::string parameters_line(const Key& key, std::size_t width) {
  std::string out = "Parameters:";
  std::size_t used = columns(out);
  for (std::size_t i = 0; i < key.parameters.size(); ++i) {
    const auto& p = key.parameters[i];
    const std::string entry =
        fmt::format("{} = {}{}", detail::pretty(p.name), detail::parameter_value_text(p),
                    i + 1 < key.parameters.size() ? ";" : "");
    const std::size_t w = columns(entry);
    if (width > 0 && used + 1 + w > width && i > 0) {
      out += "\n ";
      used = 1;
    }
    out += " " + entry;
    used += 1 + w;
  }
  return out + "\n";
}
}  // namespace

std::string render_text(const Key& key, std::size_t width) {
  using detail::pretty;
  const detail::ProseNames names = detail::prose_names(key);
  const auto prose = [&](const std::string& s) {
    return detail::unicode_text(s, names, detail::AnswerNameStyle::plain);
  };
  std::string out = word_wrapped(
      fmt::format("{}{}  [{}]", key.title,
                  key.variant ? fmt::format(" (variant {})", *key.variant) : "", key.problem),
      width, "", "");
  if (!key.source.empty()) out += word_wrapped("Source: " + key.source, width, "", "  ");
  std::string statement = plain_text(key.statement);
  if (!statement.empty() && statement.back() != '\n') statement += "\n";
  out += "\n" + reflowed(statement, width);
  out += "\n" + parameters_line(key, width);
  for (const auto& part : key.parts) {
    out += "\n" + word_wrapped(plain_text(part.question), width, "(" + part.id + ") ", "    ");
    for (const auto& a : part.answers) {
      const std::string lead = "    " + a.name + " = ";
      if (!a.symbolic.empty()) out += lead + pretty(a.symbolic) + "\n";
      const std::string eq = a.symbolic.empty() ? lead : std::string(lead.size() - 2, ' ') + "= ";
      const std::string indent(eq.size(), ' ');
      out += eq + detail::value_text(a.value, indent) + detail::unit_text(a.unit) + "\n";
      for (const auto& n : a.notes)
        out += word_wrapped(prose(n), width, "      note: ", std::string(12, ' '));
    }
    for (std::size_t i = 0; i < part.absent.size(); ++i)
      out += "    " + part.absent[i] + " = " + detail::absent_answer_text(part, i) + "\n";
    if (!part.steps.empty()) {
      out += "  Steps:\n";
      for (std::size_t i = 0; i < part.steps.size(); ++i) {
        const auto& s = part.steps[i];
        const std::string number = fmt::format("   {}. ", i + 1);
        out += word_wrapped(s.text.empty() ? s.latex : prose(pretty(s.text)), width, number,
                            std::string(number.size(), ' '));
      }
    }
  }
  out += "\nConventions:\n";
  for (const auto& n : key.notes) out += word_wrapped(prose(n), width, "  - ", "    ");
  return out;
}

}  // namespace wobble
