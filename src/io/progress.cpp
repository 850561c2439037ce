#include "io/progress.hpp"

#include <cstdio>
#include <unistd.h>

namespace colza {

Progress::Progress(bool enabled) : active_(enabled && ::isatty(STDERR_FILENO)) {}

void Progress::start_stage(const std::string& name) {
  stage_ = name;
  stage_start_ = last_print_ = std::chrono::steady_clock::now();
}

void Progress::update(double fraction, const std::string& detail) {
  if (!active_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_print_ < std::chrono::milliseconds(250)) return;
  last_print_ = now;
  const double elapsed = std::chrono::duration<double>(now - stage_start_).count();
  char eta[32] = "--:--";
  if (fraction > 0.01 && fraction <= 1.0) {
    const int remaining = static_cast<int>(elapsed * (1.0 - fraction) / fraction);
    std::snprintf(eta, sizeof eta, "%02d:%02d", remaining / 60, remaining % 60);
  }
  if (fraction >= 0.0)
    std::fprintf(stderr, "\r\033[K[%s] %5.1f%%  %s  elapsed %.0f s  ETA %s", stage_.c_str(), 100.0 * fraction,
                 detail.c_str(), elapsed, eta);
  else
    std::fprintf(stderr, "\r\033[K[%s] %s  elapsed %.0f s", stage_.c_str(), detail.c_str(), elapsed);
  std::fflush(stderr);
}

void Progress::end_stage() {
  if (!active_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - stage_start_).count();
  std::fprintf(stderr, "\r\033[K[%s] done in %.1f s\n", stage_.c_str(), elapsed);
}

}  // namespace colza
