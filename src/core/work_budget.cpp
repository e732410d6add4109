#include "core/work_budget.hpp"

#include <csignal>
#include <unistd.h>

namespace wobble {

namespace {
std::atomic<bool> interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the flag is set from a signal handler");

extern "C" void on_signal(int) {
  if (interrupted.exchange(true)) ::_exit(130);  // the second Ctrl-C: no more waiting
}
}  // namespace

void request_interrupt() noexcept { interrupted.store(true); }

bool interrupt_requested() noexcept { return interrupted.load(std::memory_order_relaxed); }

void stop_on_signals() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace wobble
