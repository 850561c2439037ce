#include "speed_tally.hpp"

#include <cstdio>
#include "result_files.hpp"

namespace crosscheck {

void SpeedTally::add(const fs::path& colza_out, const fs::path& yade_out, const std::string& what) {
  const auto c = read_json(colza_out / "summary.json");
  const auto y = read_json(yade_out / "summary.json");
  if (!c.contains("particle_steps_per_second") || !y.contains("particle_steps_per_second")) return;
  const double ps_y = y.value("particles", 0.0) * y.value("steps", 0.0);
  const double ps_c = c.value("particles", 0.0) * c.value("steps", 0.0);
  const double c_rate = c["particle_steps_per_second"].get<double>();
  if (ps_y <= 0.0 || ps_c <= 0.0 || c_rate <= 0.0) return;
  yade_particle_steps_ += ps_y;
  colza_particle_steps_ += ps_c;
  colza_seconds_ += ps_c / c_rate;
  yade_seconds_ += y.value("wall_seconds", 0.0);
  yade_engine_seconds_ += y.value("wall_seconds", 0.0) - y.value("python_engine_seconds", 0.0);
  if (what_.find(what) == std::string::npos) what_ += (what_.empty() ? "" : ", ") + what;
}

std::string SpeedTally::text() const {
  if (yade_particle_steps_ <= 0.0) return "speed: measured on the oedometer and shear runs (the micro scenes are too small to time)\n";
  const double c = colza_particle_steps_ / colza_seconds_;
  const double y = yade_particle_steps_ / yade_seconds_;
  const double ye = yade_engine_seconds_ > 0 ? yade_particle_steps_ / yade_engine_seconds_ : 0.0;
  char line[256];
  std::string out;
  std::snprintf(line, sizeof line, "speed on the same loadings (%s; colza %.3g, YADE %.3g particle-steps; single thread, from each "
              "run's wall time):\n",
              what_.c_str(), colza_particle_steps_, yade_particle_steps_);
  out += line;
  std::snprintf(line, sizeof line, "  colza                                   %10.3g particle-steps/s\n", c);
  out += line;
  std::snprintf(line, sizeof line, "  YADE (whole loop incl. Python runners)  %10.3g particle-steps/s   colza/YADE = %.1f\n", y, c / y);
  out += line;
  if (ye > 0) {
    std::snprintf(line, sizeof line, "  YADE (C++ engines only)                 %10.3g particle-steps/s   colza/YADE = %.1f\n", ye, c / ye);
    out += line;
  }
  return out;
}

}  // namespace crosscheck
