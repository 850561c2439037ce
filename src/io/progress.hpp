// Progress display for long runs: stage, fraction done and ETA on a terminal (stderr),
// nothing when stderr is not a terminal (CI logs, pipes) or when disabled.
#pragma once
#include <chrono>
#include <string>

namespace colza {

class Progress {
 public:
  explicit Progress(bool enabled);  // shown only if enabled and stderr is a terminal
  static Progress quiet() { return Progress(false); }
  void start_stage(const std::string& name);
  // fraction in [0, 1] (negative: unknown); detail is free text such as "F = 1.2 kN".
  void update(double fraction, const std::string& detail);
  void end_stage();
  bool active() const { return active_; }

 private:
  bool active_;
  std::string stage_;
  std::chrono::steady_clock::time_point stage_start_, last_print_;
};

}  // namespace colza
