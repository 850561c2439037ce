// Pieces shared by the `colza run` commands.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>
#include "cli/run_commands.hpp"
#include "config/run_config.hpp"
#include "scenario/stage_timing.hpp"

namespace colza {

// Model choices and provenance every summary.json carries.
nlohmann::json common_summary(const RunConfig& c, const std::string& scenario, int threads);
double total_wall_seconds(const std::vector<StageTiming>& stages);
double overall_rate(const std::vector<StageTiming>& stages);  // particle-steps per second

void run_shear_scenario(const RunConfig& config, const RunOptions& options, class OutputStaging& out);
// The series manages its own output directory (it resumes finished loads). Returns the exit code.
int run_shear_series(const RunConfig& config, const RunOptions& options);

}  // namespace colza
