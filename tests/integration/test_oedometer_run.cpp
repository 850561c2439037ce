// End-to-end: a small oedometer through the CLI (tests/data/small_oedometer.toml: the
// paper's particles and contact law in a 40 mm cylinder, 30 mm rim, fast piston).
// Checks the outputs and the invariants of the protocol, not fitted numbers.
#include <gtest/gtest.h>

#include <cmath>

#include "cli_runner.hpp"
#include "io/packing_file.hpp"

using namespace colza::testing;
namespace fs = std::filesystem;

namespace {

const std::string kConfig = source_path("tests/data/small_oedometer.toml");

struct CurveColumns {
  std::vector<double> displacement, force;
};

CurveColumns read_curve(const fs::path& file) {
  std::istringstream in(read_file(file));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "time,piston_displacement,piston_force,contacts,bonds");
  CurveColumns c;
  while (std::getline(in, line)) {
    double t, s, f, n, b;
    char comma;
    std::istringstream row(line);
    row >> t >> comma >> s >> comma >> f >> comma >> n >> comma >> b;
    c.displacement.push_back(s);
    c.force.push_back(f);
  }
  return c;
}

class SmallOedometer : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    out_ = scratch_dir("small-oedometer");
    const CliResult r = run_colza("run oedometer --quiet --config " + kConfig + " --out " + out_.string());
    ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  }
  static fs::path out_;
};
fs::path SmallOedometer::out_;

}  // namespace

TEST_F(SmallOedometer, WritesAllOutputsAndNoStagingLeftovers) {
  for (const char* f : {"curve.csv", "summary.json", "result.h5", "packing.txt"})
    EXPECT_TRUE(fs::exists(out_ / f)) << f;
  for (const auto& entry : fs::directory_iterator(out_))
    EXPECT_EQ(entry.path().filename().string().rfind(".colza-partial", 0), std::string::npos);
}

TEST_F(SmallOedometer, SummaryFollowsTheProtocol) {
  const auto s = read_json(out_ / "summary.json");
  for (const char* key : {"particles", "bulk_density", "fit", "max_force", "dt", "steps", "wall_seconds",
                          "particle_steps_per_second", "stages"})
    EXPECT_TRUE(s.contains(key)) << key;
  EXPECT_TRUE(s["settling"]["converged"].get<bool>());
  EXPECT_LT(s["settling"]["mean_unbalanced_force"].get<double>(), 1e-4);
  // Discarding keeps only spheres below the 30 mm rim: the packing top is at most the rim.
  EXPECT_LE(s["packing_height"].get<double>(), 0.030 + 1e-12);
  EXPECT_LT(s["particles"].get<int>(), s["particles_generated"].get<int>());
  // A loose random packing of spheres: solid fraction between 0.35 and 0.64 (random close
  // packing), i.e. bulk density between 0.35 and 0.64 of rho_p = 1250 kg/m^3 (narrow
  // cylinder walls make it looser than a bulk packing).
  const double bulk = s["bulk_density"].get<double>();
  EXPECT_GT(bulk, 0.35 * 1250.0);
  EXPECT_LT(bulk, 0.64 * 1250.0);
  EXPECT_EQ(s["stop_reason"], "stop_force");
  EXPECT_GE(s["max_force"].get<double>(), 3000.0);
  // The paper: the compression curve is close to a parabola (R^2 > 0.95).
  EXPECT_TRUE(s["fit"]["valid"].get<bool>());
  EXPECT_GT(s["fit"]["r2"].get<double>(), 0.95);
  EXPECT_GT(s["fit"]["c2"].get<double>(), 0.0);  // progressive (stiffening) curve
  EXPECT_EQ(s["stages"].size(), 2u);
}

TEST_F(SmallOedometer, CurveStartsAtZeroAndPistonAdvancesAtItsSpeed) {
  const CurveColumns c = read_curve(out_ / "curve.csv");
  ASSERT_GT(c.force.size(), 10u);
  // The piston is placed touching the highest sphere's top (z + r): no overlap, zero force at
  // first, up to the rounding of z + r (an overlap of ~1e-17 m at most, times Kn ~ 4e5 N/m).
  EXPECT_LT(std::abs(c.force.front()), 1e-9);
  EXPECT_EQ(c.displacement.front(), 0.0);
  for (std::size_t i = 1; i < c.displacement.size(); ++i) EXPECT_GT(c.displacement[i], c.displacement[i - 1]);
}

