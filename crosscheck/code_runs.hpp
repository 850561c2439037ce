// Running the two codes: `colza run <scenario>` and YADE with a script of yade-scripts/, both
// on one thread (colza --threads 1, yade -j 1), output to a run folder and a log beside it.
#pragma once
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <toml++/toml.h>
#include <vector>
#include "options.hpp"

namespace crosscheck {

namespace fs = std::filesystem;

// `s` quoted for the shell.
std::string quote(const std::string& s);

// Whether `yade` runs as a command (on PATH or a path).
bool yade_available(const std::string& yade);

// When a finished run in the run folder (summary.json present) stands instead of a new run.
// A run crosscheck made stands only if made from the same inputs (its stamp, run_stamp.hpp:
// command, config, packings, program).
enum class Reuse {
  // With --reuse (an interrupted cross-check continues where it stopped). A finished run
  // without a stamp (a load run by hand into the work dir) stands too, with a notice.
  kIfAsked,
  // Always, if its stamp matches: a product kept in the work dir, such as the shear box's
  // sample; one without a stamp is made again.
  kIfSameInputs,
};

class CodeRuns {
 public:
  explicit CodeRuns(const Options& opt) : opt_(opt) {}
  const Options& options() const { return opt_; }

  // colza run <scenario> --config <config> --out <out> [--set s]... [extra]...; false (and
  // the log's tail on stderr) if it failed.
  bool run_colza(const std::string& scenario, const fs::path& config, const fs::path& out,
                 const std::vector<std::string>& sets = {}, const std::vector<std::string>& extra = {},
                 Reuse reuse = Reuse::kIfAsked) const;
  // yade -n -j 1 -x yade-scripts/<script> <config> <out> [extra]...; as run_colza.
  bool run_yade(const std::string& script, const fs::path& config, const fs::path& out,
                const std::vector<std::string>& extra = {}) const;
  // Why the last run into `out` failed, in a few words for the table ("exit 2, log ..."); ""
  // if it did not fail (or was stopped by a signal).
  std::string failure(const fs::path& out) const;
  // The FAIL row's text for a pair of runs, the first that failed: "colza: <why>" or
  // "YADE: <why>" ("run failed" when neither says why).
  std::string failure(const fs::path& colza_out, const fs::path& yade_out) const;

 private:
  // Whether the finished run in `out` (summary.json present) stands, as `reuse` says; prints
  // why one made from other inputs does not.
  bool reused(const fs::path& out, const std::string& stamp, Reuse reuse) const;
  // Runs command_for(staging) into a staging folder beside `out` (its log beside it) and, when
  // it succeeds, puts it in place of `out` and writes its stamp; a failed or stopped run leaves
  // an earlier result in `out` as it was (a failed run's log: <out>.failed.log).
  bool run(const std::string& code, const std::function<std::string(const fs::path&)>& command_for,
           const fs::path& out, const std::string& stamp) const;
  // The stamp of a run, or nothing (and the reason on stderr) if its inputs cannot be read.
  std::optional<std::string> stamp_of(const std::string& code, const fs::path& out, const std::string& command,
                                      const std::vector<fs::path>& programs, const fs::path& config,
                                      const std::vector<std::string>& arguments) const;

  // Prints "crosscheck: <code>: <why>" (and `detail`, a log's tail) on stderr, records `why`
  // for failure(out); returns false.
  bool failed(const std::string& code, const fs::path& out, const std::string& why, const std::string& detail = "") const;
  void forget_failure(const fs::path& out) const;

  const Options& opt_;
  mutable std::mutex failures_mutex_;  // runs of an ensemble fail in parallel
  mutable std::map<fs::path, std::string> failures_;
};

// How many runs run_in_parallel keeps going at once: the 2 cores of the CI machine (each run
// is one thread: colza --threads 1, yade -j 1); more would oversubscribe a ctest -j run.
inline constexpr std::size_t kParallelRuns = 2;

// Runs the jobs (each one run of a code), kParallelRuns at a time; returns each job's success
// (false for a job that threw).
std::vector<bool> run_in_parallel(const std::vector<std::function<bool()>>& jobs);

// `doc` written to `file` with a first comment line naming `source`, for both codes; returns
// `file`. Throws std::runtime_error if it cannot be written.
fs::path write_run_config(const fs::path& file, const toml::table& doc, const fs::path& source);

}  // namespace crosscheck
