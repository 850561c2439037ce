// `colza diagnose --spec FILE --out DIR [--runs RUNS] [--jobs N] [--threads N] [--force]
//  [--quiet]`: what the calibrated model gets wrong against measured features, which
// candidate mechanism explains it, and the gain of adding it (src/diagnose/diagnosis.hpp),
// written to DIR/summary.json and DIR/report.md, with each calibrated model as configs
// `colza run` accepts (DIR/model-<model>-<test>.toml). DEM runs are kept in DIR/runs (or
// RUNS) and reused when the command runs again.
#pragma once
#include <string>

namespace colza {

struct DiagnoseOptions {
  std::string spec_path, out_dir, runs_dir;
  int jobs = 1;
  int threads = 0;
  bool force = false;
  bool quiet = false;
};

// Returns the exit code: 0 success, 2 bad input (message printed).
int diagnose_command(const DiagnoseOptions& options);

}  // namespace colza
