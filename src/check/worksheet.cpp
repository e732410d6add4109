#include "check/worksheet.hpp"

#include <fmt/format.h>

#include <cctype>
#include <functional>
#include <istream>
#include <ostream>

#include "check/absent_answer.hpp"
#include "check/brackets.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"
#include "core/word_wrap.hpp"
#include "symbolic/plain_text.hpp"
#include "symbolic/unicode_notation.hpp"

namespace wobble::check {

namespace {
std::string shown(const Answer& a) {
  const auto& d = a.value.data;
  std::string v;
  if (a.value.shape == Value::Shape::scalar) {
    v = format_number(d[0]);
  } else if (a.value.shape == Value::Shape::vector) {
    v = "[";
    for (std::size_t i = 0; i < d.size(); ++i) v += (i ? ", " : "") + format_number(d[i]);
    v += "]";
  } else {
    v = "[";
    for (std::size_t r = 0; r < a.value.rows; ++r) {
      v += r ? ", [" : "[";
      for (std::size_t c = 0; c < a.value.cols; ++c)
        v += (c ? ", " : "") + format_number(d[r * a.value.cols + c]);
      v += "]";
    }
    v += "]";
  }
  // In the terminal's notation, as the statement above it and the text key print it
  // ("m·R²/4 = 0.00072 kg m²"): what a student copies reads back in check.
  if (!a.unit.empty()) v += " " + sym::to_unicode(a.unit);
  return a.symbolic.empty() ? v : sym::to_unicode(a.symbolic) + " = " + v;
}

enum class Outcome { right, revealed, skipped, quit };

// What a line asks for besides an answer: the symbol or the word, in any case ("Quit", "HINT").
enum class Command { none, hint, reveal, skip, quit, help };

Command command_of(const std::string& line) {
  const std::string word = ascii_lower(line);
  if (word == "?" || word == "hint") return Command::hint;
  if (word == "!" || word == "reveal") return Command::reveal;
  if (word == "s" || word == "skip") return Command::skip;
  if (word == "q" || word == "quit" || word == "exit") return Command::quit;
  if (word == "help") return Command::help;
  return Command::none;
}

constexpr const char* kCommands =
    "At any prompt: ? hint, ! reveal, s skip the part, q quit (help: the commands as words).";
constexpr const char* kCommandWords =
    "commands, as symbols or words in any case: ? or hint (the part's hint), ! or reveal (the "
    "answer), s or skip (the next part), q, quit or exit (the summary)";

struct Session {
  const ReadLine& read_line;
  std::ostream& out;
  const Context& ctx;
  const Options& opt;
  std::size_t width;  ///< the terminal's columns, 0 if none is known
  bool quit_after_reveal = false;
  int answered_before_quit = 0;  ///< answers of the part quit in that were right or revealed

  // One line of the worksheet's own, broken at spaces to the width: after `first`, each further
  // line after `rest`.
  void say(const std::string& text, const std::string& first, const std::string& rest) {
    out << word_wrapped(text, width, first, rest);
  }

  bool read(const std::string& prompt, std::string& line) {
    if (!read_line(prompt, line)) {
      out << "\n(end of input)\n";
      return false;
    }
    line = trim(line);
    return true;
  }

  // An answer pasted over several lines, as NumPy prints a matrix ("[[ 4.33 -0.5 ..]" then
  // " [-0.5 ..]]"): while a list's bracket is open, the next line continues it, under a prompt
  // of dots. An empty line, the end of input or the limit ends it as it stands (the judge says
  // what is open).
  bool read_answer(const std::string& prompt, std::string& line) {
    if (!read(prompt, line)) return false;
    const std::size_t prompt_columns = columns(prompt);  // its unit may have a '²'
    const std::string dots =
        fmt::format("{:>{}} ", "...", prompt_columns > 1 ? prompt_columns - 1 : 3);
    for (int lines = 1; list_left_open(line) && lines < kMostAnswerLines; ++lines) {
      std::string more;
      if (!read_line(dots, more) || trim(more).empty()) break;
      line += "\n" + trim(more);
    }
    return true;
  }

  // One answer asked until it is right, revealed, skipped or quit: `judged` gives the verdict
  // on a line, `revealed_as` is what '!' shows (one line, to be copied), `why` a line under it.
  enum class Asked { right, revealed, skipped, quit };
  struct Asking {
    std::string prompt, revealed_as, why;
    std::function<Verdict(const std::string&)> judged;
  };
  Asked ask(const Asking& asking, const std::function<void()>& give_hint, const bool& hint_shown) {
    int wrong = 0;
    while (true) {
      std::string line;
      const bool more = read_answer(asking.prompt, line);
      const Command command = more ? command_of(line) : Command::quit;
      if (command == Command::quit) return Asked::quit;
      if (command == Command::skip) return Asked::skipped;
      if (command == Command::help) {
        say(kCommandWords, "  ", "    ");
        continue;
      }
      if (command == Command::hint) {
        give_hint();
        continue;
      }
      if (command == Command::reveal) {
        out << "  answer: " << asking.revealed_as << "\n";
        if (!asking.why.empty()) say(asking.why, "    ", "      ");
        return Asked::revealed;
      }
      if (line.empty()) continue;
      try {
        const Verdict v = asking.judged(line);
        say(v.line, "  ", "    ");
        for (const auto& f : v.feedback) say(f, "    ", "      ");
        if (v.correct) return Asked::right;
        if (++wrong == 2 && !hint_shown) give_hint();
      } catch (const InputError& e) {
        say("cannot read that: " + without_option(e.what()), "  ", "    ");
      }
    }
  }

