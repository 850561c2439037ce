// `colza run <scenario>`: load and validate the config, run, write the results atomically.
#pragma once
#include <string>
#include <vector>

namespace colza {

struct RunOptions {
  std::string scenario;               // "oedometer" | "shear" | "shear-series" | "repose" | "scene"
  std::string config_path;            // empty: built-in defaults (= data/oedometer.toml), oedometer only
  std::vector<std::string> overrides; // --set key=value
  long long seed = -1;                // --seed, -1: from the config
  int threads = 0;                    // 0: default_worker_threads(jobs)
  std::string out_dir;
  bool force = false;
  bool quiet = false;
  double normal_stress = 0.0;         // Pa, `shear` only
  int jobs = 1;                       // concurrent loads (`shear-series`) or speeds (--speeds)
  std::vector<double> speeds;         // m/s: a speed series (speed_series_command.hpp); empty: one run
};

// Returns the process exit code: 0 success, 2 bad input (message already printed).
int run_command(const RunOptions& options);

}  // namespace colza
