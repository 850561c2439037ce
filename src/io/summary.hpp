// summary.json helpers (nlohmann::json).
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>
#include "core/stage_timing.hpp"

namespace colza {

nlohmann::json stages_json(const std::vector<StageTiming>& stages);
void write_json(const std::string& file, const nlohmann::json& value);
// A JSON file colza wrote earlier (a summary.json, a series' sample.json). Unreadable or
// not JSON (edited, truncated): ConfigError naming the file and what to do.
nlohmann::json read_json_file(const std::string& file);

}  // namespace colza