TEST_F(SmallOedometer, SameSeedSameResultBitForBit) {
  const fs::path again = scratch_dir("small-oedometer-again");
  const CliResult r = run_colza("run oedometer --quiet --config " + kConfig + " --out " + again.string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(read_file(out_ / "curve.csv"), read_file(again / "curve.csv"));
  EXPECT_EQ(read_file(out_ / "packing.txt"), read_file(again / "packing.txt"));
  // result.h5 too, byte for byte: it embeds the summary without its timings and its
  // objects carry no creation times (summary.json keeps the timings, so it differs).
  EXPECT_EQ(read_file(out_ / "result.h5"), read_file(again / "result.h5"));
}

TEST_F(SmallOedometer, OtherSeedOtherPacking) {
  const fs::path other = scratch_dir("small-oedometer-seed");
  const CliResult r = run_colza("run oedometer --quiet --seed 8 --set oedometer.stop_force=200 --config " + kConfig +
                                " --set oedometer.fit_force_min=10 --set oedometer.fit_force_max=150 --out " + other.string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_NE(read_file(out_ / "packing.txt"), read_file(other / "packing.txt"));
}

TEST_F(SmallOedometer, LoadingFromTheWrittenPackingRepeatsTheRunBitForBit) {
  // The packing file holds the settled sample with 17 significant digits (exact round trip),
  // and a new sample is handed to the loading at rest without contact histories, as a
  // packing file gives it: loading from the file repeats the run, curve and all, bit for bit.
  const auto spheres = colza::read_packing((out_ / "packing.txt").string(), "test");
  const auto s = read_json(out_ / "summary.json");
  EXPECT_EQ(spheres.size(), s["particles"].get<std::size_t>());
  const fs::path from_packing = scratch_dir("small-oedometer-packing");
  const CliResult r = run_colza("run oedometer --quiet --config " + kConfig + " --set oedometer.packing_file=" +
                                (out_ / "packing.txt").string() + " --out " + from_packing.string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const auto s2 = read_json(from_packing / "summary.json");
  EXPECT_EQ(s2["particles"], s["particles"]);
  EXPECT_EQ(s2["packing_height"].get<double>(), s["packing_height"].get<double>());
  EXPECT_EQ(s2["bulk_density"].get<double>(), s["bulk_density"].get<double>());
  EXPECT_FALSE(s2.contains("settling"));  // no generation or settling (it said converged, after 0 steps)
  EXPECT_EQ(s2["stop_reason"], "stop_force");
  EXPECT_EQ(read_file(out_ / "packing.txt"), read_file(from_packing / "packing.txt"));
  EXPECT_TRUE(read_file(out_ / "curve.csv") == read_file(from_packing / "curve.csv")) << "the curves differ";
  EXPECT_EQ(s2["fit"], s["fit"]);
}

TEST_F(SmallOedometer, ASettlingCriterionIsNotJudgedWithoutSettling) {
  // A criterion above the spheres' weight is refused when the run settles a sample
  // (ConfigValidation.ASettlingCriterionAboveTheSphereWeightIsRefused), not when it loads a
  // packing file: nothing settles then. 2 mm of travel keep the run short.
  const fs::path out = scratch_dir("small-oedometer-criterion-unused");
  fs::remove_all(out);
  const std::string loose = " --set sample.settle_unbalanced_force=1.0 --set oedometer.max_piston_travel=0.002";
  CliResult r = run_colza("run oedometer --quiet --config " + kConfig + loose + " --set oedometer.packing_file=" +
                          (out_ / "packing.txt").string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
  fs::remove_all(out);
  r = run_colza("run oedometer --quiet --config " + kConfig + loose + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("key 'sample.settle_unbalanced_force'"), std::string::npos) << r.stderr_text;
}

TEST_F(SmallOedometer, ATimeStepFarAboveTheCriticalStopsTheRunInsteadOfWritingItsCurve) {
  // dt = 1 ms, ~100 times the critical estimate: the piston reaches the stop force within a
  // few steps, before any periodic check, with spheres driven metres into the walls. The
  // check at the end of the stage stops the run; the time step was fixed above the critical
  // estimate, so the error names it: exit 2, no result written.
  const fs::path out = scratch_dir("small-oedometer-unstable");
  fs::remove_all(out);
  const CliResult r = run_colza("run oedometer --quiet --config " + kConfig + " --set oedometer.packing_file=" +
                                (out_ / "packing.txt").string() + " --set integration.time_step=1e-3 --out " +
                                out.string());
  EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("key 'integration.time_step': the fixed time step exceeds the critical estimate"),
            std::string::npos)
      << r.stderr_text;
  // Caught by the end-of-stage check, not the periodic one: the step it names is below the
  // first periodic check (step 100, Stepper::kFiniteCheckInterval). (It is step 3 today.)
  const std::size_t at = r.stderr_text.find("at step ");
  ASSERT_NE(at, std::string::npos) << r.stderr_text;
  EXPECT_LT(std::stoull(r.stderr_text.substr(at + 8)), 100u) << r.stderr_text;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
}

TEST_F(SmallOedometer, SettlingCutShortIsAWarning) {
  // The small sample settles in 0.93 s (SummaryFollowsTheProtocol's run); stopped at 0.6 s
  // its mean unbalanced force is ~7e-4 N against 1e-4 N. The run finishes and says so: a
  // WARNING line and summary.json's "warnings", naming the key to raise. The default run
  // converges and has none.
  const fs::path out = scratch_dir("small-oedometer-unsettled");
  fs::remove_all(out);
  const CliResult r = run_colza("run oedometer --quiet --config " + kConfig +
                                " --set sample.settle_max_time=0.6 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const auto s = read_json(out / "summary.json");
  EXPECT_FALSE(s["settling"]["converged"].get<bool>());
  const auto warnings = s["warnings"];
  ASSERT_EQ(warnings.size(), 1u) << warnings.dump();
  const std::string w = warnings[0].get<std::string>();
  EXPECT_EQ(w.rfind("settling did not converge within sample.settle_max_time = 0.6 s", 0), 0u) << w;
  EXPECT_NE(w.find("raise sample.settle_max_time"), std::string::npos) << w;
  EXPECT_NE(r.stdout_text.find("WARNING: " + w), std::string::npos) << r.stdout_text;
  EXPECT_TRUE(read_json(out_ / "summary.json")["warnings"].empty());
}

TEST_F(SmallOedometer, ASampleShortOfTheRimIsAWarning) {
  // The small sample (170 spheres, 40 mm cylinder) stands ~42 mm high; with the rim raised to
  // 50 mm it is not cut level, and its bulk density counts its rough top (a walk-through's
  // 1000 spheres in the paper's cylinder read 572 kg/m^3 against the full sample's 660, with
  // no warning). The fit ends at the largest force when the run stops below fit_force_max,
  // and the console says so.
  const fs::path out = scratch_dir("small-oedometer-short-of-the-rim");
  fs::remove_all(out);
  const CliResult r = run_colza("run oedometer --config " + kConfig +
                                " --set oedometer.cylinder_height=0.05 --set oedometer.stop_force=1000 --out " +
                                out.string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const auto warnings = read_json(out / "summary.json")["warnings"];
  ASSERT_EQ(warnings.size(), 2u) << warnings.dump();
  const std::string w = warnings[0].get<std::string>();
  EXPECT_EQ(w.rfind("the sample's top, ", 0), 0u) << w;
  EXPECT_NE(w.find("below the rim, oedometer.cylinder_height = 50 mm"), std::string::npos) << w;
  EXPECT_NE(w.find("generate more spheres (sample.count)"), std::string::npos) << w;
  EXPECT_NE(r.stdout_text.find("over 20..1000 N"), std::string::npos) << r.stdout_text;
}

TEST_F(SmallOedometer, BondsAreInstalledBeforeLoadingWhenAsked) {
  const fs::path bonded = scratch_dir("small-oedometer-bonded");
  const CliResult r = run_colza("run oedometer --quiet --config " + kConfig +
                                " --set contact.bond=contact_bond --set contact.bond_install=before_loading"
                                " --set oedometer.packing_file=" + (out_ / "packing.txt").string() +
                                " --out " + bonded.string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const auto s = read_json(bonded / "summary.json");
  EXPECT_GT(s["bonds_installed"].get<int>(), 0);
  EXPECT_EQ(s["bond_install"], "before_loading");
}
