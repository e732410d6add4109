#include "check/refusal_hints.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "check/judge_internal.hpp"
#include "check/latex_answer.hpp"
#include "check/names_put_in.hpp"
#include "check/program_notation.hpp"
#include "check/symbol_values.hpp"
#include "check/unit_arithmetic.hpp"
#include "core/characters.hpp"
#include "symbolic/plain_text.hpp"
#include "symbolic/unicode_notation.hpp"
#include "symbolic/units.hpp"

namespace wobble::check::detail {

std::string misreading_hint(const Answer& a, const std::string& typed,
                            std::optional<std::size_t> entries_read) {
  if (a.value.shape != Value::Shape::scalar) {
    const std::size_t split = commas_between_digits(typed);
    const bool commas = entries_read && split > 0 && *entries_read == a.value.data.size() + split;
    return commas ? fmt::format(" ({})", kDecimalCommaHint) : "";
  }
  // "437,200 min": a lone comma before three digits may be either.
  if (const std::string grouped = decimal_comma_or_grouping(typed); !grouped.empty()) {
    const std::size_t point = grouped.size() - 3;
    return fmt::format(" (a decimal comma, or digits grouped? write {}.{} or {})",
                       grouped.substr(0, point), grouped.substr(point), grouped);
  }
  if (looks_like_decimal_comma(typed)) return fmt::format(" ({})", kDecimalCommaHint);
  const std::string ungrouped = digits_ungrouped(typed);
  return ungrouped.empty() ? "" : fmt::format(" (digits grouped? write {})", ungrouped);
}

std::string imaginary_hint(const Answer& a, const std::string& typed, const std::string& message) {
  if (a.value.shape != Value::Shape::scalar) return "";
  const bool rate = !a.unit.empty() &&
                    parse_unit(a.unit, "key unit of " + a.name).dim == std::array<int, 3>{0, 0, -1};
  const std::string growth =
      rate ? "; an imaginary frequency iλ is a growth e^(λt), and its rate is λ" : "";
  if (message.find("not real") != std::string::npos)
    return fmt::format(" (answers here are real{})", growth);
  // As the reader sees it: "4.995+0.j", NumPy's real root, has no imaginary unit left.
  const std::string s = as_programs_mean(sym::to_ascii(typed));
  const auto name_char = [&](std::size_t k) {
    return k < s.size() && (std::isalpha(static_cast<unsigned char>(s[k])) || s[k] == '_');
  };
  for (std::size_t k = 0; k < s.size(); ++k) {
    if ((s[k] != 'i' && s[k] != 'j') || (k > 0 && name_char(k - 1)) || name_char(k + 1) ||
        (k + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[k + 1]))))
      continue;
    return fmt::format(" (the {} reads as the unit vector {} along {}: answers here are real{})",
                       s[k], s[k] == 'i' ? "î" : "ĵ", s[k] == 'i' ? "x" : "y", growth);
  }
  return "";
}

