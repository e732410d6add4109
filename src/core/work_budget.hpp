#pragma once
/// @file
/// Stopping long work: at the user's request (Ctrl-C, SIGTERM) and past a budget.
///
/// A signal handler may only set a flag; the loops that can run long (integrator steps, samples,
/// keys, benchmarks) poll it and unwind by throwing Interrupted, so that every temporary file is
/// removed on the way out and nothing half-written is left. A run's budget counts right-hand-side
/// evaluations: past it, WorkLimitReached (an InputError: the input asked for too much).
#include <atomic>
#include <cstdint>
#include <stdexcept>

#include "core/input_error.hpp"

namespace wobble {

/// Thrown by the polling loops after an interrupt request.
struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted") {}
};

/// Thrown when a run's evaluations exceed its budget; what() says how many.
struct WorkLimitReached : InputError {
  using InputError::InputError;
};

/// Async-signal-safe: sets the flag only.
void request_interrupt() noexcept;
bool interrupt_requested() noexcept;
/// @throws Interrupted once request_interrupt() was called.
inline void throw_if_interrupted() {
  if (interrupt_requested()) throw Interrupted();
}

/// Installs request_interrupt() for SIGINT and SIGTERM; a second signal ends the process at once
/// (exit status 130) for a user who does not want to wait for the unwinding.
void stop_on_signals();

}  // namespace wobble
