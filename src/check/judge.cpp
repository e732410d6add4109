#include "check/judge.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <exception>
#include <initializer_list>
#include <optional>
#include <string_view>
#include <utility>

#include "check/absent_answer.hpp"
#include "check/answer_reading.hpp"
#include "check/answer_shape.hpp"
#include "check/answer_sides.hpp"
#include "check/axes_judge.hpp"
#include "check/brackets.hpp"
#include "check/diagnosis.hpp"
#include "check/euler_equations.hpp"
#include "check/expression_dimension.hpp"
#include "check/inequality.hpp"
#include "check/judge_internal.hpp"
#include "check/latex_answer.hpp"
#include "check/latex_vocabulary.hpp"
#include "check/lost_power.hpp"
#include "check/names_put_in.hpp"
#include "check/plus_minus.hpp"
#include "check/program_notation.hpp"
#include "check/refusal_hints.hpp"
#include "check/submission.hpp"
#include "check/unit_arithmetic.hpp"
#include "check/written_forms.hpp"
#include "core/characters.hpp"
#include "core/inertia.hpp"
#include "core/input_error.hpp"
#include "symbolic/expression_guard.hpp"
#include "symbolic/unicode_notation.hpp"
#include "symbolic/units.hpp"
#include "symbolic/value_text.hpp"

namespace wobble::check {

using detail::answer_name_hint;
using detail::answer_referenced;
using detail::approximations_as_equal;
using detail::check_shape;
using detail::convention_named;
using detail::defined_named;
using detail::defined_spelling;
using detail::entry_named;
using detail::function_of_answer;
using detail::imaginary_hint;
using detail::in_plane_of_two;
using detail::is_one_name;
using detail::Judge;
using detail::judge_symbolic;
using detail::kField;
using detail::latex_unknown_symbol;
using detail::listed_layout;
using detail::misreading_hint;
using detail::moments_on_diagonal;
using detail::name_refused;
using detail::names_read_too;
using detail::part_answering;
using detail::primed_named;
using detail::problem_listed;
using detail::quoted_after;
using detail::referable_answer;
using detail::Referenced;
using detail::refused_beside_units;
using detail::root_of_squared_label;
using detail::sides;
using detail::SquaredLabel;
using detail::symbol_described;
using detail::undefined_name;
using detail::unit_spelling_symbols;

namespace {
// The sides of '=' judged at most: a key's line "closed form = value", its name dropped.
constexpr std::size_t kMostSides = 2;

}  // namespace

bool angles_up_to_turns(const Answer& a) {
  return a.kind == AnswerKind::vector && a.unit == "rad";
}

namespace detail {
OnKeysTurns on_keys_turns(const Judge& j, const std::vector<double>& got) {
  const Answer& a = j.a;
  OnKeysTurns out{false, {}, got};
  if (!angles_up_to_turns(a) || got.size() != a.value.data.size()) return out;
  bool every = true;
  for (std::size_t i = 0; i < got.size(); ++i) {
    const double key = a.value.data[i], turns = std::round((got[i] - key) / (2 * M_PI));
    const double moved = got[i] - turns * (2 * M_PI);
    if (std::abs(turns) == 1.0) out.for_diagnosis[i] = moved;
    // Significant figures are of the number typed (5.93 for 340°): it must round as the key's
    // value in that range does. A relative tolerance is of the angle itself, in the key's range
    // (-20.3° and 339.7° alike are 1.5% off -20°).
    const bool right =
        j.opt.sigfigs ? j.close(got[i], key + turns * (2 * M_PI)) : j.close(moved, key);
    every = every && right;
    if (turns == 0.0 || !right) continue;
    out.for_diagnosis[i] = key;  // right: the diagnosis is about the other entries
    out.moved.push_back(entry_name(a, i));
  }
  out.right = every && !out.moved.empty();
  // Only where every entry is then near the key's: 1000 times (40°, 30°, 70°) has 40° again in
  // 40000°, yet is a power of ten off, which the typed values show.
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (!(std::abs(out.for_diagnosis[i] - a.value.data[i]) <= M_PI / 2)) {
      out.for_diagnosis = got;
      break;
    }
  }
  return out;
}

std::string whole_turns_note(const std::vector<std::string>& moved) {
  std::string names;
  for (std::size_t i = 0; i < moved.size(); ++i)
    names += (i == 0 ? "" : i + 1 == moved.size() ? " and " : ", ") + moved[i];
  const bool one = moved.size() == 1;
  return " (" + names + (one ? " differs" : " differ") +
         " from the key's by whole turns: the same angle" + (one ? ")" : "s)");
}

std::optional<std::string> other_branch(const Judge& j, const std::vector<double>& got) {
  // At θ = 0 or π only φ ± ψ is defined, and any branch is another reading.
  if (!angles_up_to_turns(j.a) || got.size() != 3 || !(j.a.value.data[1] > 0.0) ||
      !(j.a.value.data[1] < M_PI) || j.close(0.0, j.a.value.data[1]))
    return std::nullopt;
  const std::vector<double> other{got[0] + M_PI, -got[1], got[2] + M_PI};
  if (!j.all_close(other, j.a.value.data) && !on_keys_turns(j, other).right) return std::nullopt;
  const std::string middle = entry_name(j.a, 1);
  return fmt::format(
      "these angles turn the body as the key's do, on the other branch, with {} negative: {} = "
      "arccos R₃₃ lies in [0, π], and then {} and {} are each half a turn from yours",
      middle, middle, entry_name(j.a, 0), entry_name(j.a, 2));
}

// Principal axes by meaning (axes_judge.hpp): the sine of the angle within the tolerance.
Verdict judge_axes_answer(const Judge& j, const std::vector<double>& got) {
  const auto& moments = j.a.axis_moments;
  if (moments.size() != 3 || j.a.value.data.size() != 9) {
    throw std::logic_error("check: " + j.a.name + " without the moments of its axes");
  }
  Mat3 axes;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) axes(r, c) = j.a.value.data[static_cast<std::size_t>(3 * r + c)];
  }
  const Vec3 lambda(moments[0], moments[1], moments[2]);
  const double tol = j.angle_tolerance();
  const AxesFinding f = judge_axes(got, axes, lambda, tol, j.layout);
  if (f.correct) {
    // An axis is a direction: (1, 1, 0) is right for (1, 1, 0)/√2, and the verdict says so.
    return {true,
            "correct: " + j.a.name + " (" + f.how + ", in any order, each up to sign" +
                (f.unit_lengths ? ")" : " and length; the key's axes are unit vectors)"),
            {}};
  }
  Verdict v{false, "incorrect: " + j.a.name, f.problems};
  // Vectors listed one by one that are the axes read down instead: the rows of the matrix an
  // eigenvector routine returns, whose columns are the axes (numpy's eigh(I)[1]).
  // (Labelled vectors, e1 = (..), come as the columns of their matrix: the other way is rows.)
  const AxesLayout read_across =
      j.layout == AxesLayout::rows ? AxesLayout::columns : AxesLayout::rows;
  if (j.layout != AxesLayout::rows_or_columns &&
      judge_axes(got, axes, lambda, tol, read_across).correct) {
    v.feedback.insert(v.feedback.begin(),
                      "these are the rows of the axes' matrix: an eigenvector routine (numpy's "
                      "eigh, MATLAB's eig) gives the axes as its columns; list the columns");
  }
  return v;
}

// What the judge found, as data for the diagnosis (diagnosis.hpp).
std::vector<std::string> diagnose(const Judge& j, const Unit& key_unit,
                                  const std::vector<double>& v, const std::vector<double>& k) {
  const Finding f{j.a, j.ctx.key, v, k, key_unit,
                  [&j](double typed, double expected) { return j.close(typed, expected); },
                  j.scale};
  return check::diagnose(f);
}
}  // namespace detail

