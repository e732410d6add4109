#pragma once
/// @file
/// Bad input from a user (a file, an option, a value, an expression): every layer throws this or
/// a subclass, and the command line reports what() on one line and exits 2. Messages name the
/// field and the value. Broken internal invariants are std::logic_error instead.
#include <stdexcept>

namespace wobble {

struct InputError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

}  // namespace wobble
