// `colza run shear` (one normal load) and `colza run shear-series` (every load of the
// config, concurrently up to --jobs, resuming loads already finished).
#pragma once
#include "cli/run_commands.hpp"
#include "config/run_config.hpp"

namespace colza {

class OutputStaging;

// One load at the config's (or --normal-stress's) normal stress, written into `out`.
void run_shear_scenario(const RunConfig& config, const RunOptions& options, OutputStaging& out);
// The series manages its own output directory (it resumes finished loads). Returns the exit code.
int run_shear_series(const RunConfig& config, const RunOptions& options);

}  // namespace colza
