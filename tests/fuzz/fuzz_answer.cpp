// Students' answers: numbers with units, vectors, matrices and expressions, judged against a
// number, a vector and a matrix of real keys.
#include "check/judge.hpp"
#include "fuzz_common.hpp"
#include "solvers/catalog.hpp"
#include "problem/values.hpp"
#include "solvers/solve.hpp"

namespace {
struct Fixture {
  wobble::Problem problem = wobble::find_problem("flying-plate");
  wobble::sym::Values values = wobble::parameter_values(problem, {});
  wobble::Key key = wobble::solve(problem, values);
  wobble::sym::SymbolTable table = problem.symbol_table();
};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const Fixture f;
  const std::string text = wobble::fuzz::text_of(data, size);
  for (const auto& part : f.key.parts) {
    for (const auto& a : part.answers) {
      if (a.name != "I0" && a.name != "I" && a.name != "L0_body" && a.name != "angle_L_e3") {
        continue;
      }
      for (const bool sigfigs : {false, true}) {
        wobble::check::Options o;
        if (sigfigs) o.sigfigs = 3;
        wobble::fuzz::expect_clean([&] {
          (void)wobble::check::judge({f.key, f.table, f.values}, a, text, o);
        });
      }
    }
  }
  return 0;
}