  // The questions of a part: each answer, then each answer that does not exist at these values
  // (a slow top's steady precession), whose answer is "none" (absent_answer.hpp): asked as the
  // others are, since saying so outright would give the answer away.
  std::vector<Asking> questions(const PartKey& part) const {
    std::vector<Asking> asked;
    // "  omega3 [rad/s] = ": the answer's name and the unit it is asked in, if any.
    const auto prompt = [](const std::string& name, const std::string& unit) {
      return fmt::format("  {}{} = ", name, unit.empty() ? "" : " [" + sym::to_unicode(unit) + "]");
    };
    for (const auto& a : part.answers) {
      asked.push_back({prompt(a.name, asked_unit(a)), shown(a), "",
                       [this, &a](const std::string& line) { return judge(ctx, a, line, opt); }});
    }
    for (std::size_t i = 0; i < part.absent.size(); ++i) {
      const std::string& name = part.absent[i];
      const std::string unit = i < part.absent_unit.size() ? part.absent_unit[i] : "";
      asked.push_back({prompt(name, unit), "none at these values", part.absent_line(i),
                       [this, &part, &name](const std::string& line) {
                         return *judge_absent(ctx.key, part.id, name, line, /*with_reason=*/true);
                       }});
    }
    return asked;
  }

  Outcome part(const PartKey& part, const std::string& hint) {
    out << "\n";
    say(plain_text(part.question), "(" + part.id + ") ", "    ");
    bool revealed = false, hint_shown = false;
    const auto give_hint = [&] {
      if (hint.empty()) {
        say("no hint for this part; '!' reveals the answer", "  ", "    ");
      } else {
        say(plain_text(hint), "  hint: ", "    ");
      }
      hint_shown = true;
    };
    int answered = 0;
    const std::vector<Asking> asked = questions(part);
    for (std::size_t i = 0; i < asked.size(); ++i) {
      // How a vector or a matrix is typed, above its prompt (beside it, the answer would start
      // near the terminal's edge): "(a vector [.., .., ..] along e₁, e₂, e₃)".
      if (i < part.answers.size()) {
        if (const std::string form = answer_form(part.answers[i]); !form.empty())
          say("(" + form + ")", "  ", "   ");
      }
      switch (ask(asked[i], give_hint, hint_shown)) {
        case Asked::quit:
          quit_after_reveal = revealed;  // a part quit after a reveal counts as revealed
          answered_before_quit = answered;
          return Outcome::quit;
        case Asked::skipped:
          return Outcome::skipped;
        case Asked::revealed:
          revealed = true;
          [[fallthrough]];
        case Asked::right:
          ++answered;
          break;
      }
    }
    return revealed ? Outcome::revealed : Outcome::right;
  }
};
}  // namespace

ReadLine stream_lines(std::istream& in, std::ostream& out, bool echo) {
  return [&in, &out, echo](const std::string& prompt, std::string& line) {
    out << prompt << std::flush;
    if (!std::getline(in, line)) return false;
    if (echo) out << trim(line) << "\n";  // piped: show what was read, so the transcript reads well
    return true;
  };
}

WorksheetSummary run_worksheet(const ReadLine& read, std::ostream& out, const std::string& intro,
                               const Problem& problem, const Context& ctx, const Options& opt,
                               std::size_t width) {
  out << reflowed(intro, width) << "\n";
  Session session{read, out, ctx, opt, width};
  session.say(std::string("Answer each part (units optional; SI if none). ") + kCommands, "", "");
  WorksheetSummary sum;
  bool quit = false;
  for (const auto& part : ctx.key.parts) {
    if (quit) {
      ++sum.not_reached;
      continue;
    }
    switch (session.part(part, problem.hint(part.id))) {
      case Outcome::right:
        ++sum.right;
        break;
      case Outcome::revealed:
        ++sum.revealed;
        break;
      case Outcome::skipped:
        ++sum.skipped;
        break;
      case Outcome::quit:
        quit = true;
        if (session.quit_after_reveal) {
          ++sum.revealed;
        } else if (session.answered_before_quit > 0) {
          // Begun, some answers right, then left: neither right nor untouched.
          sum.unfinished =
              fmt::format("({}) left unfinished, {} of its {} answers right", part.id,
                          session.answered_before_quit, part.answers.size() + part.absent.size());
        } else {
          ++sum.not_reached;
        }
        break;
    }
  }
  out << "\n";
  session.say(
      fmt::format("summary: {} right, {} revealed, {} skipped, {} not reached (of {} parts{})",
                  sum.right, sum.revealed, sum.skipped, sum.not_reached, ctx.key.parts.size(),
                  sum.unfinished.empty() ? "" : "; " + sum.unfinished),
      "", "  ");
  return sum;
}

}  // namespace wobble::check