namespace {

// What a name the textbook formulas use but the problem has no symbol for stands for: "a
// principal moment" for I3 in "(I3 - I1)/I1 ω cos α", or "" for any other name. Such a formula
// is the general one, not yet this body's; the name is no symbol, and the line says what to do.
std::string textbook_name_words(const std::string& name) {
  std::string plain;
  for (char c : name)
    if (c != '_') plain += c;
  if (plain.size() < 2 || !std::isdigit(static_cast<unsigned char>(plain.back())) ||
      plain.back() < '1' || plain.back() > '3')
    return "";
  const std::string letters = plain.substr(0, plain.size() - 1);
  if (letters == "I") return "a principal moment of the body";
  if (letters == "omega" || letters == "w") return "a component of ω along the body's axes";
  return "";
}

// The parameter `name` likely means, with its "0" added or taken away: ψ̇₀ for "psidot" where
// the problem gives the spin at t = 0 only (its key writes ψ̇₀, a student the rate ψ̇), θ for
// "theta0" or "theta_0" where it gives θ itself; nullptr if there is none.
const ParameterValue* parameter_but_for_zero(const Key& key, const std::string& name) {
  if (const ParameterValue* p = parameter_named(key, name + "0")) return p;
  for (const std::string zero : {"_0", "0"}) {
    if (name.size() > zero.size() && name.ends_with(zero)) {
      if (const ParameterValue* p = parameter_named(key, name.substr(0, name.size() - zero.size())))
        return p;
    }
  }
  return nullptr;
}

// What the statement or a question defines `name` as, in its own math: "A = C(1 − H)" for A
// where the Earth's statement writes "$A = C(1 - H)$" (its left side spelt as `name` is,
// name_spelling()); "" if no math of theirs begins so. A name a statement defines is no symbol:
// the line shows the definition to write in.
std::string definition_in_text(const Key& key, const std::string& name) {
  std::vector<const std::string*> texts{&key.statement};
  for (const auto& part : key.parts) texts.push_back(&part.question);
  const std::string spelling = name_spelling(name);
  for (const std::string* text : texts) {
    for (std::size_t open = text->find('$'); open != std::string::npos;) {
      const std::size_t close = text->find('$', open + 1);
      if (close == std::string::npos) break;
      const std::string math = text->substr(open + 1, close - open - 1);
      const std::size_t equals = math.find('=');
      // "$\theta = 0$" in "what happens at θ = 0?" is a case, not a definition: the right side
      // of one has a letter.
      const bool formula =
          equals != std::string::npos &&
          std::any_of(math.begin() + static_cast<std::ptrdiff_t>(equals), math.end(),
                      [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; });
      if (formula && name_spelling(math.substr(0, equals)) == spelling)
        return math_to_unicode(math);
      open = text->find('$', close + 1);
    }
  }
  return "";
}

// Whether the key reads `name` in `a`: an answer `a` may be written in terms of (p_ψ in the
// heavy top's energy), a name its steps write (I₃) but `a`'s own (ω₃ for ω₃), a convention's.
bool key_reads(const Context& ctx, const Answer& a, const std::string& name) {
  const std::string spelled = defined_spelling(name);
  return referable_answer(ctx, a, name) != nullptr ||
         std::any_of(ctx.key.defined_names.begin(), ctx.key.defined_names.end(),
                     [&](const DefinedName& d) { return d.name == spelled && d.name != a.name; }) ||
         std::any_of(ctx.key.convention_names.begin(), ctx.key.convention_names.end(),
                     [&](const ConventionName& c) { return c.name == name; });
}

// " (I0 is the answer to part (a): write it in the problem's symbols)" where `name` is another
// answer of the key, or "". An answer is no symbol: reading it as its key's value would let a
// name stand in for the working. A parameter but for its "0" is named next (not read: ψ̇ is
// ψ̇₀ at t = 0 only), then a name the statement defines, then answers the name begins, then a
// principal moment or a component of ω where the problem has no such symbol. Nothing for a
// name the key reads in `a` (key_reads): another one keeps the text from reading.
std::string name_hint(const Context& ctx, const Answer& a, const std::string& name) {
  if (ctx.table.contains(name) || key_reads(ctx, a, name)) return "";
  std::vector<std::string> named;  // "Omega" for Omega_body_rate, as a book writes Ω
  const std::string answer_named = name_in_key(ctx.key, name);  // ω₃ as \omega_3: omega_3
  for (const auto& part : ctx.key.parts) {
    for (const auto& answer : part.answers) {
      if (answer.name == answer_named) {
        return fmt::format(" ({} is the answer to part ({}): write it in the problem's symbols)",
                           answer.name, part.id);
      }
      if (answer.name.rfind(name + "_", 0) == 0)
        named.push_back(fmt::format("{} (part ({}))", answer.name, part.id));
    }
  }
  if (const ParameterValue* p = parameter_but_for_zero(ctx.key, name)) {
    return fmt::format(" ({} is no symbol here; the problem's is {}, the {})", name, shown_of(*p),
                       plain_text(p->description));
  }
  if (const std::string defined = definition_in_text(ctx.key, name); !defined.empty()) {
    return fmt::format(
        " ({} is no symbol here; the problem defines {}: write it in the "
        "problem's symbols)",
        name, defined);
  }
  if (!named.empty()) {
    return fmt::format(" ({} names {} here: write it in the problem's symbols)", name,
                       named.size() == 1
                           ? "the answer " + named[0]
                           : "the answers " + fmt::format("{}", fmt::join(named, ", ")));
  }
  // "ω̇₂ ω₃" on a right side of Euler's equations: a derivative where a component belongs.
  constexpr std::array<const char*, 3> kSubscripts{"₁", "₂", "₃"};
  for (std::size_t i = 0; i < 3; ++i) {
    const std::string n = std::to_string(i + 1);
    for (const std::string& spelt :
         {"omegadot" + n, "wdot" + n, "omega" + n + "dot", "w" + n + "dot"}) {
      if (name != spelt) continue;
      return fmt::format(
          " (dω{}/dt is no symbol here: in Euler's equations each right side is a coefficient "
          "times the other two components, dω₁/dt = c₁ ω₂ ω₃)",
          kSubscripts[i]);
    }
  }
  // ω₁ where the steps write ω₁′ only (the Euler-angle top's line-of-nodes basis), or ω₁′ in
  // the answer whose own entry it is (the reader refuses at the name, before its prime).
  const auto defined = [&](const std::string& spelled) {
    return std::find_if(ctx.key.defined_names.begin(), ctx.key.defined_names.end(),
                        [&](const DefinedName& d) { return d.name == spelled; });
  };
  const auto primed = defined(defined_spelling(name) + "'");
  if (primed != ctx.key.defined_names.end() &&
      defined(defined_spelling(name)) == ctx.key.defined_names.end()) {
    return fmt::format(
        " ({} is no symbol here; the key's steps write {}′ for {}: write it in the "
        "problem's symbols)",
        name, sym::to_unicode(defined_spelling(name)), primed->meaning);
  }
  const std::string words = textbook_name_words(name);
  if (words.empty()) return "";
  return fmt::format(" ({}, {}, is no symbol here: write it in the problem's symbols)", name,
                     words);
}

}  // namespace