double zero_scale(const Key& key, const Answer& a) {
  double s = 0.0;
  for (const auto& part : key.parts) {
    for (const auto& b : part.answers) {
      if (b.unit != a.unit) continue;
      for (double x : b.value.data) s = std::max(s, std::abs(x));
    }
  }
  return s > 0.0 ? s : 1.0;
}

Options options_for(const Answer& a, const Options& options) {
  Options opt = options;
  if (!options.rel_tol_given && a.check_tolerance) opt.rel_tol = *a.check_tolerance;
  return opt;
}

std::string nothing_after(const std::string& field, const std::string& separator,
                          const std::string& line) {
  return fmt::format("{}: nothing after the '{}' in \"{}\"; the answer goes after it", field,
                     separator, line);
}

std::string without_option(const std::string& message) {
  const std::string prefix = kField + ": ";
  if (message.rfind(prefix, 0) == 0) return message.substr(prefix.size());
  // "--answer[0]: ..", "--answer[1][2]: ..": an entry, counted from 1 as people count.
  if (message.rfind(kField + "[", 0) != 0) return message;
  std::vector<std::string> indices;
  std::size_t at = kField.size();
  while (at < message.size() && message[at] == '[') {
    const std::size_t close = message.find(']', at);
    if (close == std::string::npos) return message;
    const std::string digits = message.substr(at + 1, close - at - 1);
    if (digits.empty() || digits.size() > 6 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
      return message;
    indices.push_back(std::to_string(std::stoul(digits) + 1));
    at = close + 1;
  }
  if (message.compare(at, 2, ": ") != 0 || indices.empty() || indices.size() > 2) return message;
  const std::string entry =
      indices.size() == 1 ? indices[0] : "(" + indices[0] + ", " + indices[1] + ")";
  return "entry " + entry + ": " + message.substr(at + 2);
}

std::string name_spelling(const std::string& written) {
  const std::string s = sym::to_ascii(written);
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\') {  // \mathrm, \text: a wrapper, not part of the name
      std::size_t j = i + 1;
      while (j < s.size() && std::isalpha(static_cast<unsigned char>(s[j]))) ++j;
      const std::string cmd = s.substr(i + 1, j - i - 1);
      if (text_wrappers().count(cmd)) i = j - 1;
      continue;
    }
    if (std::isalnum(static_cast<unsigned char>(s[i]))) out += s[i];
  }
  return out;
}

namespace {
// The prime as typed, "'", as set, "′" (U+2032), or as a word processor turns "'", "’". A
// spelling drops it, yet it makes another name (E′, the heavy top's level, is not its energy E):
// names are alike only if both have a prime or neither has.
bool primed(const std::string& name) {
  return name.find('\'') != std::string::npos || name.find("′") != std::string::npos ||
         name.find("’") != std::string::npos;
}
}  // namespace

NamesInKey::NamesInKey(const Key& key) {
  const auto add = [&](const std::string& written, const std::string& answer) {
    spelt_[{name_spelling(written), primed(written)}].insert(answer);
  };
  for (const auto& part : key.parts) {
    exact_.insert(part.id);
    for (const auto& answer : part.answers) {
      exact_.insert(answer.name);
      add(answer.name, answer.name);
      for (const std::string& step_name : answer.step_names) add(step_name, answer.name);
    }
    // An answer that does not exist at these values is named as where it exists ("φ̇_slow").
    for (const auto& absent : part.absent) {
      exact_.insert(absent);
      add(absent, absent);
    }
  }
}

std::string NamesInKey::operator()(const std::string& written) const {
  if (written.empty() || exact_.count(written) != 0) return written;
  const auto found = spelt_.find({name_spelling(written), primed(written)});
  return found != spelt_.end() && found->second.size() == 1 ? *found->second.begin() : written;
}

// As NamesInKey does, without building its maps: one name is looked up many times a check.
std::string name_in_key(const Key& key, const std::string& written) {
  if (written.empty()) return written;
  for (const auto& part : key.parts) {
    if (part.id == written) return written;
    for (const auto& answer : part.answers) {
      if (answer.name == written) return written;
    }
    for (const auto& absent : part.absent) {
      if (absent == written) return written;
    }
  }
  const std::string spelling = name_spelling(written);
  const bool written_primed = primed(written);
  const auto alike = [&](const std::string& name) {
    return primed(name) == written_primed && name_spelling(name) == spelling;
  };
  std::string found;
  int matches = 0;
  for (const auto& part : key.parts) {
    for (const auto& answer : part.answers) {
      if (alike(answer.name) ||
          std::any_of(answer.step_names.begin(), answer.step_names.end(), alike)) {
        found = answer.name;
        ++matches;
      }
    }
    for (const auto& absent : part.absent) {
      if (alike(absent)) {
        found = absent;
        ++matches;
      }
    }
  }
  return matches == 1 ? found : written;
}

