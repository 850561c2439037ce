// `colza run repose`: the angle of repose test's outputs (docs/running.md, "Angle of repose").
#pragma once
#include "cli/run_commands.hpp"
#include "config/run_config.hpp"
#include "io/output_dir.hpp"

namespace colza {

void run_repose_scenario(const RunConfig& c, const RunOptions& opt, OutputStaging& out);

}  // namespace colza
