#include "check/absent_answer.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cctype>

#include "core/characters.hpp"

namespace wobble::check {
namespace {

// Lower case (ASCII letters), one space between words, the typographic apostrophe as ASCII,
// no final full stop or exclamation mark.
std::string normalised(const std::string& typed) {
  std::string text = typed;
  for (std::size_t at = text.find("\u2019"); at != std::string::npos; at = text.find("\u2019"))
    text.replace(at, 3, "'");
  std::string out;
  for (const char c : trim(text)) {
    if (std::isspace(static_cast<unsigned char>(c))) {
      if (!out.empty() && out.back() != ' ') out += ' ';
    } else {
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
  }
  while (!out.empty() && (out.back() == '.' || out.back() == '!' || out.back() == ' '))
    out.pop_back();
  return out;
}

constexpr std::array kNone{"none",
                           "dne",
                           "n/a",
                           "\u2205",
                           "nothing",
                           "undefined",
                           "impossible",
                           "not possible",
                           "does not exist",
                           "doesn't exist",
                           "do not exist",
                           "don't exist",
                           "it does not exist",
                           "it doesn't exist",
                           "they do not exist",
                           "they don't exist",
                           "there is none",
                           "there are none",
                           "there is no solution",
                           "there are no solutions",
                           "no solution",
                           "no solutions",
                           "no real solution",
                           "no real solutions",
                           "no real root",
                           "no real roots",
                           "no such rate",
                           "no such rates",
                           "no steady precession",
                           "there is no steady precession"};

// What may follow a phrase: "at these values" (as a key prints it), then a reason after a
// separator or a conjunction.
bool is_reason(const std::string& rest) {
  std::string r = rest.rfind(" at these values", 0) == 0 ? rest.substr(16) : rest;
  if (r.empty()) return true;
  if (r.front() == ' ') r.erase(0, 1);
  for (const std::string start :
       {",", ";", ":", "(", "-", "\u2013", "\u2014", "because ", "since ", "as "}) {
    if (r.rfind(start, 0) == 0) return true;
  }
  return false;
}

// The absent answers of one part that `part_id` and `name` point at, by index in its `absent`.
struct Pointed {
  const PartKey* part = nullptr;
  std::vector<std::size_t> indices;
};

std::optional<Pointed> pointed(const Key& key, const std::string& part_id,
                               const std::string& name) {
  const std::string wanted = name_spelling(name.empty() ? part_id : name);
  for (const auto& part : key.parts) {
    if (!name.empty() && !part_id.empty() && part.id != part_id) continue;
    for (std::size_t i = 0; i < part.absent.size(); ++i) {
      if (!wanted.empty() && name_spelling(part.absent[i]) == wanted) return Pointed{&part, {i}};
    }
  }
  if (!name.empty()) return std::nullopt;
  for (const auto& part : key.parts) {
    if (part.id != part_id || !part.answers.empty() || part.absent.empty()) continue;
    Pointed all{&part, {}};
    for (std::size_t i = 0; i < part.absent.size(); ++i) all.indices.push_back(i);
    return all;
  }
  return std::nullopt;
}

}  // namespace

bool says_none(const std::string& typed) {
  const std::string text = normalised(typed);
  return std::any_of(kNone.begin(), kNone.end(), [&](const std::string& phrase) {
    return text.rfind(phrase, 0) == 0 && is_reason(text.substr(phrase.size()));
  });
}

std::optional<Verdict> judge_absent(const Key& key, const std::string& part_id,
                                    const std::string& name, const std::string& typed,
                                    bool with_reason) {
  const auto p = pointed(key, part_id, name);
  if (!p) return std::nullopt;
  std::vector<std::string> names, reasons;
  for (const std::size_t i : p->indices) {
    names.push_back(p->part->absent[i]);
    const std::string why = i < p->part->absent_why.size() ? p->part->absent_why[i] : "";
    if (!why.empty() && std::find(reasons.begin(), reasons.end(), why) == reasons.end())
      reasons.push_back(why);
  }
  if (reasons.empty()) reasons.push_back("the key says why");
  if (!with_reason) reasons.clear();
  const bool right = says_none(typed);
  return Verdict{right,
                 // The names alone, as any verdict's line has them: the part is beside it on every
                 // surface (a submission's "(d) correct: .."), or was typed.
                 fmt::format("{}: {} {} not exist at these values", right ? "correct" : "incorrect",
                             fmt::join(names, ", "), names.size() == 1 ? "does" : "do"),
                 reasons};
}

}  // namespace wobble::check
