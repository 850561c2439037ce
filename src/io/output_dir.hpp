// Atomic result directories. Files are written into a hidden staging folder inside the
// output directory and moved into place only when the whole run has succeeded, so a
// failed or interrupted run never leaves half-written files nor replaces an earlier result.
// The staging folder (.colza-partial-<host>-<pid>) is removed when the run fails or is
// interrupted (core/interrupt.hpp); one left by a killed process of this machine is removed
// by the next OutputStaging in the same directory.
#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace colza {

class OutputStaging {
 public:
  // Throws ConfigError (naming "--out DIR") if `overwrite` is false and `dir` already holds
  // a result (a summary.json) or other files (check_output_dir), or if it cannot be created.
  OutputStaging(const std::filesystem::path& dir, bool overwrite);
  ~OutputStaging();
  OutputStaging(const OutputStaging&) = delete;
  OutputStaging& operator=(const OutputStaging&) = delete;

  // Where to write `name` (a file, or a folder the caller fills); it appears as dir/name
  // after commit(), replacing a file or folder of that name.
  std::string path(const std::string& name);
  // Moves everything into place, summary.json last. `stale`: entries of an earlier result
  // in dir (earlier_run_outputs), all removed after its summary.json and before the moves.
  // Checks first that every move can be made (ConfigError, nothing removed); a failure after
  // the removals began keeps the staging folder and names it.
  void commit(const std::vector<std::string>& stale = {});
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_, staging_;
  std::vector<std::string> files_;
  bool created_dir_ = false, committed_ = false;
  bool keep_staging_ = false;  // commit() began removing the earlier result: keep the new one
};

// Writes `file` by calling write(tmp) with a temporary name of this process next to it
// (two writers never share one), then syncs it to the disk and renames it into place
// (replacing `file`): the file appears complete or not at all, even after a power cut.
void write_atomically(const std::filesystem::path& file, const std::function<void(const std::string& tmp)>& write);

// write_atomically with `text` as the contents.
void write_text_atomically(const std::filesystem::path& file, const std::string& text);

// Whether `entry` is a staging folder (.colza-partial-<host>-<pid>) of a run in progress or
// of one killed before it finished.
bool is_staging_folder(const std::filesystem::path& entry);

// Checks the output directory of `command` ("run" or "calibrate") without creating anything
// (for early validation). Unless `overwrite` (--force), a directory that holds a
// summary.json, or any file but staging folders, is refused; one that holds
// `unfinished_marker` (e.g. a series' sample.json) is accepted, to be resumed. With
// `overwrite`, another command's result is refused (refuse_another_commands_result).
void check_output_dir(const std::filesystem::path& dir, bool overwrite, const std::string& command,
                      const std::string& unfinished_marker = "");

// The entries of an earlier `colza run` result in dir: its summary.json and sample.json,
// packing.txt, curve.csv, series.csv, result.h5, result.xmf, plots/ and load-<sigma>Pa folders holding a
// summary.json, but only if dir's summary.json or sample.json is colza's (it names
// colza_version or config_fingerprint); none otherwise. For OutputStaging::commit when
// --force replaces the result.
std::vector<std::string> earlier_run_outputs(const std::filesystem::path& dir);

}  // namespace colza
