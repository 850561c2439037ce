// What the crosscheck command line asks for (main.cpp parses it), and its exit codes.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace crosscheck {

namespace fs = std::filesystem;

inline constexpr int kExitFail = 1;   // a comparison failed
inline constexpr int kExitUsage = 2;  // bad usage, or an unreadable tolerance file
inline constexpr int kExitSkip = 77;  // YADE is not installed (CTest SKIP_RETURN_CODE)
inline constexpr const char* kDefaultYade = "yade";  // the Debian package's command

struct Options {
  std::string what;            // micro | oedometer | shear | all
  std::string size = "small";  // small | full
  fs::path colza, source, workdir, tolerances;
  std::string yade = kDefaultYade;
  bool reuse = false;
  std::vector<double> loads;  // --loads: overrides [shear.<size>] loads (Pa)
};

}  // namespace crosscheck
