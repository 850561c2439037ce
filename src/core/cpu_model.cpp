#include "core/cpu_model.hpp"

#include <fstream>

namespace colza {

namespace {

// The value of "key<spaces>: value" in line, or "" when the line holds another key.
std::string value_of(const std::string& line, const std::string& key) {
  if (line.compare(0, key.size(), key) != 0) return "";
  const std::size_t colon = line.find(':', key.size());
  if (colon == std::string::npos || line.find_first_not_of(" \t", key.size()) != colon) return "";
  const std::size_t start = line.find_first_not_of(" \t", colon + 1);
  return start == std::string::npos ? "" : line.substr(start);
}

}  // namespace

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line, name, family, model;
  // The first processor's fields: they end at its first empty line.
  while (std::getline(in, line) && !line.empty()) {
    if (name.empty()) name = value_of(line, "model name");
    if (family.empty()) family = value_of(line, "cpu family");
    if (model.empty()) model = value_of(line, "model");
  }
  if (name.empty()) return "unknown";
  if (family.empty() || model.empty()) return name;
  return name + " (family " + family + ", model " + model + ")";
}

}  // namespace colza
