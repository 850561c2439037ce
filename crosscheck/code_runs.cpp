#include "code_runs.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <thread>
#include "child_process.hpp"
#include "run_stamp.hpp"

namespace crosscheck {

namespace {

// Whether `out` may be removed before a run writes there: it holds what a run of crosscheck
// wrote (a summary.json, or the log beside it), or nothing. A user's folder of that name is not.
bool removable_run_folder(const fs::path& out, const fs::path& log) {
  if (!fs::exists(out)) return true;
  return fs::exists(log) || fs::exists(out / "summary.json") || fs::is_empty(out);
}

// The last `lines` lines of a log, indented.
std::string tail_of(const fs::path& log, std::size_t lines = 15) {
  std::ifstream in(log);
  std::vector<std::string> all;
  std::string line;
  while (std::getline(in, line)) all.push_back(line);
  std::string out;
  for (std::size_t i = all.size() > lines ? all.size() - lines : 0; i < all.size(); ++i) out += "    " + all[i] + "\n";
  return out;
}

}  // namespace

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

bool yade_available(const std::string& yade) {
  const std::string cmd = "command -v " + quote(yade) + " > /dev/null 2>&1";
  return std::system(cmd.c_str()) == 0;
}

bool CodeRuns::reused(const fs::path& out, const std::string& stamp, Reuse reuse) const {
  if ((reuse == Reuse::kIfAsked && !opt_.reuse) || !fs::exists(out / "summary.json")) return false;
  if (const std::string damage = damaged_result(out); !damage.empty()) {
    std::printf("crosscheck: not reusing %s: %s since the run; running it again\n", out.string().c_str(),
                damage.c_str());
    return false;
  }
  const std::optional<std::string> before = read_stamp(out);
  if (!before) {  // a load run by hand, or by a crosscheck before the stamps
    if (reuse == Reuse::kIfSameInputs) {
      std::printf("crosscheck: not reusing %s: no stamp of what it was made from (%s); making it again\n",
                  out.string().c_str(), stamp_file(out).string().c_str());
      return false;
    }
    std::printf("crosscheck: reusing %s without checking its inputs: no stamp (%s) vouches for its results\n",
                out.string().c_str(), stamp_file(out).string().c_str());
    return true;
  }
  if (*before != stamp) {
    const std::string change = first_change(*before, stamp);
    std::printf("crosscheck: not reusing %s: it was made from other inputs (%s); running it again\n",
                out.string().c_str(), change.empty() ? "fewer input files now" : ("now: " + change).c_str());
    return false;
  }
  std::printf("crosscheck: reusing %s\n", out.string().c_str());
  return true;
}

bool CodeRuns::failed(const std::string& code, const fs::path& out, const std::string& why,
                      const std::string& detail) const {
  std::fprintf(stderr, "crosscheck: %s: %s\n%s", code.c_str(), why.c_str(), detail.c_str());
  const std::lock_guard<std::mutex> lock(failures_mutex_);
  failures_[out] = why;
  return false;
}

void CodeRuns::forget_failure(const fs::path& out) const {
  const std::lock_guard<std::mutex> lock(failures_mutex_);
  failures_.erase(out);
}

std::string CodeRuns::failure(const fs::path& out) const {
  const std::lock_guard<std::mutex> lock(failures_mutex_);
  const auto it = failures_.find(out);
  return it == failures_.end() ? "" : it->second;
}

std::string CodeRuns::failure(const fs::path& colza_out, const fs::path& yade_out) const {
  if (const std::string why = failure(colza_out); !why.empty()) return "colza: " + why;
  if (const std::string why = failure(yade_out); !why.empty()) return "YADE: " + why;
  return "run failed";
}

bool CodeRuns::run(const std::string& code, const std::function<std::string(const fs::path&)>& command_for,
                   const fs::path& out, const std::string& stamp) const {
  std::error_code ec;
  fs::create_directories(out.parent_path(), ec);
  if (ec) return failed(code, out, "cannot make the folder " + out.parent_path().string() + ": " + ec.message());
  const fs::path log = out.string() + ".log", failed_log = out.string() + ".failed.log";
  if (!removable_run_folder(out, log))
    return failed(code, out,
                  out.string() + " holds files crosscheck did not write; not running there (move them, or give "
                                 "another --workdir)");
  // The run writes into a staging folder beside `out`, and replaces `out` (its stamp and log)
  // only when it has succeeded: a run that fails or is stopped never costs a finished one (a
  // full-size YADE load takes hours), and an earlier result cannot pass for this run's, since
  // the caller reads nothing of a failed run. A stop that ends crosscheck inside the run
  // leaves the staging folder, named as unfinished, for the next run to clear.
  const fs::path staging = out.string() + ".running", staging_log = staging.string() + ".log";
  fs::remove_all(staging, ec);
  if (!ec) fs::remove(staging_log, ec);
  if (ec) return failed(code, out, "cannot clear " + staging.string() + " for the run: " + ec.message());
  const std::string command = command_for(staging);
  const int status = run_shell_command(command, staging_log);
  if (stop_requested()) {  // stopped by crosscheck's stop signal: no failure to report
    fs::remove_all(staging, ec);
    fs::remove(staging_log, ec);
    return false;
  }
  if (status != 0) {
    fs::rename(staging_log, failed_log, ec);
    const fs::path& whole_log = ec ? staging_log : failed_log;
    const std::string kept = fs::exists(out) ? "; the earlier result in " + out.string() + " is kept" : "";
    const std::string detail = "    " + command + "\n" + tail_of(whole_log) + "    (the whole log: " +
                               whole_log.string() + kept + ")\n";
    fs::remove_all(staging, ec);
    return failed(code, out, "failed (exit " + std::to_string(status) + "; log " + whole_log.string() + ")", detail);
  }
  fs::remove(stamp_file(out), ec);
  if (!ec) fs::remove_all(out, ec);
  if (!ec) fs::rename(staging, out, ec);
  if (!ec) fs::rename(staging_log, log, ec);
  if (ec)
    return failed(code, out, "cannot move the run from " + staging.string() + " to " + out.string() + ": " + ec.message());
  fs::remove(failed_log, ec);
  try {
    write_stamp(out, stamp);
  } catch (const std::exception& e) {
    return failed(code, out, e.what());
  }
  return true;
}

std::optional<std::string> CodeRuns::stamp_of(const std::string& code, const fs::path& out, const std::string& command,
                                              const std::vector<fs::path>& programs, const fs::path& config,
                                              const std::vector<std::string>& arguments) const {
  try {
    return run_stamp(command, programs, config, arguments);
  } catch (const std::exception& e) {
    failed(code, out, e.what());
    return std::nullopt;
  }
}

bool CodeRuns::run_colza(const std::string& scenario, const fs::path& config, const fs::path& out,
                         const std::vector<std::string>& sets, const std::vector<std::string>& extra,
                         Reuse reuse) const {
  const auto command_for = [&](const fs::path& into) {
    std::string cmd = quote(opt_.colza.string()) + " run " + scenario + " --config " + quote(config.string()) +
                      " --out " + quote(into.string()) + " --force --quiet --threads 1" +  // as YADE -j 1
                      " --set output.plots=false";  // the comparison reads numbers; plots cost a Python start per run
    for (const auto& s : sets) cmd += " --set " + quote(s);
    for (const auto& e : extra) cmd += " " + quote(e);
    return cmd;
  };
  std::vector<std::string> arguments = sets;
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  forget_failure(out);
  const std::optional<std::string> stamp = stamp_of("colza", out, command_for(out), {opt_.colza}, config, arguments);
  if (!stamp) return false;
  if (reused(out, *stamp, reuse)) return true;
  return run("colza", command_for, out, *stamp);
}

bool CodeRuns::run_yade(const std::string& script, const fs::path& config, const fs::path& out,
                        const std::vector<std::string>& extra) const {
  const fs::path scripts = opt_.source / "yade-scripts";
  const fs::path py = scripts / script;
  const auto command_for = [&](const fs::path& into) {
    std::string cmd = quote(opt_.yade) + " -n -j 1 -x " + quote(py.string()) + " " + quote(config.string()) + " " +
                      quote(into.string());
    for (const auto& e : extra) cmd += " " + quote(e);
    return cmd;
  };
  // The script and the modules of yade-scripts/ (every .py but the other run_*.py scripts,
  // which no script imports).
  std::vector<fs::path> programs{py};
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(scripts, ec)) {
    const fs::path& f = entry.path();
    if (f.extension() == ".py" && f.filename().string().rfind("run_", 0) != 0) programs.push_back(f);
  }
  std::sort(programs.begin() + 1, programs.end());
  forget_failure(out);
  const std::optional<std::string> stamp = stamp_of("yade", out, command_for(out), programs, config, extra);
  if (!stamp) return false;
  if (reused(out, *stamp, Reuse::kIfAsked)) return true;
  return run("yade", command_for, out, *stamp);
}

