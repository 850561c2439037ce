#include "io/summary.hpp"

#include <fstream>
#include <stdexcept>

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

}  // namespace colza
