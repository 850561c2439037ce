// The codes' runs as child processes, and stopping them with crosscheck.
//
// Each command runs under /bin/sh in a process group of its own. A stop signal (SIGINT from
// Ctrl-C, SIGTERM, SIGHUP) sent to crosscheck is caught and forwarded as SIGTERM to the
// groups of every run in progress, then crosscheck ends by that signal once no run is left
// (exit status 128 + the signal, as the shell reports it). SIGTERM, not SIGINT: colza stops
// cleanly on either (src/core/interrupt.hpp), but YADE notices SIGINT only when its O.run()
// returns, which for a full shear load is 1.5-2 hours on; its results are written at the end
// only, so a killed YADE leaves none to mistake for a finished run.
//
// Before (std::system), SIGTERM to crosscheck alone killed it and left its yade child
// running, orphaned; SIGINT to crosscheck alone was ignored (std::system ignores SIGINT while
// a command runs). Only Ctrl-C at a terminal, which signals the whole foreground group, worked.
#pragma once
#include <filesystem>
#include <string>

namespace crosscheck {

// Installs the stop-signal handlers (main() only, before any run); a stop signal that was
// ignored when crosscheck started (nohup) stays ignored. A stop signal that arrives while no
// run is in progress and no parallel section is open ends crosscheck at once.
void forward_stop_signals();

// Runs `command` with /bin/sh -c, stdin from /dev/null, stdout and stderr to `log`; waits for
// it. Returns its exit status, or -1 if it could not start or was ended by a signal. After a
// stop signal no new command starts (-1), and crosscheck ends once the last run in progress
// has returned, unless a parallel section is open (then run_in_parallel ends it after joining).
int run_shell_command(const std::string& command, const std::filesystem::path& log);

// Whether a stop signal has arrived.
bool stop_requested();

// While one exists, a stop signal does not end crosscheck from run_shell_command or the
// handler; the section's owner calls end_if_stop_requested() after its workers have joined.
class ParallelSection {
 public:
  ParallelSection();
  ~ParallelSection();
  ParallelSection(const ParallelSection&) = delete;
  ParallelSection& operator=(const ParallelSection&) = delete;
};

// Ends crosscheck by the stop signal if one arrived (with its default action), else returns.
void end_if_stop_requested();

}  // namespace crosscheck
