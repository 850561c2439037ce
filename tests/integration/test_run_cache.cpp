// The run cache (calibration/run_cache.hpp) on the small oedometer, called directly: a run is
// made once and then answered from its folder, by the same fingerprint, with the same
// outputs; another realisation is another run with seed + 1; the caller's annotations go
// into the summary; the outputs read as named features (run_features.hpp).
#include <gtest/gtest.h>

#include "calibration/run_cache.hpp"
#include "calibration/run_features.hpp"
#include "core/version.hpp"
#include "io/fingerprint.hpp"

#include "cli_runner.hpp"

using namespace colza;
using namespace colza::calibration;
using namespace colza::testing;
namespace fs = std::filesystem;

namespace {

RunRequest small_oedometer(int replicate) {
  RunRequest r;
  r.scenario = Scenario::kOedometer;
  r.config_path = source_path("tests/data/small_oedometer.toml");
  r.overrides = {"oedometer.stop_force=100.0", "oedometer.fit_force_max=90.0", "particle.friction=0.3"};
  r.replicate = replicate;
  r.annotations = {{"stage", "a test"}};
  r.label = "mu = 0.3";
  return r;
}

TEST(RunCache, ARunIsMadeOnceThenReusedAndAnotherSeedIsAnotherRun) {
  const fs::path runs = scratch_dir("run-cache") / "runs";
  fs::remove_all(runs);
  RunCache cache(runs, /*verbose=*/false);
  const RunRecord first = cache.run(small_oedometer(0));
  EXPECT_FALSE(first.reused);
  EXPECT_TRUE(is_fingerprint_text(first.id)) << first.id;
  EXPECT_EQ(first.dir, runs / first.id);
  EXPECT_TRUE(fs::exists(first.dir / "curve.csv"));
  const nlohmann::json summary = read_json(first.dir / "summary.json");
  EXPECT_EQ(summary["fingerprint"], first.id);
  EXPECT_EQ(summary["stage"], "a test");
  EXPECT_EQ(summary["outputs"], first.outputs);
  EXPECT_EQ(first.seed, 7u);  // tests/data/small_oedometer.toml

  const RunRecord again = cache.run(small_oedometer(0));
  EXPECT_TRUE(again.reused);
  EXPECT_EQ(again.id, first.id);
  EXPECT_EQ(again.outputs, first.outputs);
  EXPECT_EQ(RunCache(runs, false).run(small_oedometer(0)).id, first.id);  // another cache on the same folder

  const RunRecord other = cache.run(small_oedometer(1));
  EXPECT_FALSE(other.reused);
  EXPECT_NE(other.id, first.id);
  EXPECT_EQ(other.seed, 8u);

  const Features f = output_features(first.outputs);
  EXPECT_GT(f.at("bulk_density"), 0.0);
  EXPECT_EQ(f.at("bulk_density"), first.outputs["bulk_density"].get<double>());
}

}  // namespace

TEST(RunCache, ReusedRunsOfAnotherRevisionAreNamedInOneWarning) {
  const std::string here = git_revision();
  EXPECT_EQ(runs_by_another_revision_warning({{"a1", here}, {"a2", here}}, "runs"), "");
  const std::string one = runs_by_another_revision_warning({{"a1", here}, {"b1", "0123abc"}, {"b1", "0123abc"}}, "runs");
  EXPECT_NE(one.find("another revision of colza than this one (" + here + "): b1 (0123abc);"), std::string::npos) << one;
  EXPECT_NE(one.find("remove them from runs"), std::string::npos) << one;
  // Ten are named, the others counted.
  std::vector<std::pair<std::string, std::string>> many;
  for (int k = 0; k < 13; ++k) many.emplace_back("r" + std::to_string(k), "unknown");
  const std::string w = runs_by_another_revision_warning(many, "runs");
  EXPECT_NE(w.find("r9 (unknown) and 3 more"), std::string::npos) << w;
  EXPECT_EQ(w.find("r10 "), std::string::npos) << w;
}
