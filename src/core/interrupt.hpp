// Stopping a run cleanly on Ctrl-C (SIGINT) or SIGTERM. The signal handler only records
// the request; the stepper checks it once per step (Stepper::begin_step) and throws
// Interrupted, so the run unwinds through its destructors: staging folders are removed
// (io/output_dir.hpp), earlier results stay as they were, and main() exits with 128 + the
// signal number (130 for Ctrl-C). A second signal while the first is being handled stops
// the process at once, as without the handler, unless it comes within 0.25 s of the first:
// that is the same request delivered twice (timeout(1) signals the child and its group).
#pragma once
#include <stdexcept>

namespace colza {

class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal_number);
  int signal_number() const { return signal_number_; }

 private:
  int signal_number_;
};

// Installs the handlers for SIGINT and SIGTERM (main() only; tests and library users
// keep the default behaviour).
void install_interrupt_handlers();

// The signal received since install_interrupt_handlers(), or 0.
int interrupt_signal();

inline void throw_if_interrupted() {
  if (const int s = interrupt_signal()) throw Interrupted(s);
}

}  // namespace colza
