// Both codes' speed on the loadings they both ran (oedometer and shear loads; the micro
// scenes are too small to time), from the wall time each run wrote in its summary.json.
#pragma once
#include <filesystem>
#include <string>

namespace crosscheck {

namespace fs = std::filesystem;

class SpeedTally {
 public:
  // Adds one loading (what: its label). The oedometer's step counts are equal; a shear
  // load's differ a little (consolidation ends when the stress holds, a chaotic moment), so
  // each code's rate is its own particle-steps / seconds. Runs without a rate are skipped.
  void add(const fs::path& colza_out, const fs::path& yade_out, const std::string& what);
  // The lines crosscheck prints after its table (and keeps with it).
  std::string text() const;

 private:
  double colza_particle_steps_ = 0.0, colza_seconds_ = 0.0;
  double yade_particle_steps_ = 0.0, yade_seconds_ = 0.0, yade_engine_seconds_ = 0.0;
  std::string what_;
};

}  // namespace crosscheck
