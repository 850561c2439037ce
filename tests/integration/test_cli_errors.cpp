// Bad input: a clear message naming file, key and reason, exit code 2, nothing written,
// and an earlier result never replaced by a failed run.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "cli_runner.hpp"

using namespace colza::testing;
namespace fs = std::filesystem;

namespace {
const std::string kConfig = source_path("tests/data/small_oedometer.toml");
}

TEST(CliErrors, UnknownKeyNamesTheKeyAndWritesNothing) {
  const fs::path out = scratch_dir("unknown-key");
  const CliResult r = run_colza("run oedometer --quiet --config " + kConfig + " --set particle.densty=1200 --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("particle.densty"), std::string::npos) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("unknown key"), std::string::npos) << r.stderr_text;
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliErrors, WrongTypeAndNegativeValuesNameFileKeyAndReason) {
  const fs::path dir = scratch_dir("bad-config");
  fs::create_directories(dir);
  const fs::path cfg = dir / "bad.toml";
  std::ofstream(cfg) << "[particle]\nnormal_stiffness = -5.0\n";
  CliResult r = run_colza("run oedometer --quiet --config " + cfg.string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find(cfg.string()), std::string::npos) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("particle.normal_stiffness"), std::string::npos) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("positive"), std::string::npos) << r.stderr_text;
  std::ofstream(cfg) << "[particle]\ndensity = \"heavy\"\n";
  r = run_colza("run oedometer --quiet --config " + cfg.string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("particle.density"), std::string::npos) << r.stderr_text;
  std::ofstream(cfg) << "[particle]\ndiameter_min = 0.008\n";
  r = run_colza("run oedometer --quiet --config " + cfg.string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("particle.diameter_min"), std::string::npos) << r.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(CliErrors, MissingConfigAndPackingFiles) {
  const fs::path out = scratch_dir("missing-files");
  CliResult r = run_colza("run oedometer --quiet --config /nonexistent/colza.toml --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("/nonexistent/colza.toml"), std::string::npos) << r.stderr_text;
  r = run_colza("run oedometer --quiet --config " + kConfig + " --set oedometer.packing_file=/nonexistent/p.txt --out " +
                out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("oedometer.packing_file"), std::string::npos) << r.stderr_text;
  EXPECT_FALSE(fs::exists(out));
  // A packing that does not fit the 100 mm cylinder (written in millimetres, say).
  fs::create_directories(out.parent_path());
  const fs::path packing = out.parent_path() / "packing-in-mm.txt";
  write_file(packing, "# x y z r\n10.0 5.0 3.5 3.2\n");
  r = run_colza("run oedometer --quiet --config " + kConfig + " --set oedometer.packing_file=" + packing.string() +
                " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find(packing.string() + ": key 'oedometer.packing_file': line 2:"), std::string::npos)
      << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("does not fit this container"), std::string::npos) << r.stderr_text;
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliErrors, ExistingResultIsKeptWithoutForceAndAfterAFailedRun) {
  const fs::path out = scratch_dir("existing-result");
  fs::create_directories(out);
  std::ofstream(out / "summary.json") << "{\"earlier\": true}\n";
  CliResult r = run_colza("run oedometer --quiet --config " + kConfig + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("--force"), std::string::npos) << r.stderr_text;
  EXPECT_EQ(read_file(out / "summary.json"), "{\"earlier\": true}\n");
  // --force with a run that fails (too many spheres for the generation volume): exit 2,
  // and the earlier result is untouched.
  r = run_colza("run oedometer --quiet --force --config " + kConfig + " --set sample.count=100000 --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("sample.count"), std::string::npos) << r.stderr_text;
  EXPECT_EQ(read_file(out / "summary.json"), "{\"earlier\": true}\n");
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(out)) ++entries;
  EXPECT_EQ(entries, 1u);  // no staging folder or partial file left behind
}

TEST(CliErrors, UsageErrorsExitWithTwo) {
  EXPECT_EQ(run_colza("run notascenario --out /tmp/x").exit_code, 2);
  EXPECT_EQ(run_colza("run oedometer").exit_code, 2);  // --out missing
  EXPECT_EQ(run_colza("--help").exit_code, 0);
}

TEST(CliErrors, InterruptedRunRemovesItsPartialOutputsAndKeepsTheEarlierResult) {
  // Ctrl-C (SIGINT) during a run: colza stops between two steps, removes its staging folder
  // and exits with 128 + 2; the earlier result that --force would have replaced stays whole.
  const fs::path out = scratch_dir("interrupted");
  fs::create_directories(out);
  write_file(out / "summary.json", "{\"earlier\": true}\n");
  const fs::path err = out.parent_path() / "interrupted-stderr.txt";
  const std::string cmd = std::string("exec ") + COLZA_EXECUTABLE + " run oedometer --quiet --force --config " +
                          source_path("data/oedometer.toml") + " --out " + out.string() + " > /dev/null 2> " +
                          err.string();
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // The full-size oedometer takes most of a minute; 1.5 s in, it is generating or settling.
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  ::kill(child, SIGINT);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_NE(read_file(err).find("interrupted by SIGINT"), std::string::npos) << read_file(err);
  EXPECT_EQ(read_file(out / "summary.json"), "{\"earlier\": true}\n");
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(out)) ++entries;
  EXPECT_EQ(entries, 1u);  // no staging folder left behind
}

TEST(CliErrors, StagingLeftByAKilledRunIsRemovedByTheNextRun) {
  // A run killed outright (SIGKILL, a crash) cannot clean up; the next run into the same
  // directory removes the staging folders of this machine's processes that have ended, and
  // leaves those of other machines (a shared network disk) alone.
  const fs::path out = scratch_dir("abandoned-staging");
  fs::create_directories(out);
  char host[256] = {0};
  ASSERT_EQ(::gethostname(host, sizeof host - 1), 0);
  const pid_t ended = ::fork();  // a process id that has ended
  ASSERT_GE(ended, 0);
  if (ended == 0) ::_exit(0);
  ASSERT_EQ(::waitpid(ended, nullptr, 0), ended);
  const fs::path abandoned = out / (".colza-partial-" + std::string(host) + "-" + std::to_string(ended));
  const fs::path elsewhere = out / ".colza-partial-some-other-machine-1";
  for (const fs::path& d : {abandoned, elsewhere}) {
    fs::create_directories(d);
    write_file(d / "curve.csv", "half\n");
  }
  const CliResult r = run_colza("run oedometer --quiet --config " + kConfig + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  EXPECT_FALSE(fs::exists(abandoned));
  EXPECT_TRUE(fs::exists(elsewhere / "curve.csv"));
}
