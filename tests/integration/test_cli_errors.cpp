// Bad input: a clear message naming file, key and reason, exit code 2, nothing written,
// and an earlier result never replaced by a failed run.
#include <gtest/gtest.h>

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
