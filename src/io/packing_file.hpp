// Packing files: one sphere per line, "x y z r" in metres, written with 17 significant
// digits so a packing read back is the same packing bit for bit. Lines starting with
// '#' are comments.
#pragma once
#include <string>
#include <vector>
#include "core/particles.hpp"

namespace colza {

struct PackedSphere {
  Vec3 position;
  double radius;
  int line = 0;  // line of the packing file it was read from (0: not read from a file)
};

// Throws ConfigError naming `file` and `key_for_errors` when missing or malformed.
std::vector<PackedSphere> read_packing(const std::string& file, const std::string& key_for_errors);
void write_packing(const std::string& file, const ParticleArrays& particles);
// write_packing through a temporary name, synced and renamed into place (write_atomically):
// for a packing others may read or reuse while it is written.
void write_packing_atomically(const std::string& file, const ParticleArrays& particles);

}  // namespace colza
