#include "check/names_put_in.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <exception>
#include <functional>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "check/answer_reading.hpp"
#include "check/brackets.hpp"
#include "check/judge.hpp"
#include "check/judge_internal.hpp"
#include "check/latex_answer.hpp"
#include "check/names_run_together.hpp"
#include "check/typed_text.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"
#include "symbolic/unicode_notation.hpp"

namespace wobble::check::detail {

// The name a reader's message quotes after `what` ("undefined symbol 'T'"), or "".
std::string quoted_after(const std::string& message, const std::string& what) {
  const auto at = message.find(what + " '");
  if (at == std::string::npos) return "";
  const auto from = at + what.size() + 2;
  const auto to = message.find('\'', from);
  return to == std::string::npos ? "" : message.substr(from, to - from);
}

// The name a reader's message says is undefined ("undefined symbol 'T'"), or "".
std::string undefined_name(const std::string& message) {
  return quoted_after(message, "undefined symbol");
}

// undefined_name, or the text the reader took for a unit and refused: after a value it takes a
// word for its unit ("ψ̇₀ I₃", "2 L0_body"), where a name may be meant.
std::string refused_name(const std::string& message) {
  const std::string name = undefined_name(message);
  return name.empty() ? sym::to_ascii(quoted_after(message, "cannot read the unit")) : name;
}

// The symbol the LaTeX reader's message says is none of the problem's, as drawn
// ("\Omega_{space}"), or "".
std::string latex_unknown_symbol(const std::string& message) {
  constexpr std::string_view kUnknown = " is not one of this problem's symbols";
  const std::size_t end = message.find(kUnknown);
  if (end == std::string::npos) return "";
  const std::size_t start = message.rfind(": ", end);
  return start == std::string::npos ? "" : message.substr(start + 2, end - start - 2);
}

const PartKey* part_answering(const Key& key, const std::string& name) {
  const auto it = std::find_if(key.parts.begin(), key.parts.end(), [&](const PartKey& p) {
    return std::any_of(p.answers.begin(), p.answers.end(),
                       [&](const Answer& b) { return b.name == name; });
  });
  return it == key.parts.end() ? nullptr : &*it;
}

namespace {
// The one answer whose name begins with `name` and '_' ("Omega_body" for Omega_body_rate, as
// the Earth's question (a) writes Ω_body), where `name` is no answer's own; "" otherwise (two
// begin so: "Omega" for Omega_body_rate and Omega_space_rate).
std::string answer_begun(const Key& key, const std::string& name) {
  const std::string own = name_in_key(key, name);
  std::string found;
  for (const auto& part : key.parts) {
    for (const auto& answer : part.answers) {
      if (own == answer.name) return "";
      if (!answer.name.starts_with(name + "_")) continue;
      if (!found.empty()) return "";
      found = answer.name;
    }
  }
  return found;
}

}  // namespace

// The answer `name` names where `a` may be written in terms of it, as question (a) of the
// rectangular solid writes I = I₀ diag(..) and t_max is π/Ω_space_rate: a number with a closed
// form, of a part before a's or of a's own, not `a` itself; or a vector or matrix so, as PHY
// 711's R(α, β, γ) is Taylor's R transposed (R_zyzᵀ), which reads only where its shape does.
// Else nullptr.
const Answer* referable_answer(const Context& ctx, const Answer& a, const std::string& name) {
  std::string named = name_in_key(ctx.key, name);
  if (const std::string begun = answer_begun(ctx.key, name); !begun.empty()) named = begun;
  for (const auto& part : ctx.key.parts) {
    bool own = false;
    const Answer* found = nullptr;
    for (const auto& other : part.answers) {
      if (&other == &a) {
        own = true;
      } else if (other.name == named) {
        found = &other;
      }
    }
    if (found != nullptr) return found->symbolic.empty() ? nullptr : found;
    if (own) return nullptr;  // a's part is the last that may hold it
  }
  return nullptr;
}

namespace {

// `ascii` with each name that `replacement` gives text for replaced by it, and whether any was;
// a name starts at a letter after no letter, '_' or '.' ("2I0" is 2 times I0).
std::pair<std::string, bool> names_replaced(
    const std::string& ascii,
    const std::function<std::optional<std::string>(const std::string&)>& replacement) {
  std::string out;
  bool found = false;
  for (std::size_t i = 0; i < ascii.size();) {
    const bool starts = std::isalpha(static_cast<unsigned char>(ascii[i])) &&
                        (i == 0 || !(std::isalpha(static_cast<unsigned char>(ascii[i - 1])) ||
                                     ascii[i - 1] == '_' || ascii[i - 1] == '.'));
    if (!starts) {
      out += ascii[i++];
      continue;
    }
    std::size_t end = i;
    while (end < ascii.size() &&
           (std::isalnum(static_cast<unsigned char>(ascii[end])) || ascii[end] == '_'))
      ++end;
    const std::string word = ascii.substr(i, end - i);
    const std::optional<std::string> put = replacement(word);
    // After a number or a bracket, the form put in is its factor, as the name was ("2 I3" is
    // 2*(M*R^2/2)), so that what else keeps the text from reading is what the reader says.
    const std::size_t last = out.find_last_not_of(' ');
    if (put && last != std::string::npos &&
        (std::isdigit(static_cast<unsigned char>(out[last])) || out[last] == '.' ||
         out[last] == ')')) {
      out.erase(last + 1);
      out += '*';
    }
    out += put ? *put : word;
    found = found || put.has_value();
    i = end;
  }
  return {out, found};
}

// The calls that take a vector's magnitude: norm(..) as NumPy and MATLAB write it, abs(..) as
// LaTeX's |..| reads.
constexpr std::array<std::string_view, 2> kMagnitudeCalls{"norm(", "abs("};

// The length of the magnitude call at ascii[i] ("norm("), or 0 where none starts there.
std::size_t magnitude_call_at(const std::string& ascii, std::size_t i) {
  if (i > 0 && std::isalnum(static_cast<unsigned char>(ascii[i - 1]))) return 0;
  for (const std::string_view call : kMagnitudeCalls) {
    if (ascii.compare(i, call.size(), call) == 0) return call.size();
  }
  return 0;
}

// The magnitude of the vector answer `r` in its exact form: sqrt of the sum of its entries'
// squares, in brackets.
std::string magnitude_of(const Answer& r) {
  std::string squares;
  for (const std::string& entry : list_items(r.symbolic).items)
    squares += (squares.empty() ? "(" : "+(") + entry + ")^2";
  return "(sqrt(" + squares + "))";
}

// `ascii` with the magnitude of the vector answer `r` put in where the text takes it of r's
// name, "|Omega_space|", "norm(Omega_space)" or "abs(Omega_space)", as the flying plate's
// statement writes t = π/|Ω_space|; and whether it was.
std::pair<std::string, bool> magnitudes_put_in(
    const std::string& ascii, const Answer& r,
    const std::function<bool(const std::string&)>& names_r) {
  if (r.value.shape != Value::Shape::vector) return {ascii, false};
  const std::string magnitude = magnitude_of(r);
  std::string out;
  bool found = false;
  for (std::size_t i = 0; i < ascii.size();) {
    const bool bar = ascii[i] == '|';
    const std::size_t call = bar ? 0 : magnitude_call_at(ascii, i);
    const std::size_t from = i + (bar ? 1 : call);
    const std::size_t to = bar ? ascii.find('|', from) : call > 0 ? ascii.find(')', from) : 0;
    if ((bar || call > 0) && to != std::string::npos &&
        names_r(trim(ascii.substr(from, to - from)))) {
      out += magnitude;
      found = true;
      i = to + 1;
      continue;
    }
    out += ascii[i++];
  }
  return {out, found};
}

// The name inside the first |..| or norm(..) of `ascii` ("Omega_space" in "pi/|Omega_space|"),
// or "": the reader refuses "norm" as a function before it comes to the name.
std::string name_in_magnitude(const std::string& ascii) {
  for (const std::string_view open : {std::string_view("|"), kMagnitudeCalls[0]}) {
    const std::size_t at = ascii.find(open);
    if (at == std::string::npos) continue;
    const std::size_t from = at + open.size();
    const std::size_t to = ascii.find(open == "|" ? '|' : ')', from);
    if (to != std::string::npos) return trim(ascii.substr(from, to - from));
  }
  return "";
}

}  // namespace

// Names put in said where they read (judge.cpp), not in the list: "lagrangian_0, p_phi, ..".
InputError problem_listed(const std::string& with, const std::string& without) {
  constexpr std::string_view kListed = " is not one of this problem's symbols (";
  const std::size_t at_with = with.find(kListed), at_without = without.find(kListed);
  if (at_with == std::string::npos || at_without == std::string::npos) return InputError(with);
  // The lists alone: what follows either (a hint on `without`'s own symbol) stays with it.
  const std::size_t end_with = matching(with, at_with + kListed.size() - 1);
  const std::size_t end_without = matching(without, at_without + kListed.size() - 1);
  if (end_with == std::string::npos || end_without == std::string::npos) return InputError(with);
  return InputError(with.substr(0, at_with) +
                    without.substr(at_without, end_without + 1 - at_without) +
                    with.substr(end_with + 1));
}

namespace {
// A name as LaTeX draws it, as a problem file spells its own: "phidot" -> "\dot\phi", "omega3"
// -> "\omega_3", "I1" -> "I_1". The LaTeX reader lists the symbols so.
std::string name_latex(const std::string& name) {
  // "theta_L" -> "\theta_L": a Greek stem and its subscript in letters, as the steps write θ_L.
  if (const std::size_t under = name.find('_');
      under != std::string::npos && under + 1 < name.size() &&
      sym::greek_letters().count(name.substr(0, under)) != 0)
    return "\\" + name.substr(0, under) + "_{" + name.substr(under + 1) + "}";
  std::size_t digits = name.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(name[digits - 1]))) --digits;
  std::string base = name.substr(0, digits);
  const std::string sub = name.substr(digits);
  const std::string_view rate = "dot";
  const bool dot = base.size() > rate.size() && base.ends_with(rate);
  if (dot) base.resize(base.size() - rate.size());
  std::string letter = sym::greek_letters().count(base) ? "\\" + base : base;
  if (dot) letter = letter[0] == '\\' ? "\\dot" + letter : "\\dot{" + letter + "}";
  return sub.empty() ? letter : letter + "_" + sub;
}

