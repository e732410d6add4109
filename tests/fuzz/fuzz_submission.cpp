// A whole answers file (`wobble check --answers`, the Gradescope autograder): lines of
// NAME = ANSWER, a variant line, comments, anything a student uploads, judged against a key
// with a tensor, principal moments and principal axes.
#include "check/submission.hpp"
#include "fuzz_common.hpp"
#include "problem/values.hpp"
#include "solvers/catalog.hpp"
#include "solvers/solve.hpp"

namespace {
struct Fixture {
  wobble::Problem problem = wobble::find_problem("four-masses");
  wobble::sym::Values values = wobble::parameter_values(problem, {});
  wobble::Key key = wobble::solve(problem, values);
  wobble::sym::SymbolTable table = problem.symbol_table();
};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Fixture f;
  const std::string text = wobble::fuzz::text_of(data, size);
  wobble::fuzz::expect_clean([&] { (void)wobble::check::submission_variant(text); });
  wobble::fuzz::expect_clean([&] {
    (void)wobble::check::judge_submission({f.key, f.table, f.values}, text, {});
  });
  return 0;
}
