#include "cli/plot_command.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <vector>

extern char** environ;

namespace colza {

namespace {

// The script's exit status when numpy or matplotlib cannot be imported (python/colza_plot.py).
constexpr int kScriptMissingStack = 3;

std::string from_env(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::string(v) : fallback;
}

}  // namespace

PlotOutcome draw_plots(const std::filesystem::path& dir, bool quiet, std::string& why,
                       const std::string& measured_shear) {
  const std::string python = from_env("COLZA_PYTHON", "/usr/bin/python3");
  const std::string script = from_env("COLZA_PLOT_SCRIPT", COLZA_PLOT_SCRIPT);
  if (::access(python.c_str(), X_OK) != 0) {
    why = python + " not found (install python3-matplotlib, or set COLZA_PYTHON)";
    return PlotOutcome::kNoPlottingStack;
  }
  if (::access(script.c_str(), R_OK) != 0) {
    why = "the plot script " + script + " is not there (set COLZA_PLOT_SCRIPT)";
    return PlotOutcome::kNoPlottingStack;
  }
  std::vector<std::string> args{python, script, dir.string()};
  if (!measured_shear.empty()) args.insert(args.end(), {"--measured-shear", measured_shear});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (quiet) posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  std::fflush(stdout);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, python.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    why = "cannot start " + python;
    return PlotOutcome::kNoPlottingStack;
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      why = "lost the plot script's process";
      return PlotOutcome::kFailed;
    }
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return PlotOutcome::kDrawn;
  if (WIFEXITED(status) && WEXITSTATUS(status) == kScriptMissingStack) {
    why = "the plotting stack (numpy, matplotlib) is missing: install python3-matplotlib";
    return PlotOutcome::kNoPlottingStack;
  }
  why = "the plot script failed (" +
        (WIFEXITED(status) ? "exit " + std::to_string(WEXITSTATUS(status)) : std::string("killed by a signal")) +
        "; its messages are above)";
  return PlotOutcome::kFailed;
}

void plot_after_run(const std::filesystem::path& dir, bool quiet) {
  std::string why;
  if (draw_plots(dir, quiet, why) != PlotOutcome::kDrawn)
    std::fprintf(stderr, "colza: warning: no plots: %s; the result is complete without them (`colza plot %s` "
                         "draws them later)\n",
                 why.c_str(), dir.c_str());
}

int plot_command(const PlotOptions& opt) {
  if (!std::filesystem::is_regular_file(std::filesystem::path(opt.dir) / "summary.json")) {
    std::fprintf(stderr, "colza: error: %s: holds no summary.json, not a colza result\n", opt.dir.c_str());
    return 2;
  }
  std::string why;
  const PlotOutcome outcome = draw_plots(opt.dir, false, why, opt.measured_shear);
  if (outcome == PlotOutcome::kDrawn) return 0;
  std::fprintf(stderr, "colza: error: cannot plot %s: %s\n", opt.dir.c_str(), why.c_str());
  return 1;
}

}  // namespace colza
