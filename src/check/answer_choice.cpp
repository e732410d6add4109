#include "check/answer_choice.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <vector>

#include "check/inequality.hpp"
#include "check/submission.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"

namespace wobble::check {

namespace {

// The left of the first '=' or ':' in `text`, trimmed; "" where there is neither.
std::string label_of(const std::string& text) {
  const auto at = text.find_first_of("=:");
  return at == std::string::npos ? "" : trim(text.substr(0, at));
}

// Where `text`'s label (a plain word: "phidot = 3") names no answer of part `part` of several,
// a refusal saying so, and naming the part whose answer it is where it is another's
// ("omega3 is part c's"): else the lookup would ask for a name the line has given. A label of
// other characters naming no answer (Euler's equations solved for ω̇₁) may be the answer
// itself, and is left to the judge.
void refuse_label_of_no_answer(const Key& key, const PartKey& part, const std::string& text,
                               const std::string& part_field) {
  const std::string label = label_of(text);
  const bool word = !label.empty() &&
                    std::isdigit(static_cast<unsigned char>(label.front())) == 0 &&
                    std::all_of(label.begin(), label.end(), [](char c) {
                      return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
                    });
  const std::string named = label.empty() ? "" : name_in_key(key, label);
  std::string elsewhere;
  for (const auto& p : key.parts) {
    for (const auto& a : p.answers) {
      if (a.name == named) elsewhere = fmt::format("; {} is part {}'s", a.name, p.id);
    }
  }
  if (!word && elsewhere.empty()) return;
  throw AnswerNotFound(fmt::format("{}: part {} has no answer '{}' (answers: {}){}", part_field,
                                   part.id, label, fmt::join(part.asked_names(), ", "), elsewhere));
}

}  // namespace

std::string answer_meant(const Context& ctx, const std::string& part_id, const std::string& text,
                         const Options& options) {
  const auto part = std::find_if(ctx.key.parts.begin(), ctx.key.parts.end(),
                                 [&](const PartKey& p) { return p.id == part_id; });
  if (part == ctx.key.parts.end() || part->answers.size() < 2) return "";
  if (const std::string label = label_of(text); !label.empty()) {
    const std::string named = name_in_key(ctx.key, label);
    for (const auto& a : part->answers) {
      if (a.name == named) return a.name;
    }
  }
  // "omega3_min 100 rad/s": one of the part's names before a number with a space between labels
  // it (before a name, "omega3 m g l", the word may be a factor).
  if (const auto spaced = spaced_answer_line(text); spaced && starts_as_number(spaced->answer)) {
    const std::string named = name_in_key(ctx.key, spaced->name);
    for (const auto& a : part->answers) {
      if (a.name == named) return a.name;
    }
  }
  // Euler's equations, right or wrong, are an answer for their coefficients c₁, c₂, c₃.
  if (written_as_euler_equations(ctx, text)) {
    for (const auto& a : part->answers) {
      if (a.named_entries == kEulerCoefficients) return a.name;
    }
  }
  // "30° ≤ θ ≤ 44.7°": a range is an answer for its first bound (the line names the other's).
  if (range_of(text)) {
    for (const auto& a : part->answers) {
      if (a.bound != AnswerBound::none && a.value.shape == Value::Shape::scalar) return a.name;
    }
  }
  // Judged against each: an answer that cannot be read as one of them (its shape or unit is
  // another's) is no answer to it. Right for one only: that one. Right for none and read as a
  // value of one only (its shape, and its dimension where it has one): that one, so that a wrong
  // answer is judged, its mistake named, where only a name would be asked for.
  std::string right, readable;
  int rights = 0, readables = 0;
  for (const auto& a : part->answers) {
    try {
      const Verdict v = judge(ctx, a, text, options);
      if (!v.wrong_dimension) {
        readable = a.name;
        ++readables;
      }
      if (v.correct) {
        right = a.name;
        ++rights;
      }
    } catch (const InputError&) {
    }
  }
  if (rights == 1) return right;
  return rights == 0 && readables == 1 ? readable : "";
}

std::string euler_equations_answer(const Context& ctx, const std::string& text) {
  std::string found;
  int answers = 0;
  for (const auto& part : ctx.key.parts) {
    for (const auto& a : part.answers) {
      if (a.named_entries != kEulerCoefficients) continue;
      found = a.name;
      ++answers;
    }
  }
  return answers == 1 && written_as_euler_equations(ctx, text) ? found : "";
}

const Answer& answer_for(const Context& ctx, const std::string& part, const std::string& name,
                         const std::string& text, const Options& options,
                         const std::string& part_field, const std::string& name_field) {
  const std::string part_id = name_in_key(ctx.key, part);
  std::string answer_name = name_in_key(ctx.key, name);
  if (answer_name.empty() && !part_id.empty()) {
    answer_name = answer_meant(ctx, part_id, text, options);
    const auto asked = std::find_if(ctx.key.parts.begin(), ctx.key.parts.end(),
                                    [&](const PartKey& p) { return p.id == part_id; });
    if (answer_name.empty() && asked != ctx.key.parts.end() && asked->answers.size() > 1)
      refuse_label_of_no_answer(ctx.key, *asked, text, part_field);
  }
  return find_answer(ctx.key, part_id, answer_name, part_field, name_field);
}

}  // namespace wobble::check
