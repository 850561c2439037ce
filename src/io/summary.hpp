// summary.json helpers (nlohmann::json).
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>
#include "core/stage_timing.hpp"

namespace colza {

nlohmann::json stages_json(const std::vector<StageTiming>& stages);
void write_json(const std::string& file, const nlohmann::json& value);
// A JSON object colza wrote earlier (a summary.json, a series' sample.json). Unreadable,
// not JSON or not an object (edited, truncated): ConfigError naming the file and ending
// with `what_to_do`.
nlohmann::json read_json_file(const std::string& file, const std::string& what_to_do = "remove it, or pass --force");

// The type a field of such a file must have (JsonField::kind) and whether it must be there.
struct JsonField {
  enum Kind { kNumber, kString, kBoolean, kObject };
  const char* key;
  Kind kind;
  bool required = false;
};
// ConfigError naming the file and the key if a field is missing (when required) or of
// another type (an edited file): what colza reads from it afterwards cannot throw.
void require_fields(const nlohmann::json& j, const std::string& file, std::initializer_list<JsonField> fields,
                    const std::string& what_to_do = "remove it, or pass --force");

}  // namespace colza
