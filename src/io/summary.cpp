#include "io/summary.hpp"

#include <fstream>
#include <stdexcept>

#include "config/config_error.hpp"

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
  if (!out) throw std::runtime_error("cannot write " + file);
  out << value.dump(2) << '\n';
  if (!out) throw std::runtime_error("cannot write " + file);
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

}  // namespace colza