namespace {
Verdict judge_text(const Context& ctx, const Answer& a, const std::string& text,
                   const Options& options);

// "M R²/2 × 150 rad/s": an expression in the problem's symbols (in SI) with a unit after it that
// is not the whole's but a number's in it, where the symbols' dimension and the unit's make the
// answer's and the unit's alone does not: judged as that (the number most likely a
// parameter's value where the key has its symbol, which the feedback names), with a line that
// says how it was read; nullopt where it is not so.
std::optional<Verdict> unit_of_a_number_in_it(const Context& ctx, const Answer& a,
                                              const std::string& text, const ReadAnswer& p,
                                              const Unit& key_unit, const Options& opt,
                                              AxesLayout layout) {
  if (!p.symbolic || !p.unit) return std::nullopt;
  // An angle unit where the answer is a pure number that is no angle is wrong whatever it is of.
  if (p.unit->angle && key_unit.dim == std::array<int, 3>{0, 0, 0} && !key_unit.angle)
    return std::nullopt;
  for (const auto& e : p.value.entries) {
    if (e.is_zero()) continue;
    const auto d = expression_dimension(e, ctx.key);
    if (!d || d->mixed || !d->dim) return std::nullopt;
    for (std::size_t k = 0; k < 3; ++k) {
      if ((*d->dim)[k] + p.unit->dim[k] != key_unit.dim[k]) return std::nullopt;
    }
  }
  ReadAnswer inside = p;
  const GiNaC::ex factor = ctx.table.parse(p.unit->to_si_exact, "unit " + p.unit->text);
  for (auto& e : inside.value.entries) e = e * factor;
  inside.unit.reset();
  inside.unit_on_numbers = true;  // its dimension is the answer's, as found above
  Verdict v = judge_symbolic(ctx, a, text, inside, opt, layout);
  v.feedback.push_back(fmt::format(
      "read with {} as the unit of a number in it, not of the whole (with the problem's symbols "
      "in SI, the whole is then in {})",
      p.unit->text, asked_unit(a).empty() ? "no unit" : asked_unit(a)));
  return v;
}

// A number in a unit of another dimension than the key's: so said, with what the student may
// have meant where the numbers tell it ("2.177 rad/s" for a period of 2.177 s: the number right,
// the unit another's; "0.11 s" for a rate of 9.09 1/s: its reciprocal).
Verdict wrong_unit(const Context& ctx, const Answer& a, const ReadAnswer& p, const Unit& key_unit,
                   const Options& opt, AxesLayout layout) {
  Verdict v;
  v.line = "incorrect: " + a.name + " has the wrong dimension";
  v.wrong_dimension = true;
  v.feedback.push_back("you gave " + sym::to_unicode(p.unit->text) + " (" +
                       p.unit->dimension_words() + "); the answer is in " +
                       (asked_unit(a).empty() ? "no unit" : sym::to_unicode(asked_unit(a))) + " (" +
                       key_unit.dimension_words() + ")");
  if (const std::string symbols = unit_spelling_symbols(ctx, p.unit->text); !symbols.empty())
    v.feedback.push_back(symbols);
  if (p.symbolic) return v;
  const Judge j{ctx, a, opt, zero_scale(ctx.key, a), layout};
  std::vector<double> typed;
  try {
    for (const auto& e : p.value.entries) typed.push_back(sym::evaluate(e, GiNaC::lst{}, kField));
  } catch (const InputError&) {
    return v;  // "sqrt(-83.4) kg": no number to say more of; the dimension is what is wrong
  }
  if (j.all_close(typed, a.value.data)) {
    const std::string numbers = typed.size() == 1 ? "the number" : "the numbers";
    v.feedback.push_back(a.unit.empty() ? "without a unit " + numbers + " would be right"
                                        : "in " + sym::to_unicode(asked_unit(a)) + " " + numbers +
                                              " would be right");
  } else if (typed.size() == 1) {
    if (auto reciprocal = reciprocal_mistake(a, typed[0], &*p.unit, key_unit, j.scale,
                                             [&](double x, double k) { return j.close(x, k); }))
      v.feedback.push_back(*reciprocal);
  }
  return v;
}

// An answer read, `p`, judged against `a`.
Verdict judge_read(const Context& ctx, const Answer& a, const std::string& text,
                   const ReadAnswer& p, const Options& opt, AxesLayout layout) {
  check_shape(a, p, text);
  const Unit key_unit = a.unit.empty() ? Unit{} : parse_unit(a.unit, "key unit of " + a.name);
  double to_key = 1.0;
  if (p.unit) {
    // Radians are pure numbers (symbolic/symbolic/units.hpp): rad/s is 1/s. An angle unit is wrong
    // only where the key is a pure number that is no angle.
    const bool pure_number_key = key_unit.dim == std::array<int, 3>{0, 0, 0} && !key_unit.angle;
    if (!p.unit->same_dimension(key_unit) || (p.unit->angle && pure_number_key)) {
      if (auto inside = unit_of_a_number_in_it(ctx, a, text, p, key_unit, opt, layout))
        return std::move(*inside);
      return wrong_unit(ctx, a, p, key_unit, opt, layout);
    }
    to_key = p.unit->to_si / key_unit.to_si;
  }
  // An expression's unit, if any, is an SI one (read_answer), and so is every key's.
  if (p.symbolic) return judge_symbolic(ctx, a, text, p, opt, layout);
  std::vector<double> got;
  try {
    for (const auto& e : p.value.entries)
      got.push_back(sym::evaluate(e, GiNaC::lst{}, kField) * to_key);
  } catch (const InputError& e) {
    throw InputError(e.what() + imaginary_hint(a, text, e.what()));  // "sqrt(-83.4)"
  }
  const Judge j{ctx, a, opt, zero_scale(ctx.key, a), layout};
  if (a.kind == AnswerKind::principal_axes && got.size() == 9) return judge_axes_answer(j, got);
  std::vector<double> compare = got;
  if (a.kind == AnswerKind::principal_moments) std::sort(compare.begin(), compare.end());
  if (j.all_close(compare, a.value.data)) {
    const std::string note =
        a.kind == AnswerKind::principal_moments && compare != got ? " (in any order)" : "";
    return {true, "correct: " + a.name + note, {}};
  }
  if (const detail::OnKeysTurns turned = detail::on_keys_turns(j, compare);
      turned.for_diagnosis != compare) {
    if (turned.right)
      return {true, "correct: " + a.name + detail::whole_turns_note(turned.moved), {}};
    // A known mistake is named from what was typed (degrees for radians); else an entry one
    // turn off is judged from the key's range.
    const auto mistakes = wrong_answers(a, ctx.key, key_unit);
    if (std::none_of(mistakes.begin(), mistakes.end(),
                     [&](const WrongAnswer& w) { return j.all_close(compare, w.values); }))
      compare = turned.for_diagnosis;
  }
  if (const auto branch = detail::other_branch(j, got))
    return {false, "incorrect: " + a.name, {*branch}};
  if (const auto degrees = detail::degrees_in_numbers(j, text, to_key))
    return {false, "incorrect: " + a.name, {*degrees}};
  // "0.4593" for a period of 2.177 s: a frequency, its unit left off.
  if (!p.unit && got.size() == 1) {
    if (auto reciprocal = reciprocal_mistake(a, got[0], nullptr, key_unit, j.scale,
                                             [&](double x, double k) { return j.close(x, k); }))
      return {false, "incorrect: " + a.name, {*reciprocal}};
  }
  return {false, "incorrect: " + a.name, diagnose(j, key_unit, compare, a.value.data)};
}

// `text` with each of `words` that follows a number or a closing bracket written as a factor:
// "-3/4 h ẑ" -> "-3/4*h ẑ", "(0, 0, -0.75 h)" -> "(0, 0, -0.75*h)", "-0.75h ẑ" -> "-0.75*h ẑ",
// "-\frac{3}{4} h \hat{z}" -> "-\frac{3}{4}*h \hat{z}".
std::string words_as_factors(const std::string& text, const std::vector<std::string>& words) {
  const auto in_name = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  };
  std::string out;
  std::size_t copied = 0;
  for (std::size_t at = 0; at < text.size();) {
    // A letter group here: at the text's start, after no name's letter, or glued to a number.
    const bool starts = std::isalpha(static_cast<unsigned char>(text[at])) &&
                        (at == 0 || !in_name(text[at - 1]) ||
                         std::isdigit(static_cast<unsigned char>(text[at - 1])));
    if (!starts) {
      ++at;
      continue;
    }
    std::size_t end = at;
    while (end < text.size() && in_name(text[end])) ++end;
    if (std::find(words.begin(), words.end(), text.substr(at, end - at)) != words.end()) {
      // Spaces before it, LaTeX's too ("0.75\,h"); then a number, a bracket or a LaTeX
      // fraction's brace ("\frac{3}{4} h").
      std::size_t before = at;
      while (before > copied) {
        if (text[before - 1] == ' ' || text[before - 1] == '~') {
          --before;
        } else if (before >= copied + 2 && text[before - 2] == '\\' &&
                   std::string_view(",;:! ").find(text[before - 1]) != std::string_view::npos) {
          before -= 2;
        } else {
          break;
        }
      }
      const char c = before > copied ? text[before - 1] : ' ';
      if (std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == ')' || c == '}') {
        out += text.substr(copied, before - copied) + "*";
        copied = at;
      }
    }
    at = end;
  }
  return out + text.substr(copied);
}

// "-3/4 h ẑ", "(0, 0, -0.75 h)" for the cone's centre, h its height: after a number h is hours,
// the wrong dimension here. Where every letter group of that unit is a symbol of the problem
// and the text read with them as factors has the answer's dimension, that reading is judged,
// and the feedback says so first. (Where the unit's dimension is right, "0.5 m" stays half a
// metre; a unit in the wrong dimension is no reading the student can have meant.)
std::optional<Verdict> judged_as_product(const Context& ctx, const Answer& a,
                                         const std::string& text, const Unit& unit,
                                         const Options& options, AxesLayout layout) {
  if (unit_spelling_symbols(ctx, unit.text).empty()) return std::nullopt;
  std::vector<std::string> words;
  for (const auto& [at, length] : identifiers(unit.text))
    words.push_back(unit.text.substr(at, length));
  const std::string product = words_as_factors(text, words);
  if (product == text) return std::nullopt;
  try {
    ReadAnswer q = read_answer(product, ctx.table, kField);
    if (!q.as_written_error.empty()) return std::nullopt;
    (void)moments_on_diagonal(a, q.value);
    Verdict v = judge_read(ctx, a, product, q, options_for(a, options), layout);
    if (v.wrong_dimension) return std::nullopt;
    // LaTeX's spaces (a thin space, a tie) shown as the spaces they are.
    std::string shown = product;
    for (const std::string space : {"\\,", "\\;", "\\:", "\\ ", "~"}) {
      for (auto at = shown.find(space); at != std::string::npos; at = shown.find(space, at + 1))
        shown.replace(at, space.size(), " ");
    }
    v.feedback.insert(
        v.feedback.begin(),
        fmt::format("read as {}, {} {}: after a number alone it would be the unit", trim(shown),
                    words.size() == 1 ? words[0] : fmt::format("{}", fmt::join(words, ", ")),
                    words.size() == 1 ? symbol_described(ctx, words[0])
                                      : std::string("the problem's symbols")));
    return v;
  } catch (const InputError&) {
    return std::nullopt;
  }
}

