// Running the two codes: `colza run <scenario>` and YADE with a script of yade-scripts/, both
// on one thread (colza --threads 1, yade -j 1), output to a run folder and a log beside it.
#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <vector>
#include "options.hpp"

namespace crosscheck {

namespace fs = std::filesystem;

// `s` quoted for the shell.
std::string quote(const std::string& s);

// Whether `yade` runs as a command (on PATH or a path).
bool yade_available(const std::string& yade);

class CodeRuns {
 public:
  explicit CodeRuns(const Options& opt) : opt_(opt) {}
  const Options& options() const { return opt_; }

  // colza run <scenario> --config <config> --out <out> [--set s]... [extra]...; false (and
  // the log's tail on stderr) if it failed.
  bool run_colza(const std::string& scenario, const fs::path& config, const fs::path& out,
                 const std::vector<std::string>& sets = {}, const std::vector<std::string>& extra = {}) const;
  // yade -n -j 1 -x yade-scripts/<script> <config> <out> [extra]...; as run_colza.
  bool run_yade(const std::string& script, const fs::path& config, const fs::path& out,
                const std::vector<std::string>& extra = {}) const;

 private:
  // --reuse: a finished run (summary.json present) stands.
  bool reused(const fs::path& out) const;
  bool run(const std::string& code, const std::string& command, const fs::path& out) const;

  const Options& opt_;
};

// Runs the jobs (each typically one run of a code on one thread) on as many workers as the
// machine has cores; returns each job's success.
std::vector<bool> run_in_parallel(const std::vector<std::function<bool()>>& jobs);

}  // namespace crosscheck
