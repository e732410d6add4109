#include "check/submission.hpp"

#include <fmt/format.h>
#include <iconv.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <sstream>
#include <string_view>

#include "check/absent_answer.hpp"
#include "check/answer_choice.hpp"
#include "check/brackets.hpp"
#include "check/latex_answer.hpp"
#include "check/written_forms.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"

namespace wobble::check {

namespace {
// A submission is a few dozen lines; a larger text is no submission.
constexpr std::size_t kMaxSubmissionBytes = 1 << 20;

struct Line {
  int number = 0;
  std::string name, answer;
  std::string text;  ///< as typed, comments left out
};

// A part's id as a student marks it: one or two letters or digits ("c", "1b").
bool is_part_id(const std::string& s) {
  return !s.empty() && s.size() <= 2 &&
         std::all_of(s.begin(), s.end(), [](char c) { return is_letter(c) || is_digit(c); });
}

// The part's mark before a name, "(c) " or "c) ", dropped: "(c) angle_omega_e3" names
// angle_omega_e3. No answer's name has a bracket.
std::string without_part_mark(const std::string& name) {
  const std::size_t close = name.find(')');
  if (close == std::string::npos || close + 1 >= name.size() || name[close + 1] != ' ') {
    return name;
  }
  const std::size_t open = name[0] == '(' ? 1 : 0;
  return is_part_id(name.substr(open, close - open)) ? trim(name.substr(close + 1)) : name;
}

// "(c)", "c)", "Part c", "part (c):": a heading over a part's answers, which names none.
bool is_part_heading(const std::string& text) {
  std::string t = ascii_lower(text);
  const bool word = t.compare(0, 4, "part") == 0;
  if (word) t = trim(t.substr(4));
  while (!t.empty() && (t.back() == ':' || t.back() == '.')) t.pop_back();
  if (t.size() > 2 && t.front() == '(' && t.back() == ')')
    return is_part_id(t.substr(1, t.size() - 2));
  if (t.size() > 1 && t.back() == ')') return is_part_id(t.substr(0, t.size() - 1));
  return word && is_part_id(t);
}

// Whether a word names one of the key's answers (as a line's first word before a space).
using NamesAnswer = std::function<bool(const std::string&)>;

// NAME = ANSWER or NAME: ANSWER, or NAME ANSWER where `names_answer` says the word names one;
// comments, part headings and blank lines give nothing.
std::optional<Line> read_line(const std::string& raw, int number, const NamesAnswer& names_answer) {
  const std::string text = trim(without_comments(raw));
  if (text.empty() || is_part_heading(text)) return {};
  if (const auto named = answer_line(text)) return Line{number, named->name, named->answer, text};
  if (const auto spaced = names_answer ? spaced_answer_line(text) : std::nullopt;
      spaced && names_answer(spaced->name)) {
    return Line{number, spaced->name, spaced->answer, text};
  }
  return Line{number, without_part_mark(text), "", text};
}

// UTF-16 with its byte-order mark (what Windows' Notepad saves as "Unicode") as UTF-8, by the
// C library's iconv.
std::string utf8_of_utf16(const std::string& bytes) {
  const iconv_t cd = iconv_open("UTF-8", "UTF-16");  // the mark says which byte order
  if (cd == reinterpret_cast<iconv_t>(static_cast<std::intptr_t>(-1)))
    throw InputError(
        "--answers: the file is UTF-16, which this system cannot read; save it as UTF-8");
  // A 2-byte unit becomes at most 3 bytes, a 4-byte pair 4.
  std::string out(bytes.size() / 2 * 3 + 4, '\0');
  char* in = const_cast<char*>(bytes.data());  // iconv's signature; it reads, never writes
  char* at = out.data();
  std::size_t in_left = bytes.size(), out_left = out.size();
  const std::size_t done = iconv(cd, &in, &in_left, &at, &out_left);
  iconv_close(cd);
  if (done == static_cast<std::size_t>(-1)) {
    throw InputError(fmt::format(
        "--answers: the file starts as UTF-16 but breaks off at byte {}; save it as UTF-8",
        bytes.size() - in_left));
  }
  out.resize(out.size() - out_left);
  return out;
}

// A submission's text as the lines are read: UTF-8 without a byte-order mark, lines ended by
// '\n'. Students hand in what their editors save: UTF-16 (Notepad's "Unicode"), a UTF-8 mark,
// Windows' CR LF or the old Mac's lone CR. A NUL byte left after that is no text.
std::string submission_lines_text(const std::string& bytes) {
  std::string text = starts_as_utf16(bytes) ? utf8_of_utf16(bytes) : bytes;
  if (text.compare(0, 3, "\xef\xbb\xbf") == 0) text.erase(0, 3);
  if (const std::size_t nul = text.find('\0'); nul != std::string::npos) {
    throw InputError(fmt::format(
        "--answers: the file holds a NUL byte (at byte {}): it is not text, or UTF-16 without "
        "its mark; save it as UTF-8",
        nul));
  }
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\r') {
      out += text[i];
    } else if (i + 1 == text.size() || text[i + 1] != '\n') {
      out += '\n';  // CR LF is one end of line, read at its LF; a lone CR is one too
    }
  }
  return out;
}