std::string symbol_described(const Context& ctx, const std::string& name) {
  const ParameterValue* p = parameter_named(ctx.key, name);
  return p == nullptr || p->description.empty()
             ? "a symbol of the problem"
             : "the problem's symbol for the " + plain_text(p->description);
}

std::string unit_spelling_symbols(const Context& ctx, const std::string& unit_text) {
  std::vector<std::string> words;
  for (const auto& [at, length] : identifiers(unit_text)) {
    words.push_back(unit_text.substr(at, length));
    if (!ctx.table.contains(words.back())) return "";
  }
  if (words.empty()) return "";
  const std::string product = fmt::format("number*{}", fmt::join(words, "*"));
  if (words.size() > 1) {
    return fmt::format(
        "{} are also the problem's symbols: after a number they read as a unit; for the "
        "product, write the '*' ({})",
        fmt::join(words, ", "), product);
  }
  return fmt::format(
      "{} is also {}: after a number it reads as the unit; for the product, write the '*' ({})",
      words[0], symbol_described(ctx, words[0]), product);
}

namespace {

// "M R²/2 × 150 rad/s × cos θ₀": a unit inside an expression in the symbols (arithmetic in
// units alone is worked out, unit_arithmetic.hpp).
std::string unit_inside_hint(const std::string& unit) {
  return fmt::format(
      " ({} is a unit: an expression in the problem's symbols is in SI, its numbers without "
      "units; write the symbol whose value a number is, or one unit after the whole)",
      unit);
}

// The hint of the first name in `typed` that has one ("I₀ diag(1, 1, 2)", as question (a)
// writes I), the name the reader found undefined first (in "½I₃ω₃²" the text runs I₃ and ω₃
// together; the reader, its stars written in, names ω₃).
std::string first_name_hint(const Context& ctx, const Answer& a, const std::string& typed,
                            const std::string& message) {
  if (const std::string name = undefined_name(message); !name.empty()) {
    // "Ω_body + ω" for a vector: the name reads, what is written around it does not.
    if (key_reads(ctx, a, name)) {
      return fmt::format(
          " ({} reads here as the key writes it; the text around it does not read "
          "with it)",
          name);
    }
    const std::string hint = name_hint(ctx, a, name);
    if (!hint.empty()) return hint;
    if (is_unit(name)) return unit_inside_hint(name);
  }
  // The LaTeX reader names the symbol as drawn, "\Omega_{space}": its plain name is the one to
  // hint at, not a word of it ("space" begins space_cone_half_angle).
  if (const std::string drawn = latex_unknown_symbol(message); !drawn.empty()) {
    if (is_unit(drawn) && !ctx.table.contains(drawn)) return unit_inside_hint(drawn);
    std::string plain;
    for (const char c : drawn) {
      if (c != '\\' && c != '{' && c != '}' && c != ' ') plain += c == ',' ? '_' : c;
    }
    return name_hint(ctx, a, plain);
  }
  const std::string ascii = sym::to_ascii(typed);
  for (std::size_t i = 0; i < ascii.size();) {
    if (!std::isalpha(static_cast<unsigned char>(ascii[i])) ||
        (i > 0 && std::isdigit(static_cast<unsigned char>(ascii[i - 1])))) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < ascii.size() &&
           (std::isalnum(static_cast<unsigned char>(ascii[end])) || ascii[end] == '_'))
      ++end;
    const std::string hint = name_hint(ctx, a, ascii.substr(i, end - i));
    if (!hint.empty()) return hint;
    i = end;
  }
  return "";
}

}  // namespace

