#include "core/interrupt.hpp"

#include <atomic>
#include <csignal>
#include <cstring>
#include <string>

#include <signal.h>  // sigaction (POSIX)
#include <time.h>    // clock_gettime (POSIX, async-signal-safe)

namespace colza {

namespace {

// Written by the handler, read by the stepper: a lock-free atomic is async-signal-safe.
std::atomic<int> received_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);
// When the first signal came (CLOCK_MONOTONIC, ns; 0: none yet).
std::atomic<long long> first_signal_ns{0};
static_assert(std::atomic<long long>::is_always_lock_free);

// A repeat within this time of the first signal is the same request delivered twice, not a
// second Ctrl-C: timeout(1) signals its child and then its own process group, which holds the
// child too, so colza got two SIGINTs microseconds apart and stopped at once without
// removing its staging folder (2 runs in 6 of a walk-through's `timeout -s INT 6 colza run
// ...`). A person's second Ctrl-C comes later than this.
constexpr long long kSameRequestNs = 250'000'000;  // 0.25 s

long long monotonic_ns() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<long long>(t.tv_sec) * 1'000'000'000LL + t.tv_nsec;
}

extern "C" void record_signal(int signal_number) {
  const long long now = monotonic_ns();
  long long unset = 0;
  first_signal_ns.compare_exchange_strong(unset, now);  // set by the first signal only
  int none = 0;
  if (received_signal.compare_exchange_strong(none, signal_number)) return;
  if (now - first_signal_ns.load() < kSameRequestNs) return;
  // A second signal: stop now, with the default action (signal() and raise() are
  // async-signal-safe).
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
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
