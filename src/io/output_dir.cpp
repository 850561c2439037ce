#include "io/output_dir.hpp"

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <stdexcept>
#include <fcntl.h>   // open (POSIX)
#include <signal.h>  // kill (POSIX)
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "config/config_error.hpp"
#include "io/load_label.hpp"
#include "io/output_error.hpp"

namespace colza {

namespace fs = std::filesystem;

namespace {

// Staging folders are named .colza-partial-<host>-<pid> (staging_prefix).
constexpr const char* kStagingPrefix = ".colza-partial-";

// `file` as a JSON object, read without throwing; an empty object if it is missing or not one.
nlohmann::json json_object_or_empty(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return nlohmann::json::object();
  nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  return j.is_object() ? j : nlohmann::json::object();
}

// Whether `file` is a JSON object colza wrote with one of `keys` (its own summary.json or
// sample.json).
bool written_by_colza(const fs::path& file, std::initializer_list<const char*> keys) {
  const nlohmann::json j = json_object_or_empty(file);
  for (const char* k : keys)
    if (j.contains(k)) return true;
  return false;
}

// The command whose result `dir` holds, read from its summary.json: "run <scenario>" (a
// `colza run` result names its scenario), "calibrate <stage>" (a calibration's names its
// stage and mode), or "" (none, or not colza's).
std::string earlier_result_command(const fs::path& dir) {
  const nlohmann::json j = json_object_or_empty(dir / "summary.json");
  if (j.contains("scenario") && j["scenario"].is_string()) return "run " + j["scenario"].get<std::string>();
  if (j.contains("stage") && j["stage"].is_string() && j.contains("mode"))
    return "calibrate " + j["stage"].get<std::string>();
  if (j.contains("verdict") && j.contains("spec")) return "diagnose --spec";
  return "";
}

// Flushes a file's (or a folder's entries') data to the disk, so that a rename that makes it
// visible is not followed, after a power cut, by an empty or short file. Best effort: a
// file system that cannot sync (EINVAL) is not an error.
void sync_to_disk(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

// The files a run writes into --out (a series also writes load-<N>Pa folders; every run the
// folder kPlotsFolder).
constexpr const char* kRunFiles[] = {"summary.json", "sample.json", "packing.txt", "curve.csv", "series.csv",
                                     "result.h5", "result.xmf"};
constexpr const char* kPlotsFolder = "plots";

// check_output_dir without the command's part: OutputStaging's check, for folders whose
// command is settled (the caller checked --out; design runs and series loads are colza's own).
void check_output_folder(const fs::path& dir, bool overwrite, const std::string& unfinished_marker) {
  const std::string name = "--out " + dir.string();
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) throw ConfigError(name, "", "exists and is not a directory");
  if (!fs::is_directory(dir, ec)) return;
  // --force replaces files of the same name, but a folder cannot be renamed over: said now,
  // not after the run.
  for (const char* f : kRunFiles)
    if (fs::is_directory(dir / f, ec))
      throw ConfigError(name, "", std::string("holds a folder named ") + f +
                                      ", the name of a file colza writes there: move it away or choose another --out");
  if (overwrite) return;
  if (fs::exists(dir / "summary.json", ec))
    throw ConfigError(name, "", "already holds a result (summary.json); pass --force to replace it");
  if (!unfinished_marker.empty() && fs::exists(dir / unfinished_marker, ec)) return;  // resumed
  std::vector<std::string> held;  // sorted: the directory's order is the file system's
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (!is_staging_folder(it->path())) held.push_back(it->path().filename().string());
  if (held.empty()) return;
  std::sort(held.begin(), held.end());
  constexpr std::size_t kNamed = 3;
  std::string listed;
  for (std::size_t k = 0; k < std::min(held.size(), kNamed); ++k) listed += (k ? ", " : "") + held[k];
  if (held.size() > kNamed) listed += " and " + std::to_string(held.size() - kNamed) + " more";
  throw ConfigError(name, "",
                    "holds " + listed + " but no colza result; choose a new or empty directory, or pass --force to "
                    "write into it (files of the same name are replaced)");
}

// Throws ConfigError naming "--out DIR" when `dir` holds another command's result than
// `command` ("run" or "calibrate"): --force would leave that result's other files (a run's
// curve and packing, a calibration's report and runs/) beside the new one.
void refuse_another_commands_result(const fs::path& dir, const std::string& command) {
  const std::string earlier = earlier_result_command(dir);
  if (earlier.empty() || earlier.rfind(command + " ", 0) == 0) return;
  throw ConfigError("--out " + dir.string(), "",
                    "holds the result of `colza " + earlier + "`: --force replaces an earlier result of `colza " +
                        command + "` only; choose another --out");
}

}  // namespace

bool is_staging_folder(const fs::path& entry) { return entry.filename().string().rfind(kStagingPrefix, 0) == 0; }

void check_output_dir(const fs::path& dir, bool overwrite, const std::string& command,
                      const std::string& unfinished_marker) {
  check_output_folder(dir, overwrite, unfinished_marker);
  if (overwrite) refuse_another_commands_result(dir, command);
}

std::vector<std::string> earlier_run_outputs(const fs::path& dir) {
  std::error_code ec;
  std::vector<std::string> names;
  if (!written_by_colza(dir / "summary.json", {"colza_version"}) &&
      !written_by_colza(dir / "sample.json", {"config_fingerprint"}))
    return names;
  for (const char* f : kRunFiles)
    if (fs::exists(dir / f, ec)) names.push_back(f);
  if (fs::is_directory(dir / kPlotsFolder, ec)) names.push_back(kPlotsFolder);
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string f = it->path().filename().string();
    if (is_load_label(f) && fs::is_directory(it->path(), ec) &&
        written_by_colza(it->path() / "summary.json", {"colza_version"}))
      names.push_back(f);
  }
  std::sort(names.begin(), names.end());
  return names;
}

