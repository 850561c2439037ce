// `colza calibrate repose` and `colza calibrate load_unload`: the lab tests of issue 39 as
// calibration stages. Their measured data are features by a run's names, stated or read off a
// measured curve (a heap profile, a load-unload curve) by the code that reduces colza's own
// runs. Here the "measured" curve is a colza run's own, at a known parameter: its features
// read back must equal the run's, and the loop must run and report. A check of the plumbing,
// not of recovery (small samples scatter more than one parameter moves them; the diagnosis's
// tests check recovery with replicates).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cli_runner.hpp"

using namespace colza::testing;
namespace fs = std::filesystem;

namespace {

// The small heap on a glued base under damping 0.2, as the diagnosis's small lab set: at rest
// within ~1 s, ~10 s a run on one core.
const std::string kRepose = source_path("tests/data/small_repose.toml");
const std::string kReposeSet =
    "\"particle.normal_stiffness=437e3\", \"particle.density=1250\", \"repose.generation_height=0.18\", "
    "\"repose.base=glued_layer\", \"integration.damping=0.2\", \"repose.rest_max_time=4\", \"output.plots=false\"";

// The small oedometer with one load-unload cycle to 40 kPa (a few seconds a run).
const std::string kOed = source_path("tests/data/small_oedometer.toml");
const std::string kCycleSet = "\"oedometer.cycles=[40e3, 0.0]\", \"oedometer.record_interval=5\", \"output.plots=false\"";

std::string repose_spec(const std::string& measured) {
  return "stage = \"repose\"\n[model]\nconfig = \"" + kRepose + "\"\nset = [" + kReposeSet +
         "]\n[[parameters]]\nname = \"mu_pp\"\nkey = \"particle.friction\"\ndesign = [0.3, 0.5]\n[measured]\n" +
         measured;
}

std::string load_unload_spec(const std::string& measured, const std::string& set = kCycleSet) {
  return "stage = \"load_unload\"\n[model]\nconfig = \"" + kOed + "\"\nset = [" + set +
         "]\n[[parameters]]\nname = \"kn_p\"\nkey = \"particle.normal_stiffness\"\nunit = \"N/m\"\n"
         "design = [450e3, 550e3]\n[measured]\n" + measured;
}

// "--set 'a' --set 'b'" from a spec's set list.
std::string as_set_options(const std::string& set) {
  std::string options;
  std::size_t at = 0;
  while ((at = set.find('"', at)) != std::string::npos) {
    const std::size_t end = set.find('"', at + 1);
    options += " --set '" + set.substr(at + 1, end - at - 1) + "'";
    at = end + 1;
  }
  return options;
}

// A refused spec: exit 2, the spec, the key and the reason named, nothing written.
void expect_refused(const fs::path& dir, const std::string& stage, const std::string& spec_text,
                    const std::string& key, const std::string& reason) {
  const fs::path spec = dir / "bad.toml", out = dir / "bad-out";
  write_file(spec, spec_text);
  const CliResult r = run_colza("calibrate " + stage + " --quiet --spec " + spec.string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find(spec.string() + ": key '" + key + "'"), std::string::npos) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find(reason), std::string::npos) << r.stderr_text;
  EXPECT_FALSE(fs::exists(out)) << key;
}

}  // namespace

