// Helpers to run the colza executable from tests and read its outputs.
#pragma once
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace colza::testing {

struct CliResult {
  int exit_code = -1;
  std::string stderr_text;
};

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_file(const std::filesystem::path& p, const std::string& text) { std::ofstream(p) << text; }

// Runs `colza <args>` with stdout discarded and stderr captured.
inline CliResult run_colza(const std::string& args) {
  const auto err = std::filesystem::temp_directory_path() / ("colza-stderr-" + std::to_string(::getpid()));
  const std::string cmd = std::string(COLZA_EXECUTABLE) + " " + args + " > /dev/null 2> " + err.string();
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.stderr_text = read_file(err);
  std::filesystem::remove(err);
  return r;
}

inline nlohmann::json read_json(const std::filesystem::path& p) { return nlohmann::json::parse(read_file(p)); }

// A fresh empty scratch directory under the system temp dir.
inline std::filesystem::path scratch_dir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("colza-test-" + std::to_string(::getpid())) / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d.parent_path());
  return d;
}

inline std::string source_path(const std::string& rel) { return std::string(COLZA_SOURCE_DIR) + "/" + rel; }

}  // namespace colza::testing