// Whether two refusals of the LaTeX reader name the same thing: the same text, or the same
// symbol refused whatever the symbols they list.
bool same_refusal(const std::string& a, const std::string& b) {
  const std::string unknown_a = latex_unknown_symbol(a), unknown_b = latex_unknown_symbol(b);
  if (unknown_a.empty() || unknown_b.empty()) return a == b;
  return unknown_a == unknown_b;
}

// LaTeX `text` as plain text, read with `with_names` (the problem's symbols and names the key
// reads); nullopt where that reading refuses it as the problem's symbols alone do (that symbol,
// or "ẑ, ê₃ mix bases" from a later reading).
// @throws InputError where the names make a difference to what is refused: the name that still
//   keeps the text from reading ("\frac{p_\psi}{Q}": Q, not the answer's p_ψ).
std::optional<std::string> latex_with_names(const Context& ctx, const std::string& text,
                                            const sym::SymbolTable& with_names) {
  try {
    return latex_as_text(text, with_names, kField);
  } catch (const InputError& with) {
    try {
      (void)latex_as_text(text, ctx.table, kField);
    } catch (const InputError& without) {
      if (!same_refusal(with.what(), without.what()))
        throw problem_listed(with.what(), without.what());
    }
    return std::nullopt;
  }
}

// Where `word`, its underscores left out ("Omega_1" as the question's Ω₁, "phi_dot"), is among
// `spelled`.
std::optional<std::size_t> index_spelled(const std::vector<std::string>& spelled,
                                         const std::string& word) {
  std::string bare = word;
  bare.erase(std::remove(bare.begin(), bare.end(), '_'), bare.end());
  const auto it = std::find(spelled.begin(), spelled.end(), bare);
  if (it == spelled.end()) return std::nullopt;
  return static_cast<std::size_t>(it - spelled.begin());
}

