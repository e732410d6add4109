#include "render/handout.hpp"

#include <fmt/format.h>

#include "render/common.hpp"

namespace wobble {

std::string render_handout(const Key& key,
                           const std::vector<std::pair<std::string, std::string>>& shown,
                           std::optional<long> variant) {
  std::string out =
      fmt::format("# {}{}\n\n", key.title, variant ? fmt::format(" (variant {})", *variant) : "");
  out += key.statement;
  if (!out.empty() && out.back() != '\n') out += "\n";
  out += "\n| Parameter | Value | Unit | Meaning |\n|---|---|---|---|\n";
  for (const auto& p : key.parameters) {
    std::string value = format_number(p.value), unit = p.unit;
    for (const auto& [name, text] : shown) {
      if (name != p.name) continue;
      value = text;
      if (text.size() > 3 && text.compare(text.size() - 3, 3, "deg") == 0) {
        value = text.substr(0, text.size() - 3);
        unit = "°";
      }
    }
    std::string description;  // a '|' would end the Markdown cell
    for (const char c : p.description)
      description += c == '|' ? std::string("\\|") : std::string(1, c);
    out += fmt::format("| ${}$ | {} | {} | {} |\n", p.latex, value, unit, description);
  }
  for (const auto& part : key.parts) out += fmt::format("\n**({})** {}\n", part.id, part.question);
  return out;
}

}  // namespace wobble
