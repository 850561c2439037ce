#include "io/summary.hpp"

#include <fstream>
#include <stdexcept>

#include "config/config_error.hpp"
#include "io/output_error.hpp"

namespace colza {

nlohmann::json stages_json(const std::vector<StageTiming>& stages) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& s : stages)
    out.push_back({{"name", s.name},
                   {"steps", s.steps},
                   {"wall_seconds", s.wall_seconds},
                   {"cpu_seconds", s.cpu_seconds},
                   {"particle_steps_per_second", s.particle_steps_per_second()}});
  return out;
}

void write_json(const std::string& file, const nlohmann::json& value) {
  std::ofstream out(file);
  if (!out) throw_cannot_write(file);
  out << value.dump(2) << '\n';
  out.close();  // the last buffer is written here: check after it
  if (!out) throw_cannot_write(file);
}

nlohmann::json read_json_file(const std::string& file, const std::string& what_to_do) {
  std::ifstream in(file);
  if (!in) throw ConfigError(file, "", "cannot be read");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw ConfigError(file, "", std::string("is not valid JSON (") + e.what() +
                                    "); colza wrote it, so it was edited or cut short: " + what_to_do);
  }
  if (!j.is_object())
    throw ConfigError(file, "", "is not a JSON object; colza wrote it, so it was edited: " + what_to_do);
  return j;
}

void require_fields(const nlohmann::json& j, const std::string& file, std::initializer_list<JsonField> fields,
                    const std::string& what_to_do) {
  for (const JsonField& f : fields) {
    if (!j.contains(f.key)) {
      if (f.required) throw ConfigError(file, f.key, "is missing; colza wrote it, so it was edited: " + what_to_do);
      continue;
    }
    const nlohmann::json& v = j[f.key];
    static const char* const kKindName[] = {"a number", "a string", "a boolean", "an object"};
    const bool ok = f.kind == JsonField::kNumber   ? v.is_number()
                    : f.kind == JsonField::kString ? v.is_string()
                    : f.kind == JsonField::kObject ? v.is_object()
                                                   : v.is_boolean();
    if (!ok)
      throw ConfigError(file, f.key,
                        std::string("must be ") + kKindName[f.kind] + ", got " + v.dump() +
                            "; colza wrote it, so it was edited: " + what_to_do);
  }
}

}  // namespace colza
