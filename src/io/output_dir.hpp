// Atomic result directories. Files are written into a hidden staging folder inside the
// output directory and moved into place only when the whole run has succeeded, so a
// failed or interrupted run never leaves half-written files nor replaces an earlier result.
// The staging folder (.colza-partial-<host>-<pid>) is removed when the run fails or is
// interrupted (core/interrupt.hpp); one left by a killed process of this machine is removed
// by the next OutputStaging in the same directory.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace colza {

class OutputStaging {
 public:
  // Throws ConfigError (key "--out") if `dir` already holds a result (a summary.json)
  // and `overwrite` is false, or if it cannot be created.
  OutputStaging(const std::filesystem::path& dir, bool overwrite);
  ~OutputStaging();
  OutputStaging(const OutputStaging&) = delete;
  OutputStaging& operator=(const OutputStaging&) = delete;

  // Where to write `name` now; it appears as dir/name after commit().
  std::string path(const std::string& name);
  void commit();
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_, staging_;
  std::vector<std::string> files_;
  bool created_dir_ = false, committed_ = false;
};

// Writes `text` to `file` under a temporary name, then renames it into place.
void write_text_atomically(const std::filesystem::path& file, const std::string& text);

// Checks the output directory without creating anything (for early validation).
void check_output_dir(const std::filesystem::path& dir, bool overwrite);

}  // namespace colza