Verdict judge_as_written(const Context& ctx, const Answer& a, const std::string& text,
                         const Options& options, AxesLayout labelled) {
  const AxesLayout layout =
      labelled != AxesLayout::rows_or_columns ? labelled : listed_layout(text);
  // "15,5deg" reads as two entries, one without a unit: say what was more likely meant.
  const auto refused = [&](const std::string& message) {
    return InputError(message + misreading_hint(a, text, std::nullopt) +
                      answer_name_hint(ctx, a, text, message) + imaginary_hint(a, text, message));
  };
  // A number wanted: bare i, j and k are names of the student's own ("k²", "k'^2", "4K(k)/λ",
  // k the elliptic modulus), no unit vectors, and the text is refused as it reads as written.
  const bool number = a.value.shape == Value::Shape::scalar;
  ReadAnswer p = [&] {
    try {
      return read_answer(text, ctx.table, kField);
    } catch (const UnitVectorsUnread& e) {
      throw refused(number && !e.as_written.empty() ? e.as_written : e.what());
    } catch (const InputError& e) {
      throw refused(e.what());
    }
  }();
  if (number && !p.as_written_error.empty()) throw refused(p.as_written_error);
  // "diag(0.569, 4.209, 4.556)": the tensor in its principal axes, whose diagonal holds them.
  const bool diagonal_read = moments_on_diagonal(a, p.value);
  const bool in_plane = in_plane_of_two(a, p.value);
  Verdict v = [&] {
    try {
      return judge_read(ctx, a, text, p, options_for(a, options), layout);
    } catch (const InputError& e) {
      // An expression that reads but is imaginary at the set values, as the root of Ω₃ Ω₁ about
      // the unstable axis is: the same hint as for a number.
      if (std::string_view(e.what()).find("not real") == std::string_view::npos) throw;
      throw InputError(e.what() + imaginary_hint(a, text, e.what()));
    }
  }();
  if (v.wrong_dimension && p.unit) {
    if (auto product = judged_as_product(ctx, a, text, *p.unit, options, layout)) return *product;
  }
  if (diagonal_read)
    v.feedback.push_back("read as the moments on its diagonal (the tensor in its principal axes)");
  if (in_plane) {
    const std::vector<std::string> axes = entry_names(a);
    v.feedback.push_back(
        fmt::format("read with {0} = 0: the key's {0} is zero", axes.size() == 3 ? axes[2] : "z"));
  }
  return v;
}

// judge_as_written, and where a wrong answer calls EllipticK or EllipticE, whether it is right
// with their arguments read as the parameter m = k² (Mathematica's and SciPy's): then that is
// the one line of feedback.
Verdict judge_one(const Context& ctx, const Answer& a, const std::string& text,
                  const Options& options, AxesLayout labelled = AxesLayout::rows_or_columns) {
  Verdict v = judge_as_written(ctx, a, text, options, labelled);
  if (v.correct) return v;
  if (const auto of_parameter = elliptic_of_parameter(text)) {
    try {
      if (judge_as_written(ctx, a, *of_parameter, options, labelled).correct) {
        v.feedback = {
            "EllipticK and EllipticE take the modulus k here, as the key writes them: your "
            "arguments are the parameter m = k² (Mathematica's EllipticK[m], SciPy's ellipk(m)); "
            "write EllipticK(sqrt(m)), or EllipticK[m] as Mathematica does"};
      }
    } catch (const InputError&) {
      // sqrt of a negative argument: no such reading
    }
  }
  // "ArcTan[Sin[α], 2 Cos[α]]": atan2's order in Mathematica's call, or the other way round.
  for (const auto& swapped : arctangents_swapped(text)) {
    try {
      if (!judge_as_written(ctx, a, swapped.text, options, labelled).correct) continue;
    } catch (const InputError&) {
      continue;
    }
    v.feedback = {swapped.name == "ArcTan"
                      ? "your ArcTan's arguments are the other way round: Mathematica's ArcTan[x, "
                        "y] takes x first (it is atan2(y, x))"
                      : "your " + swapped.name + "'s arguments are the other way round: " +
                            swapped.name + "(y, x) takes y first (the angle of the point (x, y))"};
    break;
  }
  return v;
}

// How a number worked out with its units was read, for its line: "2π rad / (303.6 days) =
// 2.395e-07 rad/s".
std::string worked_out_line(const UnitsWorkedOut& worked) {
  std::string line =
      fmt::format("{} = {:.4g}{}{}", sym::to_unicode(worked.grouped), worked.value_si,
                  worked.unit.empty() ? "" : " ", sym::to_unicode(worked.unit));
  // "(m after a number as the unit m, not the problem's symbol m)".
  for (const std::string& name : worked.symbols_as_units)
    line +=
        fmt::format(" ({0} after a number as the unit {0}, not the problem's symbol {0})", name);
  return line;
}

// A number, or a vector's entries, worked out with its units (unit_arithmetic.hpp) judged as
// the numbers they work out to, with a line that says how they were read; nullopt where the
// text has no unit inside arithmetic.
std::optional<Verdict> judged_worked_out(const Context& ctx, const Answer& a,
                                         const std::string& text, const Options& options) {
  if (a.value.shape == Value::Shape::scalar) {
    const auto worked = units_worked_out(text, ctx.table, kField, a.unit);
    if (!worked) return std::nullopt;
    Verdict v = judge_one(ctx, a, worked->text, options);
    v.feedback.push_back("read with its units worked out: " + worked_out_line(*worked));
    return v;
  }
  if (a.value.shape != Value::Shape::vector) return std::nullopt;
  const auto worked = entries_worked_out(text, ctx.table, kField, a.unit);
  if (!worked) return std::nullopt;
  Verdict v = judge_one(ctx, a, worked->text, options);
  std::vector<std::string> lines;
  for (const auto& [i, entry] : worked->worked)
    lines.push_back(fmt::format("entry {}: {}", i + 1, worked_out_line(entry)));
  v.feedback.push_back("read with its units worked out, " +
                       fmt::format("{}", fmt::join(lines, "; ")));
  return v;
}

// Where the quote that starts at `at` in a refusal ends: its closing '"', before ": " or, where
// a name was put in, ", read with" ("\"I3 + (1,2)\", read with I3 = M·R²/2 ..: a ','"); npos
// where `at` is.
std::size_t quote_end(const std::string& refusal, std::size_t at) {
  if (at == std::string::npos) return at;
  return std::min(refusal.find("\": ", at), refusal.find("\", read with ", at));
}

