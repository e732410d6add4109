#include "check/worksheet.hpp"

#include <fmt/format.h>

#include <istream>
#include <ostream>

#include "check/text.hpp"
#include "core/input_error.hpp"

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
  if (!a.unit.empty()) v += " " + a.unit;
  return a.symbolic.empty() ? v : a.symbolic + " = " + v;
}

enum class Outcome { right, revealed, skipped, quit, nothing };

struct Session {
  const ReadLine& read_line;
  std::ostream& out;
  const Context& ctx;
  const Options& opt;
  bool quit_after_reveal = false;

  bool read(const std::string& prompt, std::string& line) {
    if (!read_line(prompt, line)) {
      out << "\n(end of input)\n";
      return false;
    }
    line = trim(line);
    return true;
  }

  Outcome part(const PartKey& part, const std::string& hint) {
    out << fmt::format("\n({}) {}\n", part.id, part.question);
    if (part.answers.empty()) {
      // Nothing exists to answer at these values (no steady precession): say why, move on.
      out << "  nothing to answer at these values: " +
                 (part.steps.empty() ? std::string("see `wobble solve`") : part.steps.back().text) +
                 "\n";
      return Outcome::nothing;
    }
    bool revealed = false, hint_shown = false;
    const auto give_hint = [&] {
      out << (hint.empty() ? "  no hint for this part; '!' reveals the answer\n"
                           : "  hint: " + hint + "\n");
      hint_shown = true;
    };
    for (const auto& a : part.answers) {
      int wrong = 0;
      while (true) {
        std::string line;
        if (!read(fmt::format("  {}{} = ", a.name, a.unit.empty() ? "" : " [" + a.unit + "]"),
                  line) ||
            line == "q") {
          quit_after_reveal = revealed;  // a part quit after a reveal counts as revealed
          return Outcome::quit;
        }
        if (line == "s") return Outcome::skipped;
        if (line == "?") {
          give_hint();
          continue;
        }
        if (line == "!") {
          out << "  answer: " << shown(a) << "\n";
          revealed = true;
          break;
        }
        if (line.empty()) continue;
        try {
          const Verdict v = judge(ctx, a, line, opt);
          out << "  " << v.line << "\n";
          for (const auto& f : v.feedback) out << "    " << f << "\n";
          if (v.correct) break;
          if (++wrong == 2 && !hint_shown) give_hint();
        } catch (const InputError& e) {
          out << "  cannot read that: " << without_option(e.what()) << "\n";
        }
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
                               const Problem& problem, const Context& ctx, const Options& opt) {
  out << intro;
  out << "\nAnswer each part (units optional; SI if none). At any prompt: ? hint, ! reveal, "
         "s skip the part, q quit.\n";
  Session session{read, out, ctx, opt};
  WorksheetSummary sum;
  bool quit = false;
  for (const auto& part : ctx.key.parts) {
    if (quit) {
      ++sum.not_reached;
      continue;
    }
    std::string hint;
    for (const auto& spec : problem.parts) {
      if (spec.id == part.id) hint = spec.hint;
    }
    switch (session.part(part, hint)) {
      case Outcome::right:
        ++sum.right;
        break;
      case Outcome::revealed:
        ++sum.revealed;
        break;
      case Outcome::nothing:
        ++sum.nothing;
        break;
      case Outcome::skipped:
        ++sum.skipped;
        break;
      case Outcome::quit:
        quit = true;
        ++(session.quit_after_reveal ? sum.revealed : sum.not_reached);
        break;
    }
  }
  out << fmt::format(
      "\nsummary: {} right, {} revealed, {} skipped, {} not reached (of {} parts{})\n", sum.right,
      sum.revealed, sum.skipped, sum.not_reached, ctx.key.parts.size(),
      sum.nothing > 0 ? fmt::format("; {} with nothing to answer", sum.nothing) : std::string());
  return sum;
}

}  // namespace wobble::check
