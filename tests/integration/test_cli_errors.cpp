// Bad input: a clear message naming file, key and reason, exit code 2, nothing written,
// and an earlier result never replaced by a failed run.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

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

TEST(CliErrors, AFixedTimeStepThatBlowsTheSampleApartNamesTheTimeStep) {
  // 1 ms against a critical estimate of ~23 us (small sample, Table 1 stiffnesses): the
  // spheres fly off during settling. The error names integration.time_step, not sample.count.
  const fs::path out = scratch_dir("blown-apart");
  const CliResult r = run_colza("run oedometer --quiet --config " + kConfig +
                                " --set integration.time_step=1e-3 --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  // The value came from --set, so the error names it there rather than the file.
  EXPECT_NE(r.stderr_text.find("--set integration.time_step: key 'integration.time_step'"), std::string::npos)
      << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("exceeds the critical estimate"), std::string::npos) << r.stderr_text;
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliErrors, ACheckAcrossTwoKeysGivesBothValues) {
  // A shorter shear with the file's strength window: the message gives both lengths.
  const fs::path out = scratch_dir("window-past-the-shear");
  const CliResult r = run_colza("run shear --quiet --normal-stress 25750 --config " +
                                source_path("tests/data/small_shear.toml") +
                                " --set shear_box.shear_displacement=0.002 --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("key 'shear_box.strength_window_end': 0.003 m must not exceed "
                               "shear_box.shear_displacement, 0.002 m"),
            std::string::npos)
      << r.stderr_text;
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
  const CliResult missing_out = run_colza("run oedometer");
  EXPECT_EQ(missing_out.exit_code, 2);
  // Option-parser errors carry the same prefix as every other colza error.
  EXPECT_EQ(missing_out.stderr_text.rfind("colza: error: --out is required", 0), 0u) << missing_out.stderr_text;
  EXPECT_EQ(run_colza("--help").exit_code, 0);
}