// judge_one for the whole answer or the value after a label: an answer in terms of an earlier
// one, "I₀ diag(2, 2, 1)", "π/Ω_space_rate", is read with the key's closed form for it
// (answer_referenced), and so are the names the key itself reads (the steps' I₁ and ω₁′, a
// convention's, an entry's), and arithmetic with units is worked out (unit_arithmetic.hpp);
// the feedback says so. Not for a side that may be a label or an
// inequality's variable ("cos θ_min = ..", "118.8 rad/s ≤ ω₃"): there a name is the student's.
Verdict judge_referring(const Context& ctx, const Answer& a, const std::string& text,
                        const Options& options, AxesLayout labelled = AxesLayout::rows_or_columns) {
  try {
    return judge_one(ctx, a, text, options, labelled);
  } catch (const InputError& e) {
    if (auto worked = judged_worked_out(ctx, a, text, options)) return std::move(*worked);
    std::optional<Referenced> referenced = primed_named(ctx, a, text);
    if (!referenced) referenced = convention_named(ctx, text, e.what());
    if (!referenced) referenced = defined_named(ctx, a, text, e.what());
    if (!referenced) referenced = entry_named(ctx, a, text, e.what());
    // A name the key itself reads (a convention's, its steps', an entry's), unlike an answer's
    // name, is no longer what keeps the answer from reading.
    const bool key_names = referenced.has_value();
    try {
      if (!referenced) referenced = answer_referenced(ctx, a, text, e.what());
    } catch (const InputError& then) {
      // "\frac{p_\psi}{Q}": the LaTeX reader, the names put in, refuses another symbol.
      throw InputError(then.what() + (name_refused(then.what()) ? names_read_too(ctx, a) : ""));
    }
    if (!referenced) {
      if (auto beside = refused_beside_units(ctx, a, text, e.what())) throw *beside;
      throw;
    }
    const std::exception_ptr refusal = std::current_exception();
    Verdict v;
    try {
      v = judge_referring(ctx, a, referenced->text, options, labelled);
    } catch (const InputError& then) {
      // "4K(k)/λ": k reads, λ does not. The name that keeps it from reading is said, in the
      // expression as typed (the refusal's quote, not the closed form put in).
      const std::string other = undefined_name(then.what());
      const std::string first = e.what(), second = then.what();
      const std::string quote = "expression \"";
      const std::size_t at1 = first.find(quote), at2 = second.find(quote);
      const std::size_t end1 = quote_end(first, at1), end2 = quote_end(second, at2);
      // The same entry refused both times ("entry 1: "), or the quote is another entry's.
      const bool same_entry = end1 != std::string::npos && end2 != std::string::npos &&
                              first.compare(0, at1, second, 0, at2) == 0;
      // "150 rad/s I₃": the names read for a word taken as a unit, but the rest does not read
      // as an expression; the refusal of the unit, as typed, says more than the forms put in.
      const bool unit_refused = !quoted_after(first, "cannot read the unit").empty();
      if (unit_refused && !other.empty()) std::rethrow_exception(refusal);
      // "I₃ω₃''", "Ω_body + ω" for a vector: the names read, the text around them does not;
      // said of the text as typed, not of the forms put in.
      const bool quote_typed = same_entry && other.empty();
      // The key's names read, what still keeps the answer from reading is said: a vector for
      // a matrix or a number, or another entry's unknown name.
      if (key_names && !quote_typed && (other.empty() || !same_entry)) throw;
      if (!quote_typed && (other.empty() || other == undefined_name(first) || !same_entry))
        std::rethrow_exception(refusal);  // the name as it was refused, with its hint
      // "Ω_body + ω" for a vector: how the name was read, for what is then refused.
      const std::string read_as =
          quote_typed && referenced->note.starts_with("read with ") ? ", " + referenced->note : "";
      throw InputError(second.substr(0, at2) + first.substr(at1, end1 - at1) + "\"" + read_as +
                       second.substr(end2 + 1));
    }
    v.feedback.push_back(referenced->note + (v.correct ? referenced->when_right : ""));
    return v;
  }
}

// judge_referring's verdict on `side`, before an '=', where it reads referring to an earlier
// answer or the steps' names (not one name alone, which is a label); else nullopt.
std::optional<Verdict> side_referring(const Context& ctx, const Answer& a, const std::string& side,
                                      const Options& options) {
  if (is_one_name(side)) return std::nullopt;
  try {
    return judge_referring(ctx, a, side, options);
  } catch (const InputError&) {
  }
  return std::nullopt;
}

// Why a side that could not be read is a label of the student's own, "T is no symbol here", or
// "" where it is no label: a name the problem lacks ("T/2"), a function it lacks ("4K(k)/λ",
// K for the complete integral), or either once primes are taken off ("k′²", k′ the
// complementary modulus: the reader refuses the prime itself first).
std::string label_reason(const Context& ctx, const Answer& a, const std::string& side,
                         const std::string& message, const Options& options) {
  if (const std::string name = undefined_name(message); !name.empty()) {
    // "T/2 = 1.91 s" for the racket's flip, where the steps write T for the energy: say so.
    // "4K(k)/λ = 7.6 s" for the flip, k being part (c)'s answer: an answer is no symbol.
    const std::string named = name_in_key(ctx.key, name);
    if (const PartKey* holds = part_answering(ctx.key, named)) {
      return named != name ? fmt::format("{} is {} here, the key's answer to part ({})",
                                         sym::to_unicode(name), named, holds->id)
                           : fmt::format("{} is the key's answer to part ({}), no symbol",
                                         sym::to_unicode(name), holds->id);
    }
    return name + " is no symbol here";
  }
  if (const std::string name = quoted_after(message, "unknown function"); !name.empty())
    return name + " is no function here";
  std::string unprimed = side;
  for (const std::string prime : {"′", "″"}) {
    for (auto at = unprimed.find(prime); at != std::string::npos; at = unprimed.find(prime))
      unprimed.erase(at, prime.size());
  }
  if (unprimed == side) return "";
  try {
    judge_one(ctx, a, unprimed, options);
  } catch (const InputError& e) {
    return label_reason(ctx, a, unprimed, e.what(), options);
  }
  return "";
}

// The value labelled with `a`'s name in a list of labelled values ("φ̇_slow = 4.995 rad/s,
// φ̇_fast = 25.82 rad/s" for phidot_slow), and a line on the rest ("φ̇_fast = 25.82 rad/s
// (phidot_fast) not judged here: .."); nullopt where the text is no such list or no one label
// is the answer's name.
struct OwnItem {
  std::string value, note;
};
std::optional<OwnItem> own_labelled_item(const Context& ctx, const Answer& a,
                                         const std::string& text) {
  const std::vector<std::string> items = top_level(text, ',');
  if (items.size() < 2) return std::nullopt;
  std::optional<OwnItem> own;
  std::vector<std::string> others;
  for (const auto& item : items) {
    const std::vector<std::string> sides = top_level(item, '=');
    if (sides.size() != 2 || trim(sides[1]).empty() || !is_one_name(sides[0])) return std::nullopt;
    const std::string label = trim(sides[0]);
    if (name_spelling(label) == name_spelling(a.name)) {
      if (own) return std::nullopt;  // labelled twice
      own = OwnItem{trim(sides[1]), ""};
      continue;
    }
    const std::string other = name_in_key(ctx.key, label);
    others.push_back(trim(item) + (other != label ? " (" + other + ")" : ""));
  }
  if (!own) return std::nullopt;
  constexpr std::size_t kMostNamed = 3;  // a line, not a list of hundreds
  std::string named = fmt::format(
      "{}",
      fmt::join(others.begin(),
                others.begin() + static_cast<std::ptrdiff_t>(std::min(others.size(), kMostNamed)),
                "; "));
  if (others.size() > kMostNamed) named += fmt::format(" and {} more", others.size() - kMostNamed);
  own->note = named + " not judged here: give each answer on its own";
  return own;
}

// One name that no symbol of the problem has, as "E" or "θ_L" before an '='.
bool is_own_label(const Context& ctx, const Answer& a, const std::string& side,
                  const Options& options) {
  if (!is_one_name(side)) return false;
  // "E′", "V′": a prime marks the name (the reader refuses the character itself).
  std::string name = side;
  for (auto at = name.find("′"); at != std::string::npos; at = name.find("′"))
    name.replace(at, std::string_view("′").size(), "'");
  try {
    judge_one(ctx, a, name, options);
  } catch (const InputError& e) {
    return !undefined_name(e.what()).empty();
  }
  return false;
}

