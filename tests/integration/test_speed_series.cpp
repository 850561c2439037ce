// End-to-end: `colza run ... --speeds` (cli/speed_series_command.hpp). The small oedometer at
// two piston speeds a decade apart runs one sample (one settled packing: the same bulk
// density at both), its inertial numbers scale with the speed (I = (v / H) d sqrt(rho_p / p),
// H the same packing's height; p, the largest piston stress, differs only by the force the
// last step overshoots the stop), and the series is written whole. Bad --speeds: exit 2
// naming --speeds and the reason, nothing written.
#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "../unit/scratch_dir.hpp"

using namespace colza::testing;
namespace fs = std::filesystem;

namespace {
const std::string kConfig = source_path("tests/data/small_oedometer.toml");
}

TEST(SpeedSeries, TheSameOedometerSampleAtTwoSpeedsADecadeApart) {
  const ScratchDir dir;
  const fs::path out = dir.path() / "series";
  const CliResult r = run_colza("run oedometer --config " + kConfig + " --speeds 0.005,0.05 --out " + out.string() +
                                " --quiet --jobs 2 --threads 1");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json s = nlohmann::json::parse(read_file(out / "summary.json"));
  EXPECT_EQ(s["speed_key"], "oedometer.piston_speed");
  ASSERT_EQ(s["runs"].size(), 2u);
  const double i_slow = s["runs"][0]["inertial_number"], i_fast = s["runs"][1]["inertial_number"];
  EXPECT_NEAR(i_fast / i_slow, 10.0, 0.01);
  bool saw_density = false, saw_c1 = false;
  for (const auto& t : s["trends"]) {
    if (t["feature"] == "bulk_density") {
      saw_density = true;
      EXPECT_EQ(t["values"][0], t["values"][1]);  // one packing for both speeds
      EXPECT_EQ(t["per_decade"], 0.0);
    }
    if (t["feature"] == "c1") saw_c1 = true;
  }
  EXPECT_TRUE(saw_density);
  EXPECT_TRUE(saw_c1);
  EXPECT_TRUE(fs::exists(out / "speed_series.csv"));
  EXPECT_TRUE(fs::exists(out / fs::path(s["runs"][1]["run"].get<std::string>()) / "curve.csv"));
}

TEST(SpeedSeries, BadSpeedsAreRefusedNamingTheOptionAndNothingIsWritten) {
  const ScratchDir dir;
  const fs::path out = dir.path() / "series";
  const struct {
    std::string args, reason;
  } cases[] = {
      {"run oedometer --config " + kConfig + " --speeds 0.005", "at least two speeds"},
      {"run oedometer --config " + kConfig + " --speeds 0.005,0", "not a positive speed"},
      {"run oedometer --config " + kConfig + " --speeds 0.005,0.005", "listed twice"},
      {"run shear --config " + source_path("tests/data/small_shear.toml") + " --speeds 0.005,0.05", "no speed series"},
  };
  for (const auto& c : cases) {
    const CliResult r = run_colza(c.args + " --out " + out.string() + " --quiet");
    EXPECT_EQ(r.exit_code, 2) << c.args << ": " << r.stderr_text;
    EXPECT_NE(r.stderr_text.find("--speeds"), std::string::npos) << r.stderr_text;
    EXPECT_NE(r.stderr_text.find(c.reason), std::string::npos) << r.stderr_text;
    EXPECT_FALSE(fs::exists(out)) << c.args;
  }
}
