// Problem files: parse, then solve at the defaults and render every format.
#include "fuzz_common.hpp"
#include "solvers/catalog.hpp"
#include "problem/values.hpp"
#include "render/render.hpp"
#include "solvers/solve.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  wobble::fuzz::expect_clean([&] {
    const wobble::Problem p =
        wobble::load_problem_text(wobble::fuzz::text_of(data, size), "fuzz.toml");
    const wobble::Key key = wobble::solve(p, wobble::parameter_values(p, {}));
    (void)wobble::render_text(key);
    (void)wobble::render_markdown(key);
    (void)wobble::render_latex(key);
    (void)wobble::render_json(key);
  });
  return 0;
}
