// Helpers to run the colza executable from tests and read its outputs.
#pragma once
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <utility>

namespace colza::testing {

struct CliResult {
  int exit_code = -1;
  std::string stderr_text;
  std::string stdout_text;  // run_colza only (the result lines and WARNING lines)
  bool ready_reached = false;  // run_colza_interrupted: the signal was sent when ready() held
};

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_file(const std::filesystem::path& p, const std::string& text) { std::ofstream(p) << text; }

// Where a run's stderr and stdout are captured: files of this test process in the temp folder.
inline std::filesystem::path stderr_file() {
  return std::filesystem::temp_directory_path() / ("colza-stderr-" + std::to_string(::getpid()));
}
inline std::filesystem::path stdout_file() {
  return std::filesystem::temp_directory_path() / ("colza-stdout-" + std::to_string(::getpid()));
}

// The shell command that runs `colza <args>` with stdout into `out` (discarded by default)
// and stderr into `err`.
inline std::string colza_command(const std::string& args, const std::filesystem::path& err,
                                 const std::filesystem::path& out = "/dev/null") {
  return std::string(COLZA_EXECUTABLE) + " " + args + " > " + out.string() + " 2> " + err.string();
}

// The captured text, and the file removed.
inline std::string take_captured(const std::filesystem::path& err) {
  std::string text = read_file(err);
  std::filesystem::remove(err);
  return text;
}

// Runs `colza <args>` with stdout and stderr captured.
inline CliResult run_colza(const std::string& args) {
  const auto err = stderr_file();
  const auto out = stdout_file();
  const int status = std::system(colza_command(args, err, out).c_str());
  CliResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.stderr_text = take_captured(err);
  r.stdout_text = take_captured(out);
  return r;
}

// Starts `colza <args>` (stdout discarded), waits until `ready()` holds (polled every 10 ms,
// at most `timeout`; `ready_reached` says whether it did), sends it SIGINT (Ctrl-C) and waits
// for it: its exit code (130 when the signal stopped it) and stderr; -1 if it ended on a
// signal instead of exiting, or did not stop within a minute (then it is killed). If colza
// ends before `ready()`, no signal is sent and its own exit code is returned. `signals`
// SIGINTs are sent back to back (2: as timeout(1) delivers one, to the child and its group).
inline CliResult run_colza_interrupted(const std::string& args, const std::function<bool()>& ready,
                                       std::chrono::seconds timeout = std::chrono::seconds(120), int signals = 1) {
  const auto err = stderr_file();
  const std::string cmd = "exec " + colza_command(args, err);
  CliResult r;
  const pid_t child = ::fork();
  if (child < 0) return r;
  if (child == 0) {
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  bool ended = false;
  const auto give_up = std::chrono::steady_clock::now() + timeout;
  while (!(r.ready_reached = ready()) && std::chrono::steady_clock::now() < give_up) {
    if (::waitpid(child, &status, WNOHANG) == child) {
      ended = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (!ended) {
    // Ctrl-C stops colza within a step; after a minute it is hung: kill it (exit_code -1).
    for (int k = 0; k < signals; ++k) ::kill(child, SIGINT);
    const auto kill_at = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (::waitpid(child, &status, WNOHANG) != child) {
      if (std::chrono::steady_clock::now() > kill_at) {
        ::kill(child, SIGKILL);
        ::waitpid(child, &status, 0);
        status = -1;
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
  if (status >= 0 && WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  r.stderr_text = take_captured(err);
  return r;
}

// Whether `dir` has an entry (at any depth) whose path satisfies `matches` (none if dir is
// missing).
inline bool has_entry(const std::filesystem::path& dir, const std::function<bool(const std::filesystem::path&)>& matches) {
  std::error_code ec;
  for (std::filesystem::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (matches(it->path())) return true;
  return false;
}

// Whether `dir` has an entry (at any depth) whose path contains `part`, e.g. a staging folder.
inline bool has_entry_containing(const std::filesystem::path& dir, const std::string& part) {
  return has_entry(dir, [&](const std::filesystem::path& p) { return p.string().find(part) != std::string::npos; });
}

// Every file under `dir` (relative path -> contents), to compare a result before and after.
inline std::map<std::string, std::string> directory_contents(const std::filesystem::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    files[std::filesystem::relative(e.path(), dir).string()] = e.is_regular_file() ? read_file(e.path()) : "<dir>";
  return files;
}

inline nlohmann::json read_json(const std::filesystem::path& p) { return nlohmann::json::parse(read_file(p)); }

// Removes the test program's scratch folder when the program ends with every test passed;
// after a failure the folder stays, for inspection, and its path is printed.
class ScratchFolderCleanup : public ::testing::EmptyTestEventListener {
 public:
  explicit ScratchFolderCleanup(std::filesystem::path folder) : folder_(std::move(folder)) {}
  void OnTestProgramEnd(const ::testing::UnitTest& unit_test) override {
    if (unit_test.Passed()) {
      std::error_code ec;
      std::filesystem::remove_all(folder_, ec);
    } else {
      std::fprintf(stderr, "the failed tests' outputs are kept in %s\n", folder_.c_str());
    }
  }

 private:
  std::filesystem::path folder_;
};

// <temp>/colza-test-<pid>: this test program's scratch folder, cleaned up at its end.
inline const std::filesystem::path& scratch_folder() {
  static const std::filesystem::path folder = [] {
    auto f = std::filesystem::temp_directory_path() / ("colza-test-" + std::to_string(::getpid()));
    ::testing::UnitTest::GetInstance()->listeners().Append(new ScratchFolderCleanup(f));  // gtest owns it
    return f;
  }();
  return folder;
}

// A fresh empty scratch directory in the test program's scratch folder.
inline std::filesystem::path scratch_dir(const std::string& name) {
  const auto d = scratch_folder() / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d.parent_path());
  return d;
}

inline std::string source_path(const std::string& rel) { return std::string(COLZA_SOURCE_DIR) + "/" + rel; }

}  // namespace colza::testing