std::string names_read_too(const Context& ctx, const Answer& a) {
  std::vector<std::string> steps;
  for (const DefinedName& d : ctx.key.defined_names) {
    if (d.name == a.name || ctx.table.contains(d.name)) continue;
    // As the reader's list of symbols writes a Greek one: "omega3 (ω3)".
    const std::string drawn = sym::to_unicode(d.name);
    steps.push_back(drawn == d.name ? d.name : d.name + " (" + drawn + ")");
  }
  bool earlier = false;
  for (const auto& part : ctx.key.parts) {
    for (const auto& b : part.answers) earlier = earlier || referable_answer(ctx, a, b.name);
  }
  if (steps.empty() && !earlier) return "";
  const std::string names =
      steps.empty() ? "" : fmt::format("the key's steps' {}", fmt::join(steps, ", "));
  if (!earlier) return " (" + names + " read too)";
  const PartKey* part = part_answering(ctx.key, a.name);
  return " (" + names + (steps.empty() ? "the key's" : " and its") + " answers' names" +
         (part == nullptr ? "" : " up to part (" + part->id + ")") + " read too)";
}

bool name_refused(const std::string& message) {
  std::string name = undefined_name(message);
  if (name.empty()) name = latex_unknown_symbol(message);
  return !name.empty() && !is_unit(name);
}

namespace {

// Where norm(..) is refused ("norm(x~y)", "norm(omega)", a name mistyped in it): it is read
// only around a vector answer's name, as NumPy writes a vector's size; which names those are
// here, and abs(..) for a number's size.
std::string norm_hint(const Context& ctx, const Answer& a, const std::string& message) {
  if (quoted_after(message, "unknown function") != "norm") return "";
  std::vector<std::string> vectors;
  for (const auto& part : ctx.key.parts) {
    for (const auto& b : part.answers) {
      const Answer* r = referable_answer(ctx, a, b.name);
      if (r != nullptr && r->value.shape == Value::Shape::vector)
        vectors.push_back("norm(" + b.name + ")");
    }
  }
  const std::string around = vectors.empty() ? "no earlier answer here is a vector"
                                             : fmt::format("here {}", fmt::join(vectors, ", "));
  return fmt::format(
      " (norm(..) reads only around a vector answer's name: {}; a number's size is abs(..))",
      around);
}

}  // namespace

