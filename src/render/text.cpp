#include <fmt/format.h>

#include "render/common.hpp"
#include "render/prose.hpp"
#include "render/render.hpp"
#include "symbolic/plain_text.hpp"

namespace wobble {

std::string render_text(const Key& key) {
  using detail::pretty;
  const detail::ProseNames names = detail::prose_names(key);
  const auto prose = [&](const std::string& s) {
    return detail::unicode_text(s, names, detail::AnswerNameStyle::plain);
  };
  std::string out = fmt::format("{}{}  [{}]\n", key.title,
                                key.variant ? fmt::format(" (variant {})", *key.variant) : "",
                                key.problem);
  if (!key.source.empty()) out += "Source: " + key.source + "\n";
  out += "\n" + plain_text(key.statement);
  if (out.back() != '\n') out += "\n";
  out += "\nParameters:";
  for (const auto& p : key.parameters) {
    out += fmt::format(" {} = {};", pretty(p.name), detail::parameter_value_text(p));
  }
  out.back() = '\n';
  for (const auto& part : key.parts) {
    out += fmt::format("\n({}) {}\n", part.id, plain_text(part.question));
    for (const auto& a : part.answers) {
      const std::string lead = "    " + a.name + " = ";
      if (!a.symbolic.empty()) out += lead + pretty(a.symbolic) + "\n";
      const std::string eq = a.symbolic.empty() ? lead : std::string(lead.size() - 2, ' ') + "= ";
      const std::string indent(eq.size(), ' ');
      out += eq + detail::value_text(a.value, indent) + detail::unit_text(a.unit) + "\n";
      for (const auto& n : a.notes) out += "      note: " + prose(n) + "\n";
    }
    if (!part.steps.empty()) {
      out += "  Steps:\n";
      for (std::size_t i = 0; i < part.steps.size(); ++i) {
        const auto& s = part.steps[i];
        out += fmt::format("   {}. {}\n", i + 1, s.text.empty() ? s.latex : prose(pretty(s.text)));
      }
    }
  }
  out += "\nConventions:\n";
  for (const auto& n : key.notes) out += "  - " + prose(n) + "\n";
  return out;
}

}  // namespace wobble