void write_atomically(const fs::path& file, const std::function<void(const std::string& tmp)>& write) {
  const std::string tmp = file.string() + ".tmp." + std::to_string(::getpid());
  write(tmp);
  sync_to_disk(tmp);
  fs::rename(tmp, file);
}

void write_text_atomically(const fs::path& file, const std::string& text) {
  write_atomically(file, [&](const std::string& tmp) {
    std::ofstream o(tmp);
    o << text;
    o.close();  // the last buffer is written here: check after it
    if (!o) throw_cannot_write(tmp);
  });
}

namespace {

// Staging folders are named .colza-partial-<host>-<pid>: unique among the processes of all
// machines that may share an output directory (a calibration's --runs on a network disk).
std::string staging_prefix() {
  char host[256] = {0};
  if (::gethostname(host, sizeof host - 1) != 0) host[0] = 0;
  return std::string(kStagingPrefix) + host + "-";
}

// Whether process `pid` of this machine still runs: it exists and is not a zombie (a process
// that has ended but that its parent has not yet waited for holds its pid, yet writes nothing
// any more; /proc/<pid>/stat's state after the command's closing parenthesis is 'Z').
bool process_runs(pid_t pid) {
  if (::kill(pid, 0) != 0 && errno == ESRCH) return false;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  if (!std::getline(stat, text)) return true;  // no /proc: trust kill
  const std::size_t close = text.rfind(')');
  return !(close != std::string::npos && close + 2 < text.size() && text[close + 2] == 'Z');
}

// Removes the staging folders that processes of this machine left when they were killed
// (SIGKILL, a crash: Ctrl-C and SIGTERM remove their own, see core/interrupt.hpp), or that a
// zombie holds. A folder whose process still runs, or that another machine wrote, is left
// alone.
void remove_abandoned_staging(const fs::path& dir, const std::string& prefix) {
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string pid_text = name.substr(prefix.size());
    if (pid_text.empty() || pid_text.size() > 9 || pid_text.find_first_not_of("0123456789") != std::string::npos)
      continue;
    const pid_t pid = static_cast<pid_t>(std::stol(pid_text));
    if (pid == ::getpid() || process_runs(pid)) continue;
    std::error_code remove_error;
    fs::remove_all(it->path(), remove_error);
  }
}

}  // namespace

