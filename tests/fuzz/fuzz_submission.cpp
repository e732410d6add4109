// A whole answers file (`wobble check --answers`, the Gradescope autograder): lines of
// NAME = ANSWER, a variant line, comments, anything a student uploads, judged against a key
// with a tensor, principal moments and principal axes, and against a heavy top's whose steady
// precession does not exist at its values (answers judged "none").
#include "check/submission.hpp"
#include "fuzz_common.hpp"
#include "problem/values.hpp"
#include "solvers/catalog.hpp"
#include "solvers/solve.hpp"

namespace {
struct Fixture {
  explicit Fixture(const std::string& id, const std::vector<std::string>& sets = {})
      : problem(wobble::find_problem(id)),
        values(wobble::parameter_values(problem, sets)),
        key(wobble::solve(problem, values)),
        table(problem.symbol_table()) {}
  wobble::Problem problem;
  wobble::sym::Values values;
  wobble::Key key;
  wobble::sym::SymbolTable table;
};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Fixture masses("four-masses"), slow_top("heavy-top", {"psidot0=10"});
  const std::string text = wobble::fuzz::text_of(data, size);
  wobble::fuzz::expect_clean([&] { (void)wobble::check::submission_variant(text); });
  for (const Fixture* f : {&masses, &slow_top}) {
    wobble::fuzz::expect_clean([&] {
      (void)wobble::check::judge_submission({f->key, f->table, f->values}, text, {});
    });
  }
  return 0;
}