TEST(CliErrors, OptionsAScenarioWouldIgnoreAndOutOfRangeValuesAreErrors) {
  const fs::path out = scratch_dir("inapplicable");
  const std::string shear = source_path("tests/data/small_shear.toml");
  CliResult r = run_colza("run oedometer --quiet --config " + kConfig + " --normal-stress 1000 --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("--normal-stress: `colza run oedometer` does not take it"), std::string::npos)
      << r.stderr_text;
  r = run_colza("run shear --quiet --config " + shear + " --normal-stress 1000 --jobs 2 --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("--jobs: `colza run shear` does not take it"), std::string::npos) << r.stderr_text;
  // The built-in defaults are the oedometer's: a shear run without a config is refused.
  r = run_colza("run shear-series --quiet --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("--config"), std::string::npos) << r.stderr_text;
  // A folder given as the config.
  r = run_colza("run oedometer --quiet --config " + source_path("data") + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("is a directory, not a file"), std::string::npos) << r.stderr_text;
  // A device that would be read forever.
  r = run_colza("run oedometer --quiet --config /dev/zero --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("is not a regular file"), std::string::npos) << r.stderr_text;
  for (const char* bad : {"--threads 0", "--seed -3", "--threads 1.5"}) {
    r = run_colza(std::string("run oedometer --quiet ") + bad + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.stderr_text.find("must be a whole number"), std::string::npos) << bad << ": " << r.stderr_text;
  }
  r = run_colza("run shear --quiet --config " + shear + " --normal-stress inf --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("must be a finite number > 0"), std::string::npos) << r.stderr_text;
  r = run_colza("run shear-series --quiet --config " + shear + " --set shear_box.normal_stresses=[1e4,inf] --out " +
                out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("shear_box.normal_stresses': every entry must be a finite number"), std::string::npos)
      << r.stderr_text;
  EXPECT_FALSE(fs::exists(out));
}

TEST(CliErrors, AFolderWithOtherFilesIsNotWrittenIntoWithoutForce) {
  const fs::path out = scratch_dir("foreign-files");
  fs::create_directories(out);
  write_file(out / "packing.txt", "my own packing\n");
  const CliResult r = run_colza("run oedometer --quiet --config " + kConfig + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("holds packing.txt but no colza result"), std::string::npos)
      << r.stderr_text;
  EXPECT_EQ(read_file(out / "packing.txt"), "my own packing\n");
  // Several: the first three by name, then how many more.
  for (const char* f : {"d.txt", "b.txt", "a.txt", "c.txt"}) write_file(out / f, "mine\n");
  const CliResult many = run_colza("run oedometer --quiet --config " + kConfig + " --out " + out.string());
  EXPECT_EQ(many.exit_code, 2);
  EXPECT_NE(many.stderr_text.find("holds a.txt, b.txt, c.txt and 2 more but no colza result"), std::string::npos)
      << many.stderr_text;
}

TEST(CliErrors, ForceReplacesOnlyColzasOwnFiles) {
  // --force into a folder of the user's own: files of the same name are replaced, but a
  // summary.json colza did not write does not make the user's load-* folders an earlier
  // result to remove.
  const fs::path out = scratch_dir("force-foreign");
  fs::create_directories(out / "load-cases");
  write_file(out / "summary.json", "{\"mine\": true}\n");
  write_file(out / "load-cases" / "summary.json", "{\"mine\": true}\n");
  write_file(out / "notes.txt", "keep\n");
  const CliResult r = run_colza("run oedometer --quiet --force --config " + kConfig + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_TRUE(read_json(out / "summary.json").contains("colza_version"));  // replaced: the same name
  EXPECT_EQ(read_file(out / "load-cases" / "summary.json"), "{\"mine\": true}\n");
  EXPECT_EQ(read_file(out / "notes.txt"), "keep\n");
  // Now out holds colza's own result: --force again replaces it, yet a folder that is not a
  // load's (load-<digits>Pa) stays, even with a summary naming colza_version.
  write_file(out / "load-cases" / "summary.json", "{\"colza_version\": \"mine\"}\n");
  const CliResult again = run_colza("run oedometer --quiet --force --config " + kConfig + " --out " + out.string());
  ASSERT_EQ(again.exit_code, 0) << again.stderr_text;
  EXPECT_EQ(read_file(out / "load-cases" / "summary.json"), "{\"colza_version\": \"mine\"}\n");
}

TEST(CliErrors, AFolderNamedLikeAResultFileIsRefusedBeforeTheRun) {
  // --force replaces files of the same name, but a folder cannot be renamed over: refused
  // before the run (it was refused only at the end, after the whole run), and left as it is.
  const fs::path out = scratch_dir("folder-named-curve");
  fs::create_directories(out / "curve.csv");
  write_file(out / "curve.csv" / "mine.txt", "keep\n");
  const CliResult r = run_colza("run oedometer --quiet --force --config " + kConfig + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("holds a folder named curve.csv"), std::string::npos) << r.stderr_text;
  EXPECT_EQ(read_file(out / "curve.csv" / "mine.txt"), "keep\n");
  EXPECT_FALSE(fs::exists(out / "summary.json"));
}

TEST(CliErrors, EmptyPackingFileIsRefusedBeforeTheRun) {
  const fs::path dir = scratch_dir("empty-packing");
  fs::create_directories(dir);
  write_file(dir / "empty.txt", "# x y z r\n");
  const CliResult r = run_colza("run oedometer --quiet --config " + kConfig + " --set oedometer.packing_file=" +
                                (dir / "empty.txt").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find((dir / "empty.txt").string() + ": key 'oedometer.packing_file': holds no sphere"),
            std::string::npos)
      << r.stderr_text;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(CliErrors, InterruptedRunRemovesItsPartialOutputsAndKeepsTheEarlierResult) {
  // Ctrl-C (SIGINT) during a run: colza stops between two steps, removes its staging folder
  // and exits with 128 + 2; the earlier result that --force would have replaced stays whole.
  const fs::path out = scratch_dir("interrupted");
  fs::create_directories(out);
  write_file(out / "summary.json", "{\"earlier\": true}\n");
  // The full-size oedometer takes most of a minute: stopped once its staging folder exists
  // (it is generating or settling then).
  const CliResult r = run_colza_interrupted(
      "run oedometer --quiet --force --config " + source_path("data/oedometer.toml") + " --out " + out.string(),
      [&] { return has_entry_containing(out, ".colza-partial-"); });
  EXPECT_TRUE(r.ready_reached);
  EXPECT_EQ(r.exit_code, 130);
  EXPECT_NE(r.stderr_text.find("interrupted by SIGINT"), std::string::npos) << r.stderr_text;
  EXPECT_EQ(read_file(out / "summary.json"), "{\"earlier\": true}\n");
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(out)) ++entries;
  EXPECT_EQ(entries, 1u);  // no staging folder left behind
}

TEST(CliErrors, OneInterruptDeliveredTwiceStillCleansUp) {
  // timeout(1) sends SIGINT to colza and then to its own process group, colza included: two
  // signals microseconds apart are one request, so colza still stops between two steps and
  // removes its staging folder (it stopped at once and left it: a walk-through, 2 runs in 6).
  const fs::path out = scratch_dir("interrupted-twice");
  fs::create_directories(out);
  const CliResult r = run_colza_interrupted(
      "run oedometer --quiet --config " + source_path("data/oedometer.toml") + " --out " + out.string(),
      [&] { return has_entry_containing(out, ".colza-partial-"); }, std::chrono::seconds(120), 2);
  EXPECT_TRUE(r.ready_reached);
  EXPECT_EQ(r.exit_code, 130);
  EXPECT_NE(r.stderr_text.find("interrupted by SIGINT"), std::string::npos) << r.stderr_text;
  EXPECT_TRUE(fs::is_empty(out));  // no staging folder left behind
}

TEST(CliErrors, StagingLeftByAKilledRunIsRemovedByTheNextRun) {
  // A run killed outright (SIGKILL, a crash) cannot clean up; the next run into the same
  // directory removes the staging folders of this machine's processes that have ended (a
  // zombie too), and leaves those of other machines (a shared network disk) alone.
  const fs::path out = scratch_dir("abandoned-staging");
  fs::create_directories(out);
  char host[256] = {0};
  ASSERT_EQ(::gethostname(host, sizeof host - 1), 0);
  const pid_t ended = ::fork();  // a process id that has ended
  ASSERT_GE(ended, 0);
  if (ended == 0) ::_exit(0);
  ASSERT_EQ(::waitpid(ended, nullptr, 0), ended);
  const fs::path abandoned = out / (".colza-partial-" + std::string(host) + "-" + std::to_string(ended));
  // A zombie: ended, not yet waited for by its parent (this test, until the run is done). It
  // holds its pid, so kill(pid, 0) finds it, but it writes nothing any more.
  const pid_t zombie = ::fork();
  ASSERT_GE(zombie, 0);
  if (zombie == 0) ::_exit(0);
  const fs::path zombies = out / (".colza-partial-" + std::string(host) + "-" + std::to_string(zombie));
  const fs::path elsewhere = out / ".colza-partial-some-other-machine-1";
  for (const fs::path& d : {abandoned, zombies, elsewhere}) {
    fs::create_directories(d);
    write_file(d / "curve.csv", "half\n");
  }
  const CliResult r = run_colza("run oedometer --quiet --config " + kConfig + " --out " + out.string());
  ASSERT_EQ(::waitpid(zombie, nullptr, 0), zombie);
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  EXPECT_FALSE(fs::exists(abandoned));
  EXPECT_FALSE(fs::exists(zombies));
  EXPECT_TRUE(fs::exists(elsewhere / "curve.csv"));
}
