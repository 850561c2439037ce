#include "io/packing_file.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "config/config_error.hpp"
#include "io/input_file.hpp"
#include "io/output_dir.hpp"
#include "io/output_error.hpp"

namespace colza {

std::vector<PackedSphere> read_packing(const std::string& file, const std::string& key) {
  if (const std::string why = unreadable_file_reason(file); !why.empty())
    throw ConfigError(file, key, "the packing file " + why);
  std::ifstream in(file);
  std::vector<PackedSphere> spheres;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream s(line);
    PackedSphere p;
    std::string extra;
    if (!(s >> p.position[0] >> p.position[1] >> p.position[2] >> p.radius) || (s >> extra))
      throw ConfigError(file, key,
                        "line " + std::to_string(line_no) + ": expected four numbers 'x y z r' (m), got '" + line + "'");
    if (!(p.radius > 0.0) || !p.position.allFinite())
      throw ConfigError(file, key, "line " + std::to_string(line_no) + ": radius must be positive, values finite");
    p.line = line_no;
    spheres.push_back(p);
  }
  if (spheres.empty()) throw ConfigError(file, key, "holds no sphere (expected lines 'x y z r' in m)");
  return spheres;
}

void write_packing(const std::string& file, const ParticleArrays& particles) {
  std::FILE* f = std::fopen(file.c_str(), "w");
  if (!f) throw_cannot_write(file);
  std::fprintf(f, "# colza packing: x y z r (m), %zu spheres\n", particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Vec3& x = particles.position[i];
    std::fprintf(f, "%.17g %.17g %.17g %.17g\n", x[0], x[1], x[2], particles.radius[i]);
  }
  if (std::fclose(f) != 0) throw_cannot_write(file);
}

void write_packing_atomically(const std::string& file, const ParticleArrays& particles) {
  write_atomically(file, [&](const std::string& tmp) { write_packing(tmp, particles); });
}

}  // namespace colza
