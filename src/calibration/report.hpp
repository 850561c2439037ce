// Calibration outputs: DIR/summary.json (machine-readable) and DIR/report.md (design table,
// surrogate fits, solution with uncertainty, validation against the measured data).
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "calibration/calibrate.hpp"

namespace colza::calibration {

struct ReportContext {
  std::string stage, spec_file, title, measured_file, notes;
  std::string runs_dir = "runs";          // where the DEM runs are kept, as the report names it (--runs)
  std::vector<std::string> run_ids;       // per result.runs entry (DEM fingerprints), may be empty
  std::vector<bool> run_reused;
  std::vector<double> run_wall_seconds;
  double wall_seconds = 0.0;
  std::size_t paper_design_runs = 0;      // the paper's design on the same targets: design points + 1 validation
  std::vector<std::string> extra_warnings;
  nlohmann::json measured;                // where the targets came from (summary.json "measured"), may be null
  std::string measured_section;           // the same for report.md (markdown), may be empty
};

nlohmann::json calibration_summary(const Problem& problem, const CalibrationResult& result, const ReportContext& ctx);
std::string calibration_report(const Problem& problem, const CalibrationResult& result, const ReportContext& ctx);

}  // namespace colza::calibration