TEST(CalibrateRepose, AHeapProfileIsReducedAsARunsHeapAndTheLoopFindsItsFriction) {
  const fs::path dir = scratch_dir("calibrate-repose");
  fs::create_directories(dir);
  ASSERT_EQ(run_colza("run repose --quiet --threads 1 --config " + kRepose + as_set_options(kReposeSet) +
                      " --set particle.friction=0.3 --out " + (dir / "truth").string()).exit_code, 0);
  const double truth = read_json(dir / "truth" / "summary.json")["angle_of_repose"]["angle_deg"].get<double>();
  write_file(dir / "spec.toml", repose_spec("curve = \"truth/heap_profile.csv\"\n[[measured.features]]\n"
                                            "name = \"angle_of_repose_deg\"\nunit = \"deg\"\nuncertainty = 3.0\n"));
  const CliResult r = run_colza("calibrate repose --quiet --jobs 2 --threads 1 --spec " + (dir / "spec.toml").string() +
                                " --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json s = read_json(dir / "out" / "summary.json");
  // The profile goes through the run's cone fit: the same surface spheres, bins of the model's
  // mean diameter instead of the heap's own (6.5 mm against the drawn spheres' mean).
  ASSERT_EQ(s["targets"].size(), 1u);
  EXPECT_EQ(s["targets"][0]["name"], "angle_of_repose_deg");
  EXPECT_NEAR(s["targets"][0]["measured"].get<double>(), truth, 0.5) << s["targets"][0].dump();
  EXPECT_EQ(s["measured"]["source"], "curve");
  EXPECT_EQ(s["measured"]["targets_from_curve"][0], "angle_of_repose_deg");
  EXPECT_TRUE(s["measured"]["curve_features"].contains("heap_radius"));
  const std::string report = read_file(dir / "out" / "report.md");
  EXPECT_NE(report.find("| angle_of_repose_deg | "), std::string::npos);
  EXPECT_NE(report.find("angle of repose test"), std::string::npos);
  // The design's first point is the measured heap's own run (same config, seed and friction):
  // the surface through it meets the measured angle there, and the validation run is that run.
  EXPECT_NEAR(s["parameters"][0]["value"].get<double>(), 0.3, 0.02) << s["parameters"][0].dump();
}

TEST(CalibrateLoadUnload, ALoadUnloadCurveIsReducedAsARunsAndTheLoopRuns) {
  const fs::path dir = scratch_dir("calibrate-load-unload");
  fs::create_directories(dir);
  ASSERT_EQ(run_colza("run oedometer --quiet --threads 1 --config " + kOed + as_set_options(kCycleSet) +
                      " --set particle.normal_stiffness=450e3 --out " + (dir / "truth").string()).exit_code, 0);
  const nlohmann::json truth = read_json(dir / "truth" / "summary.json");
  const double height = truth["packing_height"].get<double>();
  const double rebound = truth["load_unload"]["cycles"][0]["rebound_strain"].get<double>();
  const double bulk_density = truth["bulk_density"].get<double>();
  write_file(dir / "spec.toml",
             load_unload_spec("curve = \"truth/curve.csv\"\nsample_height = " + std::to_string(height) +
                              "\n[[measured.features]]\nname = \"cycle1/rebound_strain\"\nuncertainty = 1e-4\n"
                              "[[measured.features]]\nname = \"bulk_density\"\nvalue = " + std::to_string(bulk_density) +
                              "\nuncertainty = 15.0\n"));
  const CliResult r = run_colza("calibrate load_unload --quiet --jobs 2 --threads 1 --spec " +
                                (dir / "spec.toml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json s = read_json(dir / "out" / "summary.json");
  ASSERT_EQ(s["targets"].size(), 2u);
  // The run's own curve read back as a measured one gives the run's rebound strain (the same
  // reduction, the sample's height as the run's packing height; its record rows are the run's).
  EXPECT_NEAR(s["targets"][0]["measured"].get<double>(), rebound, 1e-3 * std::abs(rebound));
  EXPECT_EQ(s["measured"]["targets_from_curve"].size(), 1u);
  EXPECT_NE(read_file(dir / "out" / "report.md").find(" | 15 | the spec |"), std::string::npos);
  // The design's first point is the measured curve's own run: the solution lies at it.
  EXPECT_NEAR(s["parameters"][0]["value"].get<double>(), 450e3, 10e3) << s["parameters"][0].dump();
}

TEST(CalibrateLabStages, BadMeasuredFeaturesAreRefusedBeforeAnyRun) {
  const fs::path dir = scratch_dir("calibrate-lab-stages-bad");
  fs::create_directories(dir);
  expect_refused(dir, "repose", repose_spec("[[measured.features]]\nname = \"c1\"\nvalue = 1.0\nuncertainty = 1.0\n"),
                 "measured.features[0].name", "is not a feature of a repose run");
  expect_refused(dir, "repose",
                 repose_spec("[[measured.features]]\nname = \"angle_of_repose_deg\"\nvalue = 0.5\nuncertainty = 0.02\n"),
                 "measured.features[0].value", "is it in radians?");
  expect_refused(dir, "repose", repose_spec("[[measured.features]]\nname = \"angle_of_repose_deg\"\nuncertainty = 1.0\n"),
                 "measured.features[0].value", "missing");
  expect_refused(dir, "repose", repose_spec("sample_height = 0.05\n[[measured.features]]\nname = \"heap_radius\"\n"
                                            "value = 0.06\nuncertainty = 0.005\n"),
                 "measured.sample_height", "belongs to a measured load-unload curve");
  expect_refused(dir, "repose", repose_spec(""), "measured.features", "missing");
  expect_refused(dir, "load_unload",
                 load_unload_spec("[[measured.features]]\nname = \"cycle1/rebound_strain\"\nvalue = 1e-3\nuncertainty = 1e-4\n",
                                  "\"output.plots=false\""),
                 "model", "needs a load-unload cycle");
  expect_refused(dir, "load_unload",
                 load_unload_spec("curve = \"missing.csv\"\nsample_height = 0.04\n[[measured.features]]\n"
                                  "name = \"cycle1/rebound_strain\"\nuncertainty = 1e-4\n"),
                 "measured.curve", "does not exist");
}
