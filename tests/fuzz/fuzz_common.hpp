#pragma once
// What every fuzz target shares: bad input must end in an InputError (a clear message, exit 2
// at the command line); anything else that escapes (a logic_error from a self-check, a
// std::out_of_range, a crash, a sanitizer report, a hang past -timeout) is a bug to fix.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/input_error.hpp"

namespace wobble::fuzz {

inline std::string text_of(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

template <class F>
void expect_clean(F&& f) {
  try {
    f();
  } catch (const wobble::InputError&) {
    // the expected way to refuse: one line naming the field and the value
  }
}

}  // namespace wobble::fuzz
