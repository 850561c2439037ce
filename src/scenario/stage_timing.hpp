// Wall-clock accounting of a scenario's stages (settling, loading, ...).
#pragma once
#include <chrono>
#include <string>
#include <vector>

namespace colza {

struct StageTiming {
  std::string name;
  std::uint64_t steps = 0;
  double particle_steps = 0.0;  // sum over steps of the particle count
  double wall_seconds = 0.0;
  double particle_steps_per_second() const { return wall_seconds > 0.0 ? particle_steps / wall_seconds : 0.0; }
};

class StageClock {
 public:
  explicit StageClock(std::string name) : start_(std::chrono::steady_clock::now()) { timing_.name = std::move(name); }
  void count_steps(std::uint64_t steps, std::size_t particles) {
    timing_.steps += steps;
    timing_.particle_steps += static_cast<double>(steps) * static_cast<double>(particles);
  }
  StageTiming finish() {
    timing_.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    return timing_;
  }

 private:
  StageTiming timing_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace colza