// An answer with a '±' is two answers (plus_minus.hpp). Both right (a value ± its uncertainty
// within the tolerance) is right; else the student is asked for one and told which is right, and
// what the other one is where a mistake is found (the heavy top's other precession rate).
Verdict judge_signs(const Context& ctx, const Answer& a, const SignReadings& signs,
                    const Options& options) {
  std::exception_ptr refused;  // why the reader refused the first sign refused
  const auto read = [&](const std::string& text) -> std::optional<Verdict> {
    try {
      return judge_text(ctx, a, text, options);
    } catch (const InputError&) {
      if (!refused) refused = std::current_exception();
      return std::nullopt;  // "sqrt(-x)": that sign gives no answer
    }
  };
  const std::optional<Verdict> plus = read(signs.plus);
  const std::optional<Verdict> minus = read(signs.minus);
  if (!plus && !minus) std::rethrow_exception(refused);
  const bool plus_right = plus && plus->correct;
  const bool minus_right = minus && minus->correct;
  if (plus_right && minus_right) {
    return {true, "correct: " + a.name + " (with either sign of its '±')", {}};
  }
  const auto said = [](const std::optional<Verdict>& v, const char* sign) {
    return v && !v->feedback.empty() ? fmt::format("with '{}', {}", sign, v->feedback.front()) : "";
  };
  std::string what;
  if (plus_right || minus_right) {
    const std::string other = plus_right ? said(minus, "−") : said(plus, "+");
    what = fmt::format("with '{}' it is right{}", plus_right ? "+" : "−",
                       other.empty() ? "" : "; " + other);
  } else {
    std::vector<std::string> each;
    for (const auto& [v, sign] : {std::pair{&plus, "+"}, std::pair{&minus, "−"}}) {
      if (const std::string line = said(*v, sign); !line.empty()) each.push_back(line);
    }
    what = fmt::format("neither is right{}",
                       each.empty() ? "" : fmt::format(" ({})", fmt::join(each, "; ")));
  }
  throw InputError(fmt::format("{}: '±' gives two answers; type one: {}", kField, what));
}

// "λ² = 83.38 1/s": a square given in a unit no square has, most often the answer's own unit
// written on its square. Wrong as written; the feedback says which unit the square is in, and
// whether the number is right in it.
Verdict square_in_odd_unit(const Context& ctx, const Answer& a, const std::string& label,
                           const SquaredLabel& square, const Options& opt) {
  const Unit& unit = *square.odd_unit;
  Unit squared = a.unit.empty() ? Unit{} : parse_unit(a.unit, "key unit of " + a.name);
  for (int& power : squared.dim) power *= 2;
  Verdict v;
  v.line = "incorrect: the square of " + a.name + " has the wrong dimension";
  v.wrong_dimension = true;
  const std::string key_squared =
      a.unit.empty() ? "no unit" : sym::to_unicode("(" + a.unit + ")^2");
  v.feedback.push_back(fmt::format("you gave {} in {} ({}); the square of {} is in {} ({})", label,
                                   sym::to_unicode(unit.text), unit.dimension_words(), a.name,
                                   key_squared, squared.dimension_words()));
  const std::string root = "sqrt(" + square.number + ")" + (a.unit.empty() ? "" : " " + a.unit);
  const auto right = [&](const std::string& sign) {
    try {
      return judge_one(ctx, a, sign + root, opt).correct;
    } catch (const InputError&) {  // "sqrt(-83.4)": no number of this square is right
      return false;
    }
  };
  if (right("") || right("-")) {
    v.feedback.push_back(fmt::format("in {} the number would be right", key_squared));
  }
  return v;
}

// "ω₃ ≥ 118.8 rad/s" for a least value (inequality.hpp): the side that reads as the answer is
// its value, the other its label ("θ ≥ θ₀": θ is no symbol of the problem); where both read,
// the right side, as "ω₃ ≥ .." is written. The sign must say the bound the answer is.
Verdict judge_bound(const Context& ctx, const Answer& a, const Inequality& q, const Options& opt) {
  const bool lower = a.bound == AnswerBound::lower;
  const auto judged = [&](const std::string& side) -> std::optional<Verdict> {
    try {
      return judge_one(ctx, a, side, opt);
    } catch (const InputError&) {
      return std::nullopt;
    }
  };
  std::optional<Verdict> read = judged(q.right);
  const bool value_right = read || !(read = judged(q.left));
  // Where neither side reads, the right side's error.
  Verdict v = read ? std::move(*read) : judge_one(ctx, a, q.right, opt);
  const std::string& value = value_right ? q.right : q.left;
  const std::string& label = value_right ? q.left : q.right;
  // label ≥ value says the value is a least one; value ≥ label a greatest.
  const bool says_lower = value_right == q.left_greater;
  if (says_lower == lower) {
    v.feedback.push_back(
        fmt::format("read as {} = {}, the bound of your '{}'", a.name, value, q.sign));
    return v;
  }
  const bool bound_right = v.correct;
  v = Verdict{};
  v.line = "incorrect: " + a.name + ": your inequality points the wrong way";
  v.feedback.push_back(fmt::format("{} is a {} value: {} {} {}", a.name,
                                   lower ? "least" : "greatest", label, lower ? "≥" : "≤", a.name));
  v.feedback.push_back(bound_right ? "the bound itself would be right"
                                   : "and the bound itself is not right either");
  return v;
}

// "30° ≤ θ ≤ 44.7°" for the nutation's limits (inequality.hpp): a least value is the range's
// lower end, a greatest its upper; the other end is named as not judged, with the answer of the
// same part it would be, where there is one.
Verdict judge_range_end(const Context& ctx, const Answer& a, const Range& r, const Options& opt) {
  const bool lower = a.bound == AnswerBound::lower;
  const std::string& end = lower ? r.lower : r.upper;
  const std::string& other = lower ? r.upper : r.lower;
  Verdict v = judge_one(ctx, a, end, opt);
  std::string partner;
  for (const auto& p : ctx.key.parts) {
    const auto own = std::find_if(p.answers.begin(), p.answers.end(),
                                  [&](const Answer& b) { return b.name == a.name; });
    if (own == p.answers.end()) continue;
    for (const auto& b : p.answers) {
      if (b.bound != AnswerBound::none && b.bound != a.bound) partner = b.name;
    }
  }
  v.feedback.push_back(fmt::format(
      "read as {} = {}, the {} end of your range; {} ({}) not judged "
      "here{}",
      a.name, end, lower ? "lower" : "upper", other, lower ? "its upper end" : "its lower end",
      partner.empty() ? "" : ": it is " + partner + "'s"));
  return v;
}

}  // namespace

