#include "child_process.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace crosscheck {

namespace {

// The process groups of the runs in progress (0 = free slot); kParallelRuns (code_runs.hpp)
// are in use at most. The handler reads them, so they are lock-free atomics, not a container.
constexpr int kGroupSlots = 16;
std::atomic<pid_t> running_groups[kGroupSlots];
std::atomic<int> runs_in_progress{0};   // from before a spawn to after its slot is free
std::atomic<int> parallel_sections{0};
std::atomic<int> received_signal{0};    // the first stop signal, 0 if none
static_assert(std::atomic<pid_t>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "the signal handler may only touch lock-free atomics");

constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP};

// Ends the process by `signal_number` with its default action. Async-signal-safe: sigaction,
// sigprocmask and raise only (the handler runs with the signal blocked, hence the unblock).
void end_by(int signal_number) {
  // write(2) is async-signal-safe (end_by may run in the signal handler); CodeRuns::run keeps
  // finished runs and stages a run under <out>.running until it succeeds.
  static const char kStopped[] =
      "crosscheck: stopped by a signal: finished runs are kept; an interrupted run's files (*.running) are cleared "
      "by the next run\n";
  [[maybe_unused]] const ssize_t written = write(STDERR_FILENO, kStopped, sizeof kStopped - 1);
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  sigemptyset(&default_action.sa_mask);
  sigaction(signal_number, &default_action, nullptr);
  sigset_t just_this;
  sigemptyset(&just_this);
  sigaddset(&just_this, signal_number);
  sigprocmask(SIG_UNBLOCK, &just_this, nullptr);
  raise(signal_number);
  _exit(128 + signal_number);  // not reached
}

void signal_running_groups() {
  for (auto& group : running_groups)
    if (const pid_t g = group.load(); g > 0) kill(-g, SIGTERM);
}

extern "C" void on_stop_signal(int signal_number) {
  int none = 0;
  received_signal.compare_exchange_strong(none, signal_number);
  signal_running_groups();
  if (runs_in_progress.load() == 0 && parallel_sections.load() == 0) end_by(received_signal.load());
}

int take_slot(pid_t group) {
  for (int i = 0; i < kGroupSlots; ++i) {
    pid_t free_slot = 0;
    if (running_groups[i].compare_exchange_strong(free_slot, group)) return i;
  }
  return -1;  // more runs at once than slots: this one is not forwarded a stop signal
}

// The child's attributes: a process group of its own (pgid = its pid), the stop signals at
// their default action, and no signal blocked.
struct SpawnAttributes {
  posix_spawnattr_t attr;
  SpawnAttributes() {
    posix_spawnattr_init(&attr);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
    posix_spawnattr_setpgroup(&attr, 0);
    sigset_t defaults;
    sigemptyset(&defaults);
    for (int s : kStopSignals) sigaddset(&defaults, s);
    posix_spawnattr_setsigdefault(&attr, &defaults);
    sigset_t none;
    sigemptyset(&none);
    posix_spawnattr_setsigmask(&attr, &none);
  }
  ~SpawnAttributes() { posix_spawnattr_destroy(&attr); }
};

// stdin from /dev/null, stdout and stderr to `log` (created or truncated).
struct SpawnFiles {
  posix_spawn_file_actions_t actions;
  explicit SpawnFiles(const std::string& log) {
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  }
  ~SpawnFiles() { posix_spawn_file_actions_destroy(&actions); }
};

}  // namespace

void forward_stop_signals() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  for (int s : kStopSignals) sigaddset(&action.sa_mask, s);  // one handler at a time
  action.sa_flags = SA_RESTART;
  for (int s : kStopSignals) {
    // A signal ignored from the start stays ignored (nohup's SIGHUP; SIGINT of a background
    // job of a shell without job control).
    struct sigaction before {};
    if (sigaction(s, nullptr, &before) == 0 && before.sa_handler == SIG_IGN) continue;
    sigaction(s, &action, nullptr);
  }
}

int run_shell_command(const std::string& command, const std::filesystem::path& log) {
  ++runs_in_progress;
  if (received_signal.load() != 0) {
    --runs_in_progress;
    return -1;
  }
  std::string shell_command = command;
  char shell_name[] = "sh", dash_c[] = "-c";
  char* argv[] = {shell_name, dash_c, shell_command.data(), nullptr};
  const SpawnAttributes attributes;
  const std::string log_name = log.string();  // kept alive until posix_spawn has opened it
  const SpawnFiles files(log_name);
  pid_t child = 0;
  const int spawn_error = posix_spawn(&child, "/bin/sh", &files.actions, &attributes.attr, argv, environ);
  int status = 0;
  bool waited = false;
  if (spawn_error != 0) {
    std::fprintf(stderr, "crosscheck: cannot start /bin/sh for %s: %s\n", command.c_str(), std::strerror(spawn_error));
  } else {
    const int slot = take_slot(child);
    if (received_signal.load() != 0) kill(-child, SIGTERM);  // it came before the slot was taken
    pid_t r = 0;
    while ((r = waitpid(child, &status, 0)) == -1 && errno == EINTR) {
    }
    waited = r == child;
    if (slot >= 0) running_groups[slot].store(0);
  }
  --runs_in_progress;
  if (received_signal.load() != 0 && parallel_sections.load() == 0 && runs_in_progress.load() == 0)
    end_by(received_signal.load());
  return (waited && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
}

bool stop_requested() { return received_signal.load() != 0; }

ParallelSection::ParallelSection() { ++parallel_sections; }
ParallelSection::~ParallelSection() { --parallel_sections; }

void end_if_stop_requested() {
  if (const int s = received_signal.load(); s != 0 && runs_in_progress.load() == 0) end_by(s);
}

}  // namespace crosscheck
