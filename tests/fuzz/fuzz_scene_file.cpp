// Scene files: parse and set up in numbers (the simulation itself is bounded by the run's own
// limits and is not what a parser fuzzer is for).
#include "fuzz_common.hpp"
#include "problem/scene.hpp"
#include "simulate/scene_setup.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  wobble::fuzz::expect_clean([&] {
    const wobble::Scene s = wobble::load_scene_text(wobble::fuzz::text_of(data, size), "fuzz.toml");
    (void)wobble::setup_scene(s, std::vector<std::string>{});
  });
  return 0;
}