namespace {

// The answer as written, without what surrounds it.
std::string written_answer(const Context& ctx, const std::string& text) {
  // "$$ m R^2/4 = 0.00072 $$": the delimiters are around both sides.
  // "Out[3]= 0.00072": a program's label of its result is no side of an '='.
  // "m*R**2/4  # disc": a comment, as a script has one after its line; "303.6 days (Euler's
  // period)": a remark.
  const auto known_word = [&](const std::string& w) {
    return ctx.table.contains(w) || is_unit(w) || sym::is_function_name(w) ||
           sym::greek_letters().count(ascii_lower(w)) > 0;
  };
  // "eigenvalues: 0.569, ..", "I1: 0.569, I2: ..": labels before a ':', as one writes an answer.
  // "2.5, 3, 3.5 (in units of m a²)": the value times the expression it is given in units of.
  // "{{E -> 7.371}}": Mathematica's rules, as Solve gives them, are equations.
  return without_colon_labels(without_output_label(without_math_delimiters(without_remark(
      in_units_of_written(rules_as_equations(without_comments(text))), known_word))));
}

// The answer judged; where right, the bracket's value too, which must be right as well (a
// bracket no value reads from is a remark, and the verdict says it was not judged).
Verdict judge_restated(const Context& ctx, const Answer& a, const Restatement& r,
                       const Options& options) {
  // One bracket: "1 (= 1) (= 1) .." would judge itself again, bracket by bracket.
  if (const auto twice = restatement_of(r.answer)) {
    throw InputError(fmt::format("{}: {} and {}: the answer again in one bracket, not two", kField,
                                 twice->bracket, r.bracket));
  }
  Verdict v = judge_text(ctx, a, r.answer, options);
  if (!v.correct) return v;
  try {
    Verdict again = judge_one(ctx, a, r.again, options);
    if (!again.correct) {
      again.feedback.insert(again.feedback.begin(),
                            "your bracket \"" + r.bracket + "\" gives another value");
      return again;
    }
  } catch (const InputError&) {
    v.feedback.push_back("your bracket \"" + r.bracket + "\" is taken as a remark, not judged");
  }
  return v;
}

// "your bracket "(unstable)"", "your word "stable"": the student's word as they wrote it.
std::string your_word(const WordRemark& remark) {
  return (remark.bracketed ? "your bracket \"" : "your word \"") + remark.bracket + "\"";
}

// What the key says of the claim a word after an answer makes: whether it holds, and why.
struct KeyOnWord {
  bool holds;
  std::string why;
};

// The stability of a spin about a principal axis, where the solver gives it; the sense of a
// precession, where the answer is signed so (+ with the spin: an oblate body); none where the
// key says nothing of what the word claims (a precession of zero has no sense).
std::optional<KeyOnWord> key_on_word(const Answer& a, const WordRemark& remark) {
  if (remark.says_stable && a.stability)
    return KeyOnWord{*remark.says_stable == a.stability->stable, a.stability->why};
  if (!remark.says_with_spin || a.sign != SignConvention::sense_of_precession ||
      a.value.shape != Value::Shape::scalar || a.value.data.at(0) == 0.0) {
    return std::nullopt;
  }
  const bool with_spin = a.value.data[0] > 0;
  return KeyOnWord{*remark.says_with_spin == with_spin,
                   with_spin
                       ? a.name + " is along +e₃, with the spin: the body is oblate (I₃ > I₁)"
                       : a.name + " is along −e₃, against the spin: the body is prolate (I₃ < I₁)"};
}

// The number's verdict with the word after it weighed against the key: a right number with the
// wrong word is wrong (the word answers what the part asks: which axes are stable, which way the
// axis precesses); the word is said right or wrong either way.
Verdict with_word_weighed(Verdict v, const Answer& a, const WordRemark& remark,
                          const KeyOnWord& key) {
  if (key.holds) {
    v.feedback.push_back(your_word(remark) + " is right: " + key.why);
    return v;
  }
  if (v.correct) {
    v.correct = false;
    v.line = "incorrect: " + a.name + " (the number is right, the word after it is not)";
  }
  v.feedback.push_back(your_word(remark) + " is wrong: " + key.why);
  return v;
}

}  // namespace

bool written_as_euler_equations(const Context& ctx, const std::string& text) {
  try {
    return read_euler_equations(euler_equations_as_text(written_answer(ctx, text), ctx.table),
                                kField)
        .has_value();
  } catch (const InputError&) {
    return true;  // equations, but not one for each component: the judge says which
  }
}

