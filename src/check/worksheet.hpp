#pragma once
/// @file
/// The interactive worksheet: a problem part by part, each answer judged as `wobble check`
/// does. At a prompt: an answer, or `?` for the hint, `!` to reveal the answer, `s` to skip the
/// part, `q` to quit, or the words (hint, reveal, skip, quit or exit, help for the list; any
/// case): they take precedence over a symbol of the same name. After a second wrong try the hint
/// comes by itself. End of input quits, so piped input never waits. An answer that does not exist
/// at these values (a slow top's steady precession) is asked as the others are: "none" is right
/// (absent_answer.hpp).
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <string>

#include "check/judge.hpp"
#include "problem/problem.hpp"

namespace wobble::check {

struct WorksheetSummary {
  int right = 0, revealed = 0, skipped = 0, not_reached = 0;
  /// The part quit in after some of its answers were right (none revealed), said as
  /// "(a) left unfinished, 1 of its 2 answers right"; empty if none. Counted in no number.
  std::string unfinished;
};

/// Where the answers come from: shows `prompt`, reads one line into `line`; false at the end of
/// the input. The command line gives a line editor at a terminal (history, arrow keys), else
/// stream_lines.
using ReadLine = std::function<bool(const std::string& prompt, std::string& line)>;

/// Lines from a stream, the prompt written to `out`; `echo` repeats each line read (for piped
/// input, which a terminal does not show).
ReadLine stream_lines(std::istream& in, std::ostream& out, bool echo);

/// Prints `intro` (the statement with its numbers), then runs the parts, then the summary. Its
/// own lines (questions, verdicts, feedback, hints) are broken at spaces to `width` columns, a
/// terminal's (core/word_wrap.hpp); 0 for none. A revealed answer stays one line, to be copied.
WorksheetSummary run_worksheet(const ReadLine& read, std::ostream& out, const std::string& intro,
                               const Problem& problem, const Context& ctx, const Options& opt,
                               std::size_t width = 0);

}  // namespace wobble::check