// A matrix's closed form is nine entries long, the tennis racket's period some 400 characters:
// there a line names the answer, and the form is the key's to look up. One line's worth is shown.
constexpr std::size_t kLongestFormShown = 80;

// What names_put_in read: the text with forms put in for names, and which names it read.
struct NamesPutIn {
  std::string text;
  std::vector<bool> read;
};

// `text` with each of `names` (GiNaC text) that `index_of` knows replaced by its `form`, where
// the reader's `message` refused one of them, run together with others or not ("φ̇θ", "I₃ω₃");
// in LaTeX, where the text reads with them declared ("\dot\phi", "I_3"), and where it then
// still does not, what else keeps it from reading is said. nullopt where no such name is read.
std::optional<NamesPutIn> names_put_in(
    const Context& ctx, const std::string& text, const std::string& message,
    const std::vector<std::string>& names,
    const std::function<std::optional<std::size_t>(const std::string&)>& index_of,
    const std::function<std::string(std::size_t)>& form) {
  if (names.empty()) return std::nullopt;
  sym::SymbolTable with_names = ctx.table;
  for (const std::string& name : names) {
    if (!with_names.contains(name))
      with_names.declare(name, name_latex(name), sym::SymbolSign::real);
  }
  std::string ascii;
  if (looks_like_latex(text)) {
    const std::optional<std::string> plain = latex_with_names(ctx, text, with_names);
    if (!plain) return std::nullopt;
    ascii = *plain;
  } else {
    const auto ours = [&](const std::string& word) -> std::optional<std::string> {
      return index_of(word) ? std::optional<std::string>(word) : std::nullopt;
    };
    const std::string refused = refused_name(message);
    if (refused.empty() || !names_replaced(names_apart(refused, with_names), ours).second)
      return std::nullopt;
    // In the reader's notation, so that a Greek letter stands apart from its neighbours as
    // the reader sets it ("c₁ω₂ω₃": ω₂ and ω₃ may be symbols spelled so, w2 and w3).
    std::string typed = sym::to_ascii(text);
    try {
      typed = prepared(text, kField);
    } catch (const InputError&) {
      // what the reader refuses there, it refuses again when the forms are put in
    }
    ascii = names_apart(typed, with_names);
  }
  NamesPutIn put{"", std::vector<bool>(names.size(), false)};
  const auto [replaced, found] =
      names_replaced(ascii, [&](const std::string& word) -> std::optional<std::string> {
        const std::optional<std::size_t> i = index_of(word);
        if (!i) return std::nullopt;
        put.read[*i] = true;
        return form(*i);
      });
  if (!found) return std::nullopt;
  put.text = replaced;
  return put;
}

}  // namespace