std::vector<bool> run_in_parallel(const std::vector<std::function<bool()>>& jobs) {
  std::vector<char> ok(jobs.size(), 0);
  std::atomic<std::size_t> next{0};
  const unsigned workers = static_cast<unsigned>(std::min<std::size_t>(kParallelRuns, jobs.size()));
  {
    // After a stop signal no job starts; the workers' runs in progress are stopped
    // (child_process.hpp), and crosscheck ends once they have joined.
    const ParallelSection section;
    std::vector<std::thread> pool;
    for (unsigned w = 0; w < workers; ++w)
      pool.emplace_back([&] {
        for (std::size_t j = next++; j < jobs.size() && !stop_requested(); j = next++) {
          try {
            ok[j] = jobs[j]() ? 1 : 0;
          } catch (const std::exception& e) {
            std::fprintf(stderr, "crosscheck: a run failed: %s\n", e.what());
          }
        }
      });
    for (auto& t : pool) t.join();
  }
  end_if_stop_requested();
  return {ok.begin(), ok.end()};
}

fs::path write_run_config(const fs::path& file, const toml::table& doc, const fs::path& source) {
  std::ofstream o(file);
  o << "# written by crosscheck from " << source.string() << "\n" << doc << "\n";
  if (!o) throw std::runtime_error("cannot write " + file.string());
  return file;
}

}  // namespace crosscheck