// "= 0.00072 kg m²", "≈ 4.995 rad/s": a line that is the value under a closed form, as the key
// prints it, with no name before its sign.
bool is_value_line(const std::string& text) {
  const auto line = answer_line(text);
  return line && line->name.empty() && !line->answer.empty() &&
         (line->separator == "=" || line->separator == "≈");
}

std::vector<Line> read_lines(const std::string& bytes, const NamesAnswer& names_answer = {}) {
  if (bytes.size() > kMaxSubmissionBytes) {
    throw InputError(fmt::format("--answers: the submission has {} bytes; at most {} are read",
                                 bytes.size(), kMaxSubmissionBytes));
  }
  const std::string text = submission_lines_text(bytes);
  std::vector<std::string> raws;
  std::istringstream in(text);
  for (std::string raw; std::getline(in, raw);) raws.push_back(raw);
  std::vector<Line> out;
  for (std::size_t at = 0; at < raws.size(); ++at) {
    auto line = read_line(raws[at], static_cast<int>(at) + 1, names_answer);
    if (!line) continue;
    // A matrix over several lines: while a list's bracket is open (as NumPy prints one), or
    // while rows in brackets follow a row (as wobble's key prints one, its unit after the
    // last), the next lines continue the answer; so does the value under a closed form, as the
    // key prints it ("I0 = m·R²/4" ⏎ "   = 0.00072 kg m²"), read as the key's whole line. A
    // blank line, or the limit, ends it.
    for (int more = 1; more < kMostAnswerLines && at + 1 < raws.size(); ++more) {
      const std::string next = trim(without_comments(raws[at + 1]));
      const std::string answer = trim(line->answer);
      const bool open = list_left_open(answer);
      const bool next_row = !answer.empty() && answer.back() == ']' && !next.empty() &&
                            next.front() == '[' && !answer_line(next);
      const bool next_value = !answer.empty() && !open && is_value_line(next);
      if (next.empty() || !(open || next_row || next_value)) break;
      line->answer += (next_value ? " " : "\n") + next;
      ++at;
    }
    out.push_back(*line);
  }
  return out;
}
}  // namespace

std::optional<NamedAnswer> answer_line(const std::string& line) {
  const std::string text = without_code_marks(line);
  std::size_t at = std::string::npos, length = 1;
  for (const char* separator : {"=", ":", "≈", "≃", "∼"}) {
    if (const std::size_t found = text.find(separator); found < at) {
      at = found;
      length = std::char_traits<char>::length(separator);
    }
  }
  if (at == std::string::npos) return std::nullopt;
  std::string name = without_part_mark(trim(text.substr(0, at)));
  // "rate_axis2 [rad/s or 1/s] = ..": the worksheet's prompt pasted with its unit.
  if (const std::size_t open = name.rfind(" ["); open != std::string::npos && name.back() == ']')
    name = trim(name.substr(0, open));
  // "rate_axis2 == 1.772", "k := 0.8": a separator typed twice (as a program's comparison or
  // assignment is written) is one; the answer starts after the last.
  const std::size_t answer_at = text.find_first_not_of("=: \t", at + length);
  return NamedAnswer{name, answer_at == std::string::npos ? "" : text.substr(answer_at),
                     text.substr(at, length)};
}