OutputStaging::OutputStaging(const fs::path& dir, bool overwrite) : dir_(dir) {
  check_output_folder(dir, overwrite, "");
  std::error_code ec;
  if (!fs::exists(dir, ec)) {
    fs::create_directories(dir, ec);
    if (ec) throw ConfigError("--out " + dir.string(), "", "cannot create the directory: " + ec.message());
    created_dir_ = true;
  }
  const std::string prefix = staging_prefix();
  remove_abandoned_staging(dir, prefix);
  staging_ = dir / (prefix + std::to_string(::getpid()));
  fs::create_directories(staging_, ec);
  if (ec) throw ConfigError("--out " + dir.string(), "", "cannot write into the directory: " + ec.message());
}

std::string OutputStaging::path(const std::string& name) {
  if (std::find(files_.begin(), files_.end(), name) == files_.end()) files_.push_back(name);
  return (staging_ / name).string();
}

void OutputStaging::commit(const std::vector<std::string>& stale) {
  // summary.json last: its presence marks a complete result.
  std::stable_partition(files_.begin(), files_.end(), [](const std::string& f) { return f != "summary.json"; });
  std::error_code ec;
  // Nothing is removed before every move is known to be possible: a file cannot replace a
  // folder nor a folder a file (a user's file named like a load's folder, say).
  for (const auto& f : files_) {
    const fs::path target = dir_ / f;
    if (!fs::exists(target, ec)) continue;
    const bool staged_folder = fs::is_directory(staging_ / f, ec);
    const bool is_stale = std::find(stale.begin(), stale.end(), f) != stale.end();
    // A folder is replaced only if it belongs to the earlier result; a file of the same name
    // is replaced (--force says so).
    if (staged_folder != fs::is_directory(target, ec) || (staged_folder && !is_stale))
      throw ConfigError("--out " + dir_.string(), "",
                        "holds " + target.filename().string() + ", which is not part of an earlier colza result and "
                            "which this result would replace; move it away and run again");
  }
  for (const auto& f : files_)
    if (fs::is_regular_file(staging_ / f, ec)) sync_to_disk(staging_ / f);  // folders synced their own
  // From here on the staging folder is the only whole copy of the new result: if a step
  // fails, it is kept (and named) rather than removed with the run.
  keep_staging_ = true;
  const auto fail = [&](const std::string& what, const std::error_code& e) {
    throw std::runtime_error("moving the result into " + dir_.string() + " failed (" + what + ": " + e.message() +
                             "); the complete new result is in " + staging_.string() +
                             ": move it out before the next run into " + dir_.string() +
                             ", which would remove it as abandoned");
  };
  // An earlier result being replaced (--force) stops looking complete before any file moves
  // (summary.json; a series' sample.json too, so that a stop in the middle never leaves the
  // new packing.txt next to the old sample.json, which a resume would trust); then all its
  // entries go, before the new ones move in.
  fs::remove(dir_ / "summary.json", ec);
  if (std::find(files_.begin(), files_.end(), "sample.json") != files_.end()) fs::remove(dir_ / "sample.json", ec);
  for (const auto& f : stale)
    if (fs::remove_all(dir_ / f, ec); ec) fail("removing " + f, ec);
  for (const auto& f : files_) {
    if (fs::is_directory(dir_ / f, ec))
      if (fs::remove_all(dir_ / f, ec); ec) fail("removing " + f, ec);  // rename() replaces files only
    if (fs::rename(staging_ / f, dir_ / f, ec); ec) fail("moving " + f, ec);
  }
  fs::remove_all(staging_, ec);
  sync_to_disk(dir_);  // the renames themselves
  committed_ = true;
}

OutputStaging::~OutputStaging() {
  if (committed_ || keep_staging_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
  if (created_dir_ && fs::is_empty(dir_, ec)) fs::remove(dir_, ec);
}

}  // namespace colza
