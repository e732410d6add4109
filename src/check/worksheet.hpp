#pragma once
/// @file
/// The interactive worksheet: a problem part by part, each answer judged as `wobble check`
/// does. At a prompt: an answer, or `?` for the hint, `!` to reveal the answer, `s` to skip the
/// part, `q` to quit. After a second wrong try the hint comes by itself. End of input quits, so
/// piped input never waits.
#include <iosfwd>
#include <string>

#include "check/judge.hpp"
#include "problem/problem.hpp"

namespace wobble::check {

struct WorksheetSummary {
  int right = 0, revealed = 0, skipped = 0, not_reached = 0;
};

/// Prints `intro` (the statement with its numbers), then runs the parts, then the summary.
/// `echo` repeats each line read (for piped input, which a terminal does not show).
WorksheetSummary run_worksheet(std::istream& in, std::ostream& out, const std::string& intro,
                               const Problem& problem, const Context& ctx, const Options& opt,
                               bool echo);

}  // namespace wobble::check
