#include "core/interrupt.hpp"

#include <atomic>
#include <csignal>
#include <cstring>
#include <string>

#include <signal.h>  // sigaction (POSIX)

namespace colza {

namespace {

// Written by the handler, read by the stepper: a lock-free atomic is async-signal-safe.
std::atomic<int> received_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void record_signal(int signal_number) {
  int none = 0;
  if (!received_signal.compare_exchange_strong(none, signal_number)) {
    // A second signal: stop now, with the default action (signal() and raise() are
    // async-signal-safe).
    std::signal(signal_number, SIG_DFL);
    std::raise(signal_number);
  }
}

const char* signal_name(int signal_number) {
  if (signal_number == SIGINT) return "SIGINT (Ctrl-C)";
  if (signal_number == SIGTERM) return "SIGTERM";
  return "a signal";
}

}  // namespace

Interrupted::Interrupted(int signal_number)
    : std::runtime_error(std::string("interrupted by ") + signal_name(signal_number)), signal_number_(signal_number) {}

void install_interrupt_handlers() {
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = record_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int interrupt_signal() { return received_signal.load(std::memory_order_relaxed); }

}  // namespace colza
