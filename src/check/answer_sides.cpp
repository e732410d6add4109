#include "check/answer_sides.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <initializer_list>
#include <string_view>
#include <utility>

#include "check/brackets.hpp"
#include "check/judge_internal.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"
#include "symbolic/unicode_notation.hpp"

namespace wobble::check::detail {

std::vector<std::string> sides(const std::string& text, const std::string& name) {
  std::vector<std::string> out = top_level(text, '=');
  // "       = 0.00072 kg m²": the second line of a text key's answer alone.
  const bool dropped = out.front().empty() || name_spelling(out.front()) == name_spelling(name);
  if (out.size() > 1 && dropped) out.erase(out.begin());
  return out;
}

std::string function_of_answer(const std::string& side, const Answer& a) {
  if (a.unit != "rad") return "";
  const std::string s = trim(sym::to_ascii(side));
  for (const std::string f : {"cos", "sin", "tan"}) {
    if (s.compare(0, f.size(), f) != 0) continue;
    std::string rest = trim(s.substr(f.size()));
    if (wrapped(rest, '(')) rest = rest.substr(1, rest.size() - 2);
    if (!rest.empty() && std::isalpha(static_cast<unsigned char>(rest[0])) &&
        name_spelling(rest) == name_spelling(a.name))
      return f;
  }
  return "";
}

std::string approximations_as_equal(const std::string& text) {
  std::string s = trim(text);
  if (!s.empty() && s[0] == '~') s[0] = '=';
  // "about 304 days", "approx. 9.13 1/s": the word as the sign, before the value only.
  for (const std::string word : {"approximately ", "approx. ", "approx ", "about ", "roughly ",
                                 "around ", "circa ", "ca. "}) {
    if (ascii_lower(s.substr(0, word.size())) == word) {
      s = "= " + trim(s.substr(word.size()));
      break;
    }
  }
  for (const std::string sign : {"≈", "≃", "∼"}) {
    for (auto at = s.find(sign); at != std::string::npos; at = s.find(sign, at))
      s.replace(at, sign.size(), "=");
  }
  return s;
}

bool is_one_name(const std::string& side) {
  // "|L|", "‖L‖": the size of a vector, named; in LaTeX too, as the LaTeX key writes it.
  std::string bare = trim(side);
  for (const auto& [open, close] :
       std::initializer_list<std::pair<std::string_view, std::string_view>>{{"‖", "‖"},
                                                                            {"|", "|"},
                                                                            {"\\lvert", "\\rvert"},
                                                                            {"\\lVert", "\\rVert"},
                                                                            {"\\left|", "\\right|"},
                                                                            {"\\|", "\\|"}}) {
    if (bare.size() > open.size() + close.size() && bare.starts_with(open) &&
        bare.ends_with(close)) {
      bare = trim(bare.substr(open.size(), bare.size() - open.size() - close.size()));
      break;
    }
  }
  std::string s = trim(sym::to_ascii(bare));
  // "ω̇(0)", "\dot{\omega}(0)", "L(t = 0)": the name's value at t = 0, as the statements and the
  // LaTeX key write it.
  for (const std::string_view at_start : {"(0)", "(t=0)", "(t = 0)"}) {
    if (s.size() > at_start.size() && s.ends_with(at_start)) {
      s = trim(s.substr(0, s.size() - at_start.size()));
      break;
    }
  }
  // E', E′: a prime marks a name (the heavy top's E′), it makes no expression.
  for (const std::string prime : {"′", "'"}) {
    for (auto at = s.find(prime); at != std::string::npos; at = s.find(prime))
      s.erase(at, prime.size());
  }
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '\\' || c == '{' ||
           c == '}';
  });
}

std::optional<SquaredLabel> root_of_squared_label(const std::string& label,
                                                  const std::string& value, const Context& ctx,
                                                  const Answer& a) {
  if (a.value.shape != Value::Shape::scalar) return std::nullopt;
  const std::string s = trim(sym::to_ascii(label));
  if (s.size() < 3 || s.compare(s.size() - 2, 2, "^2") != 0) return std::nullopt;
  const std::string base = trim(s.substr(0, s.size() - 2));
  if (!is_one_name(base)) return std::nullopt;
  const bool own_name = name_spelling(base) == name_spelling(a.name);
  if (!own_name && (ctx.table.contains(base) || name_in_key(ctx.key, s) != s)) return std::nullopt;
  const auto [number, unit_text] = split_value_unit(trim(sym::to_ascii(value)));
  if (number.empty()) return std::nullopt;
  if (unit_text.empty()) return SquaredLabel{"sqrt(" + number + ")", std::nullopt, ""};
  Unit unit;
  try {
    unit = parse_unit(unit_text, kField);
  } catch (const InputError&) {
    return std::nullopt;
  }
  static constexpr std::array<const char*, 3> kSiBase{"kg", "m", "s"};
  std::string si;
  for (std::size_t k = 0; k < unit.dim.size(); ++k) {
    if (unit.dim[k] % 2 != 0) return SquaredLabel{"", unit, number};
    if (unit.dim[k] != 0)
      si += fmt::format("{}{}^{}", si.empty() ? "" : " ", kSiBase[k], unit.dim[k] / 2);
  }
  return SquaredLabel{
      "sqrt((" + number + ")*(" + unit.to_si_exact + "))" + (si.empty() ? "" : " " + si),
      std::nullopt, ""};
}

AxesLayout listed_layout(const std::string& text) {
  const auto [items, bracketed] = list_items(text);
  if (items.size() < 2 || items.size() > 3) return AxesLayout::rows_or_columns;
  const bool matrix_literal =
      bracketed && std::all_of(items.begin(), items.end(), [](const std::string& i) {
        return wrapped(i, '[') || wrapped(i, '(') || wrapped(i, '{');
      });
  return matrix_literal ? AxesLayout::rows_or_columns : AxesLayout::rows;
}

}  // namespace wobble::check::detail