namespace {
// LaTeX `text` as plain text, read with the name of every answer `a` may be written in terms of
// declared as the LaTeX a problem file draws it with (I0 as I_0, name_latex), and the first such
// name in it: "I_0 \mathrm{diag}(1, 1, 2)" gives "I0*diag(1, 1, 2)" and I0. nullopt where it
// does not read so or holds no such name.
std::optional<std::pair<std::string, std::string>> latex_with_answer_names(
    const Context& ctx, const Answer& a, const std::string& text) {
  sym::SymbolTable with_answers = ctx.table;
  for (const auto& part : ctx.key.parts) {
    for (const auto& b : part.answers) {
      if (referable_answer(ctx, a, b.name) == nullptr) continue;
      if (!with_answers.contains(b.name))
        with_answers.declare(b.name, name_latex(b.name), sym::SymbolSign::real);
      for (const std::string& step_name : b.step_names) {  // \theta_L for angle_L_e3
        // Only a name a symbol can have: not a primed one (E′ for the heavy top's level) nor a
        // derivative's (dω/dt); they have no LaTeX name.
        const bool symbol_name = std::all_of(step_name.begin(), step_name.end(), [](char c) {
          return is_letter(c) || is_digit(c) || c == '_';
        });
        if (!with_answers.contains(step_name) && symbol_name)
          with_answers.declare(step_name, name_latex(step_name), sym::SymbolSign::real);
      }
    }
  }
  // "\frac{p_\psi}{I_3}": the steps' names as well, read in turn (defined_named) from the
  // plain text this gives. Not a primed one (no LaTeX name) nor a's own (ω₃ for ω₃).
  for (const DefinedName& d : ctx.key.defined_names) {
    if (d.name != a.name && d.name.find('\'') == std::string::npos &&
        !with_answers.contains(d.name))
      with_answers.declare(d.name, name_latex(d.name), sym::SymbolSign::real);
  }
  const std::optional<std::string> plain = latex_with_names(ctx, text, with_answers);
  if (!plain) return std::nullopt;
  const std::string& ascii = *plain;
  for (const auto& [at, length] : identifiers(ascii)) {
    const std::string word = ascii.substr(at, length);
    if (!ctx.table.contains(word) && referable_answer(ctx, a, word) != nullptr)
      return std::pair{ascii, word};
  }
  return std::nullopt;
}

// The first name in `ascii` of an answer `a` may be written in terms of, found with the key's
// answers' names set apart from the problem's symbols as the reader sets names ("I0omega" from
// "I₀ω"); "" where there is none. For a refusal whose quote names no one name: a sum along unit
// vectors, "I₀ω sin α ê₁ + 2I₀ω cos α ê₃", is refused as a whole.
std::string referable_name_in(const Context& ctx, const Answer& a, const std::string& ascii) {
  sym::SymbolTable with_answers = ctx.table;
  for (const auto& part : ctx.key.parts) {
    for (const auto& b : part.answers) {
      if (!with_answers.contains(b.name))
        with_answers.declare(b.name, name_latex(b.name), sym::SymbolSign::real);
    }
  }
  const std::string apart = names_apart(ascii, with_answers);
  for (const auto& [at, length] : identifiers(apart)) {
    const std::string word = apart.substr(at, length);
    if (!ctx.table.contains(word) && referable_answer(ctx, a, word) != nullptr) return word;
  }
  return "";
}
}  // namespace

