// --set values: a length, an angle (degrees allowed) and a rate of a real problem.
#include "fuzz_common.hpp"
#include "solvers/catalog.hpp"
#include "problem/values.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const wobble::Problem plate = wobble::find_problem("flying-plate");
  const std::string text = wobble::fuzz::text_of(data, size);
  for (const char* name : {"R=", "alpha=", "omega="}) {
    wobble::fuzz::expect_clean([&] { (void)wobble::parameter_values(plate, {name + text}); });
  }
  wobble::fuzz::expect_clean([&] { (void)wobble::parameter_values(plate, {text}); });
  return 0;
}