std::string answer_name_hint(const Context& ctx, const Answer& a, const std::string& typed,
                             const std::string& message) {
  if (std::string hint = first_name_hint(ctx, a, typed, message); !hint.empty()) return hint;
  if (std::string hint = norm_hint(ctx, a, message); !hint.empty()) return hint;
  return name_refused(message) ? names_read_too(ctx, a) : "";
}

std::optional<InputError> refused_beside_units(const Context& ctx, const Answer& a,
                                               const std::string& text,
                                               const std::string& refusal) {
  if (name_refused(refusal)) return std::nullopt;
  if (looks_like_latex(text)) {
    try {
      (void)latex_units_as_text(text, ctx.table, kField);
    } catch (const InputError& other) {
      const std::string name = latex_unknown_symbol(other.what());
      if (name.empty() || is_unit(name) || !is_unit(latex_unknown_symbol(refusal)))
        return std::nullopt;
      // Listing the problem's symbols as the first refusal does, not the units named.
      return InputError(problem_listed(other.what(), refusal).what() + names_read_too(ctx, a));
    }
    return std::nullopt;
  }
  // Refused for a unit read as a symbol or a function ("kg (0.05 m)^2"), or as the value's
  // unit with the name in it ("0.5 kg × Q": 'kg × Q').
  const auto unit_like = [](const std::string& word) {
    return is_unit(word) || units_run_together(word);  // "kgm"
  };
  const bool unit_as_name =
      unit_like(undefined_name(refusal)) || unit_like(quoted_after(refusal, "unknown function"));
  const std::string unit_text = sym::to_ascii(quoted_after(refusal, "cannot read the unit"));
  const std::string name = name_beside_units(text, ctx.table, kField);
  if (name.empty() && unit_text.empty()) {
    // "0.5 kgm (0.05 m) 150 rad/s": units run together, refused as the unit reader refuses them
    // after a number, not as an unknown function.
    for (const auto& [at, length] : identifiers(text)) {
      const std::string word = text.substr(at, length);
      if (!units_run_together(word) || ctx.table.contains(word)) continue;
      try {
        (void)parse_unit(word, kField);
      } catch (const InputError& run_together) {
        return run_together;
      }
    }
  }
  if (name.empty()) {
    // "0.5 kg (0.05 m)² 150 rad/s", "0.5 kg (0.05 m)^2 150 rad/s)": every name a unit; what
    // keeps it from reading is said.
    const std::optional<std::string> units =
        unit_as_name || !unit_text.empty() ? units_refusal(text, ctx.table, kField) : std::nullopt;
    return units ? std::optional<InputError>(InputError(*units)) : std::nullopt;
  }
  if (key_reads(ctx, a, name)) return std::nullopt;
  if (!unit_as_name && unit_text.find(name) == std::string::npos) return std::nullopt;
  try {
    (void)ctx.table.parse(name, kField);
  } catch (const InputError& alone) {
    // The reader's words for the name alone ("undefined symbol 'Q'; the symbols here are ..",
    // with what it may have meant), said of the answer as typed.
    const std::string said = alone.what();
    const std::size_t at = said.find("undefined symbol");
    if (at == std::string::npos) return std::nullopt;
    return InputError(fmt::format("{}: cannot read expression \"{}\": {}{}", kField,
                                  printable(text, kQuotedCharacters), said.substr(at),
                                  names_read_too(ctx, a)));
  }
  return std::nullopt;
}

}  // namespace wobble::check::detail