namespace {
// The judge of judge(), which adds what a lost power of ten reads as.
Verdict judge_text(const Context& ctx, const Answer& a, const std::string& text,
                   const Options& options) {
  // "1.772 1/s (unstable)": the number judged; the word is the student's claim, weighed where
  // the key says what it claims (the stability of a spin about a principal axis, which the
  // question asks), else said unjudged rather than taken for right.
  if (const auto remark = word_remark(text)) {
    Verdict v = judge_text(ctx, a, remark->answer, options);
    if (const auto claim = key_on_word(a, *remark)) return with_word_weighed(v, a, *remark, *claim);
    v.feedback.push_back(your_word(*remark) + " is taken as a remark, not judged (the value is)");
    return v;
  }
  const std::string written = written_answer(ctx, text);
  // "rate_axis2 =": a prompt's line pasted with its answer left out.
  if (const std::string line = trim(written); !line.empty() && line.back() == '=') {
    throw InputError(nothing_after(kField, "=", line));
  }
  // "118.8 rad/s (about 1134 rpm)": the answer and the same again, each judged.
  if (const auto r = restatement_of(written)) return judge_restated(ctx, a, *r, options);
  // "±9.131 1/s", "(I3ω3 ± √(..))/(2 I1 cos θ)": the roots of a quadratic, two answers.
  if (const auto signs = sign_readings(written)) return judge_signs(ctx, a, *signs, options);
  // "dω₁/dt = -0.9651 ω₂ ω₃, ..": Euler's equations for their coefficients, as the question asks
  // them written and the key's step prints them.
  if (a.value.shape == Value::Shape::vector && a.value.data.size() == 3) {
    if (const auto equations =
            read_euler_equations(euler_equations_as_text(written, ctx.table), kField)) {
      if (!equations->wrong_products.empty()) {
        Verdict v;
        v.line = "incorrect: " + a.name +
                 ": in Euler's equations each dωᵢ/dt is a coefficient times the other two "
                 "components";
        v.feedback = equations->wrong_products;
        return v;
      }
      // In the moments as the steps write them ("I₁ω̇₁ = (I₂ − I₃)ω₂ω₃"), read as the key's.
      Verdict v = judge_referring(ctx, a, equations->coefficients, options);
      v.feedback.push_back("read as the coefficients of Euler's equations: (c₁, c₂, c₃) = " +
                           sym::to_unicode(equations->coefficients));
      return v;
    }
  }
  // "ω₃ ≥ 118.8 rad/s": a least or greatest value as the bound it is.
  if (a.bound != AnswerBound::none && a.value.shape == Value::Shape::scalar) {
    if (const auto r = range_of(written)) return judge_range_end(ctx, a, *r, options);
    if (const auto q = inequality_of(written)) return judge_bound(ctx, a, *q, options);
    if (const auto one_way = range_both_ways(written)) {
      throw InputError(fmt::format(
          "{}: the signs of your range point both ways; a range's point one way, as in {}", kField,
          *one_way));
    }
  } else if (inequality_of(written) || range_of(written)) {
    // "E < 8 J", "t ≤ 0.1612 s": no expression compares, and this answer is no bound.
    throw InputError(
        fmt::format("{}: {} is a value, not a bound: give the value itself (an "
                    "inequality or a range is read only for a least or greatest "
                    "value)",
                    kField, a.name));
  }
  // "φ̇_slow = 4.995 rad/s, φ̇_fast = 25.82 rad/s": a part's numbers in one box, each labelled
  // with its answer's name. This answer's is judged; the line says the others were not.
  if (a.value.shape == Value::Shape::scalar) {
    if (auto own = own_labelled_item(ctx, a, written)) {
      Verdict v = judge_referring(ctx, a, own->value, options);
      v.feedback.push_back(own->note);
      return v;
    }
  }
  // "z_cm = −3h/4" for a centre of mass on the axis: a 3-vector's components given in part, the
  // others zero, as the line says.
  if (a.value.shape == Value::Shape::vector && a.value.data.size() == 3 &&
      a.named_entries.empty() && a.kind != AnswerKind::principal_moments) {
    if (const auto some = some_components(without_others_zero(written))) {
      Verdict v = judge_referring(ctx, a, some->text, options);
      const std::vector<std::string> axes = entry_names(a);  // x y z, or the body's e₁ e₂ e₃
      std::vector<std::string> missing;
      for (const std::size_t k : some->missing)
        missing.push_back(axes.size() == 3 ? axes[k] : std::string(1, "xyz"[k]));
      v.feedback.push_back(fmt::format("read as {}: {} not given, taken as zero", some->text,
                                       fmt::join(missing, ", ")));
      return v;
    }
  }
  // "x = 0.5, y = 1, z = 1.5": components one by one, each with its label.
  // Vectors labelled e1 = (..), .. are the axes: written as columns ("[..]^T"), or as the rows
  // of a list where one has a factor outside its bracket.
  const std::size_t entries = a.value.shape == Value::Shape::scalar ? 3 : a.value.data.size();
  if (const auto components =
          labelled_components(without_others_zero(written), kField, a.named_entries, entries)) {
    // Each value as any answer's: in the steps' names, with units worked out, ..
    Verdict v = judge_referring(ctx, a, components->text, options,
                                components->columns ? AxesLayout::columns : AxesLayout::rows);
    v.feedback.insert(v.feedback.end(), components->notes.begin(), components->notes.end());
    return v;
  }
  auto parts = sides(approximations_as_equal(written), a.name);
  // "E = M R² ψ̇₀²/4 + M g l cos θ₀ = 7.37 J", "E = T + V = 7.37 J": a label of the student's own
  // (one name that is no symbol of the problem) before a key's line, or before a formula of
  // their own and the value. The label is dropped, as before one side; the rest read as two
  // sides are.
  if (parts.size() > kMostSides && is_own_label(ctx, a, parts[0], options))
    parts.erase(parts.begin());
  if (parts.size() == 1) return judge_referring(ctx, a, parts[0], options);
  // "cos θ_max = 0.7109": the cosine of an angle asked for, as u = cos θ is found first.
  if (const std::string f = function_of_answer(parts[0], a); parts.size() == 2 && !f.empty()) {
    Verdict v = judge_one(ctx, a, "a" + f + "(" + trim(parts[1]) + ")", options);
    v.feedback.push_back(
        fmt::format("read as {0} = a{1}({2}): your '=' gives {1} {0}", a.name, f, trim(parts[1])));
    return v;
  }
  // "λ² = 83.38 s⁻²": the square of the answer, as a rate is found from its square first.
  if (const auto squared =
          parts.size() == 2 ? root_of_squared_label(parts[0], parts[1], ctx, a) : std::nullopt) {
    if (squared->odd_unit) {
      return square_in_odd_unit(ctx, a, trim(parts[0]), *squared, options);
    }
    const std::string& root = squared->root;
    Verdict v = judge_one(ctx, a, root, options);
    std::string sign;
    if (!v.correct) {  // the negative root, for an answer with a sign
      if (Verdict negative = judge_one(ctx, a, "-" + root, options); negative.correct) {
        v = std::move(negative);
        sign = "−";
      }
    }
    v.feedback.push_back(fmt::format("read as {} = {}√({}): your '=' gives {}", a.name, sign,
                                     trim(parts[1]), trim(parts[0])));
    return v;
  }
  // A key's line has a closed form and a value; judging more sides only costs time (each may be
  // an expression to simplify).
  if (parts.size() > kMostSides) {
    throw InputError(
        fmt::format("{}: {} sides of '='; give the answer, or a key's line: its "
                    "closed form = its value",
                    kField, parts.size()));
  }
  // "m·R²/4 = 0.00072 kg m²": every side is judged, and must be right.
  Verdict first;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    Verdict v;
    try {
      v = judge_one(ctx, a, parts[k], options);
    } catch (const InputError& e) {
      // "θ_L = 7.63°", "L = (..)": a label of the student's own before the '=' (a name that is
      // no symbol of the problem), where a pasted key line has the answer's name; or one that
      // names this answer as the question does ("dω/dt = .." for dw_dt0). The answer is what
      // follows it.
      if (k == 0 && parts.size() == 2 &&
          (is_one_name(parts[0]) || name_in_key(ctx.key, trim(parts[0])) == a.name)) {
        return judge_referring(ctx, a, parts[1], options);
      }
      // "T/2 = 1.91 s": a formula of the student's own in names the problem lacks labels the
      // value; that side cannot be judged, and the verdict says so.
      if (parts.size() != 2) throw;
      const std::string reason = label_reason(ctx, a, parts[k], e.what(), options);
      if (k == 0) {
        // "2π/Ω_body_rate = 303.6 days", "2θ_L = 15.26°": a formula in an earlier answer's or
        // the steps' names, right as the key's closed form reads in, is judged as a side (said
        // so), not taken as a label; also where the name was first taken for a unit (2 θ_L).
        std::optional<Verdict> formula = side_referring(ctx, a, parts[0], options);
        // Wrong, it is a label where a name the problem lacks stands in it, as before the names
        // were read ("2π/Ω_space_rate = 0.161 s": Ω_space_rate is no symbol); else, where the
        // name was first taken for a unit ("3θ_L = 15.26°"), a wrong side, said as any other.
        if (formula && !formula->correct && reason.empty()) {
          formula->feedback.insert(formula->feedback.begin(),
                                   "the side \"" + trim(parts[0]) + "\" of your '='");
          return *formula;
        }
        if (formula && formula->correct) {
          Verdict value = judge_one(ctx, a, parts[1], options);
          if (!value.correct) {
            value.feedback.insert(value.feedback.begin(),
                                  "the side \"" + trim(parts[1]) + "\" of your '='");
          }
          value.feedback.insert(value.feedback.end(), formula->feedback.begin(),
                                formula->feedback.end());
          return value;
        }
      }
      if (k == 0 && !reason.empty()) {
        Verdict label = judge_referring(ctx, a, parts[1], options);
        label.feedback.push_back(
            fmt::format("the side \"{}\" of your '=' is taken as a label, not judged: {}",
                        trim(parts[0]), reason));
        return label;
      }
      // "1.91 s = T/2", "7.63° = θ_L": the same label after the value, the value judged right
      // (a wrong one returned above with its side named).
      if (k == 1 && (!reason.empty() || is_one_name(parts[1]))) {
        if (!is_one_name(parts[1])) {
          first.feedback.push_back(
              fmt::format("the side \"{}\" of your '=' is taken as a label, not judged: {}",
                          trim(parts[1]), reason));
        }
        return first;
      }
      throw;
    }
    if (!v.correct) {
      v.feedback.insert(v.feedback.begin(), "the side \"" + trim(parts[k]) + "\" of your '='");
      return v;
    }
    if (k == 0) first = std::move(v);
  }
  return first;
}
}  // namespace

Verdict judge(const Context& ctx, const Answer& a, const std::string& typed,
              const Options& options) {
  // "`I0 = 0.00072 kg m^2`": the code marks of a forum's or a chat's post around it all;
  // "0.569, 4.209 and 4.556": a list in words.
  const std::string text = and_as_comma(without_code_marks(typed));
  // "none" for an answer that exists (where it does not, absent_answer.hpp judges it right).
  const auto labelled = answer_line(text);
  if (says_none(text) || (labelled && says_none(labelled->answer)))
    return {false, "incorrect: " + a.name + " exists at these values", {}};
  // "omega3_min 118.8 rad/s": the answer's own name before it with only a space between is its
  // label, as in "omega3_min = 118.8 rad/s" (the answer times itself is no answer).
  if (const auto spaced = spaced_answer_line(text);
      spaced && name_in_key(ctx.key, spaced->name) == a.name) {
    return judge(ctx, a, spaced->name + " = " + spaced->answer, options);
  }
  // "7.2 × 10−4 kg m2": read as written, 7.2 × 6; the verdict says so, and whether the power
  // of ten it lost would be right. Where the text reads only with the power, the refusal says
  // how to write it.
  const auto lost = lost_powers_of_ten(text);
  if (!lost) return judge_text(ctx, a, text, options);
  const auto as_powers = [&]() -> std::optional<Verdict> {
    try {
      return judge_text(ctx, a, lost->as_powers, options);
    } catch (const InputError&) {
      return std::nullopt;
    }
  };
  const std::string power = "10^-" + lost->exponent;
  const std::string read_as =
      fmt::format("\"{}\" reads as 10 − {} = {}, not {}", lost->written, lost->exponent,
                  10 - std::stoi(lost->exponent), sym::to_unicode(power));
  Verdict v;
  try {
    v = judge_text(ctx, a, text, options);
  } catch (const InputError&) {
    if (!as_powers()) throw;
    throw InputError(
        fmt::format("{}: {}: write {}, as in \"{}\"", kField, read_as, power, lost->as_powers));
  }
  if (v.correct) return v;
  // Right with the power: how far off the difference is ("9.44e+04 times the answer") says
  // nothing more.
  if (const auto powers = as_powers(); powers && powers->correct) {
    v.feedback = {fmt::format("{}; written {}, your answer is right", read_as, power)};
    return v;
  }
  v.feedback.insert(v.feedback.begin(),
                    fmt::format("{}; a power of ten is written {}", read_as, power));
  return v;
}

}  // namespace wobble::check
