// summary.json helpers (nlohmann::json).
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>
#include "core/stage_timing.hpp"

namespace colza {

nlohmann::json stages_json(const std::vector<StageTiming>& stages);
void write_json(const std::string& file, const nlohmann::json& value);

}  // namespace colza