namespace {
// What may follow a factor in an expression, so that a word before it is no label: an operator
// ("*", "/", "^", "·", "×", "⋅"), a sign with a space after it ("ω3 − 3"), or a closing bracket
// or separator.
bool goes_on_as_expression(const std::string& rest) {
  for (const char* op :
       {"*", "/", "^", "·", "×", "⋅", "∙", ")", "]", "}", ",", ";", "!", "'", "′"}) {
    if (rest.rfind(op, 0) == 0) return true;
  }
  for (const char* sign : {"+", "-", "−"}) {
    const std::size_t n = std::char_traits<char>::length(sign);
    if (rest.rfind(sign, 0) == 0 && (rest.size() == n || rest[n] == ' ' || rest[n] == '\t'))
      return true;
  }
  return false;
}

// A relation, "E < 8 J", "θ ∈ [30°, 44.7°]", "theta in (..)", "E -> 8 J" (Mathematica's rule):
// a bound, a range or an equation, read as such (inequality.hpp), whose name labels nothing.
bool has_relation(const std::string& text) {
  for (const char* sign : {"<", ">", "≤", "≥", "⩽", "⩾", "∈", "→", "⟶", "≠", "⇒", " in "}) {
    if (text.find(sign) != std::string::npos) return true;
  }
  return false;
}
}  // namespace

std::optional<NamedAnswer> spaced_answer_line(const std::string& line) {
  if (answer_line(line) || has_relation(line)) return std::nullopt;
  const std::string text = without_part_mark(without_code_marks(line));
  const std::size_t space = text.find_first_of(" \t");
  if (space == std::string::npos) return std::nullopt;
  const std::string rest = trim(text.substr(space));
  if (rest.empty() || goes_on_as_expression(rest)) return std::nullopt;
  return NamedAnswer{text.substr(0, space), rest, " "};
}

bool starts_as_number(const std::string& answer) {
  std::string_view s = answer;
  for (const char* sign : {"+", "-", "−"}) {
    if (s.rfind(sign, 0) == 0) {
      s.remove_prefix(std::char_traits<char>::length(sign));
      break;
    }
  }
  return !s.empty() && (is_digit(s[0]) || s[0] == '.' || s[0] == '[' || s[0] == '(');
}

bool SubmissionResult::all_correct() const {
  return problems.empty() && std::all_of(answers.begin(), answers.end(),
                                         [](const auto& a) { return a.verdict.correct; });
}

std::optional<long> submission_variant(const std::string& text) {
  for (const auto& line : read_lines(text)) {
    if (line.name != "variant") continue;
    try {
      std::size_t used = 0;
      const long n = std::stol(line.answer, &used);
      if (used == line.answer.size()) return n;
    } catch (const std::exception&) {
    }
    throw InputError(fmt::format("--answers: line {}: variant '{}' is not a whole number",
                                 line.number, line.answer));
  }
  return {};
}

namespace {
bool is_answer_name(const Key& key, const std::string& name) {
  return std::any_of(key.parts.begin(), key.parts.end(), [&](const PartKey& p) {
    return std::any_of(p.answers.begin(), p.answers.end(),
                       [&](const Answer& a) { return a.name == name; });
  });
}

}  // namespace