// An earlier answer's name (names_put_in.hpp).
std::optional<Referenced> answer_referenced(const Context& ctx, const Answer& a,
                                            const std::string& text, const std::string& message) {
  std::string ascii, name;
  if (looks_like_latex(text)) {
    const auto plain = latex_with_answer_names(ctx, a, text);
    if (!plain) return std::nullopt;
    std::tie(ascii, name) = *plain;
  } else {
    // "‖Ω_space‖", a norm's double bars, as single ones.
    ascii = sym::to_ascii(text);
    for (std::size_t at = ascii.find("‖"); at != std::string::npos; at = ascii.find("‖"))
      ascii.replace(at, std::string_view("‖").size(), "|");
    // "ê₁" is "ê1" in ASCII, which no reader takes for a unit vector: "ê_1", which they do.
    constexpr std::string_view kHatE = "ê";
    for (std::size_t at = ascii.find(kHatE); at != std::string::npos;
         at = ascii.find(kHatE, at + kHatE.size())) {
      const std::size_t index = at + kHatE.size();
      if (index < ascii.size() && ascii[index] >= '1' && ascii[index] <= '3')
        ascii.insert(index, "_");
    }
    name = refused_name(message);
    if (name.empty()) name = name_in_magnitude(ascii);
    if (name.empty()) name = referable_name_in(ctx, a, ascii);
  }
  // What stands between bars or in norm(..) may be no name at all ("norm(Omega_sp~ace)"): not
  // one to put in, nor to declare.
  if (!sym::is_identifier(name)) return std::nullopt;  // nor is "" one
  const Answer* r = referable_answer(ctx, a, name);
  if (r == nullptr) return std::nullopt;
  if (!looks_like_latex(text)) {
    // "I₀ω sin α": the name run together with a symbol, set apart as the reader sets names.
    sym::SymbolTable with_name = ctx.table;
    if (!with_name.contains(name)) with_name.declare(name, name_latex(name), sym::SymbolSign::real);
    ascii = names_apart(ascii, with_name);
  }
  const auto names_r = [&](const std::string& word) {
    return name_in_key(ctx.key, word) == r->name || answer_begun(ctx.key, word) == r->name;
  };
  const auto [with_magnitudes, magnitude] = magnitudes_put_in(ascii, *r, names_r);
  // In a number's expression a vector's name alone can only be its size, as books write Ω for
  // the precession rate: "π/Ω_space" for t_max is π/|Ω_space|, and the line says so.
  const bool size_of_name =
      a.value.shape == Value::Shape::scalar && r->value.shape == Value::Shape::vector;
  const auto [out, named] =
      names_replaced(with_magnitudes, [&](const std::string& word) -> std::optional<std::string> {
        if (!names_r(word)) return std::nullopt;
        if (size_of_name) return magnitude_of(*r);
        // A vector's or matrix's own brackets hold it (round ones about it would not read).
        if (r->value.shape != Value::Shape::scalar) return r->symbolic;
        return "(" + r->symbolic + ")";
      });
  if (!magnitude && !named) return std::nullopt;
  const PartKey* part = part_answering(ctx.key, r->name);
  const bool shown =
      r->value.shape == Value::Shape::scalar && r->symbolic.size() <= kLongestFormShown;
  // Ω_body for Omega_body_rate: the name as typed, and the answer it is read as.
  // θ_L for angle_L_e3 alike: the name the steps write for it.
  const bool begun = name_spelling(name) != name_spelling(r->name);
  // As typed, its Greek stem as a letter: "Ω_body", "θ_L" (to_unicode keeps a name with an
  // underscore whole).
  const std::size_t stem = std::min(name.find('_'), name.size());
  const std::string yours =
      begun ? sym::to_unicode(name.substr(0, stem)) + name.substr(stem) : r->name;
  const std::string subject = begun ? yours + " as " + r->name : r->name;
  const std::string read = shown   ? subject + " = " + sym::to_unicode(r->symbolic) + ","
                           : begun ? subject + ","
                                   : subject + " as";
  if (named && size_of_name) {
    return Referenced{out,
                      fmt::format("read with {} as its size |{}| (the key's answer to part "
                                  "({}) is a vector)",
                                  yours, r->name, part->id),
                      fmt::format(": right as far as your {} is", yours)};
  }
  return Referenced{out, fmt::format("read with {} the key's answer to part ({})", read, part->id),
                    fmt::format(": right as far as your {} is", yours)};
}

