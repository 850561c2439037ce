// Where a calibration's targets came from: DIR/summary.json "measured" and the "Measured
// data" section of DIR/report.md (files, the values derived from them and how).
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "calibration/spec.hpp"

namespace colza::calibration {

nlohmann::json measured_data_summary(const Spec& spec);
std::string measured_data_section(const Spec& spec);  // markdown, starts with "## Measured data"

}  // namespace colza::calibration
