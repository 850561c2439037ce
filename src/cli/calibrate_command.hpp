// `colza calibrate density|compression|shear|load_unload|repose --spec FILE --out DIR [--mode paper|sequential]
//  [--jobs N] [--threads N] [--force] [--quiet]`: the paper's staged calibration (sections 2.2, 3.2, 3.3)
// or a sequential trust-region refinement, written to DIR/summary.json and DIR/report.md;
// design runs are kept in DIR/runs/<fingerprint>/ (or --runs RUNS/<fingerprint>/) and reused when
// the command runs again, or by another calibration of the same model sharing RUNS.
#pragma once
#include <string>

namespace colza {

struct CalibrateOptions {
  std::string stage;           // density | compression | shear
  std::string spec_path;
  std::string out_dir;
  std::string runs_dir;        // where DEM runs are kept and reused; empty: out_dir/runs
  std::string mode = "paper";  // paper | sequential
  int jobs = 1;
  int threads = 0;             // per design run; 0: default_worker_threads(jobs)
  bool force = false;
  bool quiet = false;
};

// Returns the exit code: 0 success, 2 bad input (message printed).
int calibrate_command(const CalibrateOptions& options);

}  // namespace colza