// `text` with the convention's names (key.hpp's ConventionName: Taylor's φ for PHY 711's α)
// written as the parameters they are here (names_put_in), and the line that says which.
std::optional<Referenced> convention_named(const Context& ctx, const std::string& text,
                                           const std::string& message) {
  const auto& names = ctx.key.convention_names;
  std::vector<std::string> spelled;
  for (const ConventionName& c : names) spelled.push_back(c.name);
  const auto index_of = [&](const std::string& word) { return index_spelled(spelled, word); };
  const std::optional<NamesPutIn> put = names_put_in(
      ctx, text, message, spelled, index_of, [&](std::size_t i) { return names[i].parameter; });
  if (!put) return std::nullopt;
  std::string lines;  // in the convention's order, whatever the answer's
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (put->read[i]) {
      lines += (lines.empty() ? "" : ", ") + sym::to_unicode(names[i].name) + " = " +
               sym::to_unicode(names[i].parameter);
    }
  }
  return Referenced{
      put->text,
      fmt::format("read in {} names, as this problem's symbols: {}", ctx.key.convention, lines),
      ""};
}

namespace {
// Marks around a form put in for a name, until brackets_put_in makes them brackets.
constexpr char kPutIn = '\x01', kPutInEnd = '\x02';

// `marked` with each form put in as a bracket, joined by '*' to a bracket beside it: "I₃ (ψ̇₀)"
// would otherwise be "(M*R^2/2) (psidot0)", which reads as a matrix's two rows.
std::string brackets_put_in(const std::string& marked) {
  std::string out;
  for (std::size_t i = 0; i < marked.size(); ++i) {
    const char c = marked[i];
    if (c == kPutIn) {
      const std::size_t last = out.find_last_not_of(' ');
      if (last != std::string::npos && out[last] == ')') out += '*';
      out += '(';
    } else if (c == kPutInEnd) {
      out += ')';
      const std::size_t next = marked.find_first_not_of(' ', i + 1);
      if (next != std::string::npos && marked[next] == '(') out += '*';
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

std::string defined_spelling(const std::string& word) {
  std::string plain;
  for (const char c : word) {
    if (c != '_') plain += c;
  }
  if (plain.size() > 1 && plain[0] == 'w' &&
      std::all_of(plain.begin() + 1, plain.end(),
                  [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }))
    return "omega" + plain.substr(1);
  return plain;
}

namespace {
// A name's trailing prime, as typed: ASCII's ' or Unicode's ′ (U+2032): its length at `at` in
// `s`, or 0.
std::size_t prime_length(const std::string& s, std::size_t at) {
  if (at < s.size() && s[at] == '\'') return 1;
  constexpr std::string_view kPrime = "′";
  return s.compare(at, kPrime.size(), kPrime) == 0 ? kPrime.size() : 0;
}

bool primed(const DefinedName& d) {
  return d.name.ends_with('\'');
}

// The exact forms of `a` itself: its entries' for a vector or matrix. A defined name that is one
// of them is no working in `a` (ω₃ for ω's third entry).
std::vector<std::string> own_forms(const Answer& a) {
  if (a.value.shape == Value::Shape::scalar) return {a.symbolic};
  return list_items(a.symbolic).items;
}

// The line for the defined names `read` (in the key's order, whatever the answer's): each with
// its form and meaning, and the text to judge with their forms put in.
Referenced defined_read(const std::vector<const DefinedName*>& names, const std::vector<bool>& read,
                        const std::string& marked) {
  std::string forms, yours;
  std::size_t count = 0;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (!read[i]) continue;
    const std::string shown =
        primed(*names[i])
            ? sym::to_unicode(names[i]->name.substr(0, names[i]->name.size() - 1)) + "′"
            : sym::to_unicode(names[i]->name);
    const std::string form = sym::to_unicode(names[i]->symbolic);
    // The racket's λ is some 150 characters: named, its form the key's to look up.
    forms += fmt::format("{}{}{} ({})", forms.empty() ? "" : ", ", shown,
                         names[i]->symbolic.size() <= kLongestFormShown ? " = " + form : "",
                         names[i]->meaning);
    yours += (yours.empty() ? "" : ", ") + shown;
    ++count;
  }
  return Referenced{
      brackets_put_in(marked),
      fmt::format("read with {}, as the key's steps write {}", forms, count == 1 ? "it" : "them"),
      fmt::format(": right as far as your {} {}", yours, count == 1 ? "is" : "are")};
}
}  // namespace

// `text` with the names the key's steps write for quantities of this problem (key.hpp's
// DefinedName: the heavy top's I₁, I₃, ω₃) as their exact forms in brackets (names_put_in), and
// the line that says so. Never the answer's own name nor one of its own forms: ω₃ for ω₃ is no
// working. Not a primed name (primed_named).
std::optional<Referenced> defined_named(const Context& ctx, const Answer& a,
                                        const std::string& text, const std::string& message) {
  const std::vector<std::string> own = own_forms(a);
  std::vector<const DefinedName*> names;
  std::vector<std::string> spelled;
  for (const DefinedName& d : ctx.key.defined_names) {
    if (primed(d) || std::find(own.begin(), own.end(), d.symbolic) != own.end()) continue;
    names.push_back(&d);
    spelled.push_back(d.name);
  }
  const auto index_of = [&](const std::string& word) -> std::optional<std::size_t> {
    const auto it = std::find(spelled.begin(), spelled.end(), defined_spelling(word));
    if (it == spelled.end() || *it == a.name || ctx.table.contains(*it)) return std::nullopt;
    return static_cast<std::size_t>(it - spelled.begin());
  };
  const std::optional<NamesPutIn> put =
      names_put_in(ctx, text, message, spelled, index_of,
                   [&](std::size_t i) { return kPutIn + names[i]->symbolic + kPutInEnd; });
  if (!put) return std::nullopt;
  return defined_read(names, put->read, put->text);
}

namespace {
// A primed name as DefinedName spells it ("omega1'" for ω₁', ω₁′, w1', ω'₁, omega_1'), and where
// it ends in the text.
struct PrimedWord {
  std::string spelled;
  std::size_t end = 0;
};

// The primed name whose identifier is at [at, at + length) of `ascii`; nullopt where no one
// prime follows it (ω₁'' is no name of the steps': a second derivative, or a slip).
std::optional<PrimedWord> primed_word(const std::string& ascii, std::size_t at,
                                      std::size_t length) {
  std::size_t past = at + length;
  const std::size_t prime = prime_length(ascii, past);
  if (prime == 0 || prime_length(ascii, past + prime) != 0) return std::nullopt;
  past += prime;
  std::string word = ascii.substr(at, length);
  // ω'₁: the index after the prime.
  std::size_t index = past < ascii.size() && ascii[past] == '_' ? past + 1 : past;
  const std::size_t index_from = index;
  while (index < ascii.size() && std::isdigit(static_cast<unsigned char>(ascii[index]))) ++index;
  if (index > index_from && !std::isdigit(static_cast<unsigned char>(word.back()))) {
    word += ascii.substr(index_from, index - index_from);
    past = index;
  }
  return PrimedWord{defined_spelling(word) + "'", past};
}

// `marked` with `form` put in, marked, as a factor where a name stood: a '*' on each side
// where an operand meets it ("I1 (..)" would read as a call of I1). `next` is where the text
// after the name starts in `ascii`.
void put_in_as_factor(std::string& marked, const std::string& form, const std::string& ascii,
                      std::size_t next) {
  const auto operand = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == ')';
  };
  const std::size_t last = marked.find_last_not_of(' ');
  if (last != std::string::npos && operand(marked[last])) marked += '*';
  marked += kPutIn + form + kPutInEnd;
  const std::size_t after = ascii.find_first_not_of(' ', next);
  if (after != std::string::npos && operand(ascii[after]) && ascii[after] != ')') marked += '*';
}
}  // namespace

// `text` with the primed names the key's steps write (the Euler-angle top's ω₁′, a component
// along the line-of-nodes basis: DefinedName "omega1'") as their exact forms in brackets, and
// the line that says so. Plain text only: the reader takes a prime after a name for no part of
// it, so they are found here, before it reads (ω₁', ω₁′, ω_1', w1', ω'₁; run together with a
// symbol, I₁ω₁'). Never one of the answer's own entries: (ω₁′, ω₂′, ω₃′) for ω′ is no working.
std::optional<Referenced> primed_named(const Context& ctx, const Answer& a,
                                       const std::string& text) {
  std::vector<const DefinedName*> names;
  for (const DefinedName& d : ctx.key.defined_names) {
    if (primed(d)) names.push_back(&d);
  }
  if (names.empty() || looks_like_latex(text)) return std::nullopt;
  const std::vector<std::string> own = own_forms(a);
  // The defined names, primed ones without their primes, declared so that a name run together
  // with them comes apart (I₂ω₂′).
  sym::SymbolTable with_bases = ctx.table;
  for (const DefinedName& d : ctx.key.defined_names) {
    const std::string base = primed(d) ? d.name.substr(0, d.name.size() - 1) : d.name;
    if (!with_bases.contains(base))
      with_bases.declare(base, name_latex(base), sym::SymbolSign::real);
  }
  const std::string ascii = names_apart(sym::to_ascii(text), with_bases);
  std::string marked;
  std::vector<bool> read(names.size(), false);
  std::size_t from = 0;
  for (const auto& [at, length] : identifiers(ascii)) {
    if (at < from) continue;
    const std::optional<PrimedWord> word = primed_word(ascii, at, length);
    if (!word) continue;
    const auto it = std::find_if(names.begin(), names.end(),
                                 [&](const DefinedName* d) { return d->name == word->spelled; });
    if (it == names.end() || std::find(own.begin(), own.end(), (*it)->symbolic) != own.end())
      continue;
    read[static_cast<std::size_t>(it - names.begin())] = true;
    marked += ascii.substr(from, at - from);
    put_in_as_factor(marked, (*it)->symbolic, ascii, word->end);
    from = word->end;
  }
  if (from == 0) return std::nullopt;
  return defined_read(names, read, marked + ascii.substr(from));
}

// `text` with the names an earlier answer gives its entries (key.hpp's named_entries: the
// asymmetric top's (Ω₂, Ω₃) about e₁, Euler's c₁, c₂, c₃) as their exact forms (names_put_in),
// and the line that says so. A name is the entry of the last answer before `a` that gives it:
// each axis's pair names its own Ω's, and the rate about that axis comes right after it
// (√(Ω₂ Ω₃) for rate_axis1). Not a name that is a symbol of the problem (Taylor's φ, θ, ψ).
std::optional<Referenced> entry_named(const Context& ctx, const Answer& a, const std::string& text,
                                      const std::string& message) {
  struct Entry {
    std::string name, form, shown;
    const Answer* of;
  };
  std::vector<Entry> entries;
  bool before_a = false;
  for (const auto& part : ctx.key.parts) {
    for (const auto& b : part.answers) {
      if (&b == &a) {
        before_a = true;
        break;
      }
      if (b.named_entries.empty() || b.symbolic.empty()) continue;
      const ListItems forms = list_items(b.symbolic);
      if (forms.items.size() != b.named_entries.size()) continue;
      for (std::size_t i = 0; i < forms.items.size(); ++i) {
        const std::string name = sym::to_ascii(b.named_entries[i]);
        if (ctx.table.contains(name)) continue;
        const auto same = std::find_if(entries.begin(), entries.end(),
                                       [&](const Entry& e) { return e.name == name; });
        if (same != entries.end()) entries.erase(same);  // the later answer's, in its order
        entries.push_back({name, forms.items[i], b.named_entries[i], &b});
      }
    }
    if (before_a) break;
  }
  std::vector<std::string> spelled;
  for (const Entry& e : entries) spelled.push_back(e.name);
  const auto index_of = [&](const std::string& word) { return index_spelled(spelled, word); };
  const std::optional<NamesPutIn> put =
      names_put_in(ctx, text, message, spelled, index_of,
                   [&](std::size_t i) { return kPutIn + entries[i].form + kPutInEnd; });
  if (!put) return std::nullopt;
  // The line: each name read with its form where the forms are one line's worth, and whose
  // entries they are, answer by answer in the key's order.
  std::string forms, yours, whose;
  std::size_t count = 0, length = 0;
  std::vector<const Answer*> answers;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (!put->read[i]) continue;
    length += entries[i].form.size();
    if (std::find(answers.begin(), answers.end(), entries[i].of) == answers.end())
      answers.push_back(entries[i].of);
  }
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (!put->read[i]) continue;
    forms += (forms.empty() ? "" : ", ") + entries[i].shown;
    if (length <= kLongestFormShown) forms += " = " + sym::to_unicode(entries[i].form);
    yours += (yours.empty() ? "" : ", ") + entries[i].shown;
    ++count;
  }
  for (const Answer* b : answers) {
    whose += fmt::format("{}{} (part {})", whose.empty() ? "" : " and ", b->name,
                         part_answering(ctx.key, b->name)->id);
  }
  return Referenced{brackets_put_in(put->text),
                    fmt::format("read with {}, {} the key's answer {}", forms,
                                count == 1 ? "an entry of" : "entries of", whose),
                    fmt::format(": right as far as your {} {}", yours, count == 1 ? "is" : "are")};
}

}  // namespace wobble::check::detail
