// Wall-clock and CPU-time accounting of a scenario's stages (settling, loading, ...).
// CPU time is the process's (all threads, CLOCK_PROCESS_CPUTIME_ID): on a machine shared
// with other jobs the wall time measures the machine, the CPU time the work. With concurrent
// runs in one process (--jobs > 1: shear series, calibration) it counts them all.
#pragma once
#include <chrono>
#include <cstdint>
#include <ctime>
#include <string>
#include <vector>

namespace colza {

struct StageTiming {
  std::string name;
  std::uint64_t steps = 0;
  double particle_steps = 0.0;  // sum over steps of the particle count
  double wall_seconds = 0.0;
  double cpu_seconds = 0.0;     // process CPU time, all threads
  double particle_steps_per_second() const { return wall_seconds > 0.0 ? particle_steps / wall_seconds : 0.0; }
};

class StageClock {
 public:
  explicit StageClock(std::string name) : start_(std::chrono::steady_clock::now()), cpu_start_(process_cpu_seconds()) {
    timing_.name = std::move(name);
  }
  void count_steps(std::uint64_t steps, std::size_t particles) {
    timing_.steps += steps;
    timing_.particle_steps += static_cast<double>(steps) * static_cast<double>(particles);
  }
  StageTiming finish() {
    timing_.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    timing_.cpu_seconds = process_cpu_seconds() - cpu_start_;
    return timing_;
  }

 private:
  static double process_cpu_seconds() {
    timespec t{};
    ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
  }
  StageTiming timing_;
  std::chrono::steady_clock::time_point start_;
  double cpu_start_;
};

}  // namespace colza