SubmissionResult judge_submission(const Context& ctx, const std::string& text, const Options& opt) {
  SubmissionResult result;
  std::vector<std::pair<int, std::string>> problems;  // each with its line, said in line order
  std::map<std::string, Line> given;
  // A line names an answer as `wobble check` takes its name (name_in_key): by its name, or by
  // its spelling, "I_0 = ..." or "L_{0,\mathrm{body}} = ..." as a LaTeX handout sets the names,
  // or by a name the steps write for it, "E = .." for the heavy top's energy. Each line's name is
  // looked up once (a submission may have thousands of lines).
  const NamesInKey in_key(ctx.key);
  // "omega3_min 118.8 rad/s": a first word that names an answer, those that do not exist at
  // these values too, labels the rest.
  const auto names_answer = [&](const std::string& word) {
    return asks_for(ctx.key, in_key(word));
  };
  for (const auto& line : read_lines(text, names_answer)) {
    if (line.name == "variant") continue;
    if (line.answer.empty() && line.name.find_first_of(" \t") != std::string::npos) {
      problems.emplace_back(
          line.number, fmt::format("line {}: '{}' is not NAME = ANSWER", line.number, line.name));
    } else if (line.name.empty()) {
      problems.emplace_back(line.number,
                            fmt::format("line {}: '{}' has no name before its sign; write NAME = "
                                        "ANSWER",
                                        line.number, printable(line.text, 40)));
    } else if (!given.emplace(line.name, line).second) {
      problems.emplace_back(line.number,
                            fmt::format("line {}: {} is answered twice (the first is judged)",
                                        line.number, line.name));
    }
  }
  std::map<std::string, std::string> named;  // each line's name -> the answer's, or itself
  for (auto& [name, line] : given) {
    std::string answer = in_key(name);
    // "dω₁/dt = -0.5 ω₂ω₃, dω₂/dt = ..": Euler's equations, whose first label names no answer,
    // are the whole line's answer, for their coefficients.
    if (answer == name && !is_answer_name(ctx.key, name)) {
      const std::string whole = name + " = " + line.answer;
      if (const std::string euler = euler_equations_answer(ctx, whole); !euler.empty()) {
        answer = euler;
        line.answer = whole;
      }
    }
    named.emplace(name, answer);
  }
  const auto names = [&](const std::string& line_name, const std::string& answer) {
    return named.at(line_name) == answer;
  };
  // The first line naming the answer.
  const auto line_for = [&](const std::string& answer) {
    auto first = given.end();
    for (auto g = given.begin(); g != given.end(); ++g) {
      if (names(g->first, answer) &&
          (first == given.end() || g->second.number < first->second.number))
        first = g;
    }
    return first;
  };
  for (const auto& part : ctx.key.parts) {
    for (const auto& a : part.answers) {
      SubmittedAnswer s{part.id, a.name, false, "", {}};
      const auto it = line_for(a.name);
      if (it == given.end() || it->second.answer.empty()) {
        s.verdict = {false, "incorrect: " + a.name + " is not answered", {}};
      } else {
        s.answered = true;
        s.typed = it->second.answer;
        try {
          s.verdict = judge(ctx, a, s.typed, opt);
        } catch (const InputError& e) {
          // Wrong all the same, but named apart from a wrong value: what the student must mend
          // is how the line is written, and the line number says where.
          s.verdict = {false,
                       fmt::format("unreadable: {} (line {}): {}", a.name, it->second.number,
                                   without_option(e.what())),
                       {}};
        }
      }
      if (it != given.end()) given.erase(it);
      result.answers.push_back(std::move(s));
    }
    // An answer that does not exist at these values is asked as the others are ("none" is right:
    // absent_answer.hpp), so that every variant's submission has the same answers to give.
    // Without the key's reason, as an autograder's verdicts are shown before a resubmission: a
    // slow top's gives ω3, part (c)'s answer.
    for (const auto& name : part.absent) {
      const auto it = line_for(name);
      if (it == given.end() || it->second.answer.empty()) {
        result.answers.push_back(
            {part.id, name, false, "", {false, "incorrect: " + name + " is not answered", {}}});
      } else {
        const auto verdict =
            judge_absent(ctx.key, part.id, name, it->second.answer, /*with_reason=*/false);
        result.answers.push_back({part.id, name, true, it->second.answer, *verdict});
      }
      if (it != given.end()) given.erase(it);
    }
  }
  for (const auto& [name, line] : given) {
    std::string all;
    const SubmittedAnswer* again = nullptr;
    for (const auto& s : result.answers) {
      all += (all.empty() ? "" : ", ") + s.name;
      if (names(name, s.name)) again = &s;
    }
    problems.emplace_back(
        line.number, again != nullptr
                         ? fmt::format("line {}: '{}' answers {} again (the first is judged)",
                                       line.number, name, again->name)
                         : fmt::format("line {}: '{}' is no answer of this problem (answers: {})",
                                       line.number, name, all));
  }
  std::stable_sort(problems.begin(), problems.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  for (auto& [number, problem] : problems) result.problems.push_back(std::move(problem));
  return result;
}

}  // namespace wobble::check
