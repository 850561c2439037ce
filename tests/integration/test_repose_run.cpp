// End-to-end: the angle of repose test (colza run repose; tests/data/small_repose.toml: the
// paper's particles in a 60 mm cylinder filled 60 mm high, lifted fast). Checks the outputs,
// the cone fit's plausibility, determinism, that spheres without rolling resistance form no
// heap on the bare plate once the damping lets them move, that on a glued layer they do and it
// rests, and bad input. That the angle grows with sliding friction is the friction series
// (label full, tests/full/test_repose_friction_series.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "cli_runner.hpp"

using namespace colza::testing;
namespace fs = std::filesystem;

namespace {

const std::string kConfig = source_path("tests/data/small_repose.toml");

// Runs the small heap with `sets` (--set options) into `out`: its summary.json, or an empty
// object when the run failed (the failure is reported).
nlohmann::json run_small_repose(const fs::path& out, const std::string& sets) {
  const CliResult r = run_colza("run repose --quiet --config " + kConfig + " " + sets + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.stderr_text;
  return r.exit_code == 0 ? read_json(out / "summary.json") : nlohmann::json::object();
}

// Runs the small heap with `sets` into `out`, expecting it refused before anything is written:
// exit 2, naming `key`. Its stderr.
std::string expect_refused(const fs::path& out, const std::string& sets, const std::string& key) {
  const CliResult r = run_colza("run repose --quiet --config " + kConfig + " " + sets + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << sets;
  EXPECT_NE(r.stderr_text.find("key '" + key + "'"), std::string::npos) << r.stderr_text;
  EXPECT_FALSE(fs::exists(out)) << sets;
  return r.stderr_text;
}

class SmallRepose : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    out_ = scratch_dir("small-repose");
    const CliResult r = run_colza("run repose --quiet --config " + kConfig + " --out " + out_.string());
    ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
    stdout_ = r.stdout_text;
  }
  static fs::path out_;
  static std::string stdout_;
};
fs::path SmallRepose::out_;
std::string SmallRepose::stdout_;

}  // namespace

TEST_F(SmallRepose, WritesAHeapAndItsAngle) {
  for (const char* f : {"summary.json", "result.h5", "packing.txt", "heap.txt", "heap_profile.csv"})
    EXPECT_TRUE(fs::exists(out_ / f)) << f;
  const auto s = read_json(out_ / "summary.json");
  const auto& a = s["angle_of_repose"];
  ASSERT_TRUE(a["valid"].get<bool>()) << s.dump(1);
  // The fixture's heap (paper's damping 0.7) stands at ~25 deg while it is still creeping; only
  // that a cone was fitted to a heap that slopes is checked: 10-45 deg.
  const double angle = a["angle_deg"].get<double>();
  EXPECT_GT(angle, 10.0);
  EXPECT_LT(angle, 45.0);
  EXPECT_GT(a["angle_error_deg"].get<double>(), 0.0);
  EXPECT_LT(a["angle_error_deg"].get<double>(), 5.0);
  EXPECT_GE(a["points"].get<int>(), 10);
  // The heap is lower than the column was and wider than the cylinder.
  EXPECT_LT(a["heap_height"].get<double>(), s["column_height"].get<double>());
  EXPECT_GT(a["heap_radius"].get<double>(), 0.030);
  // Without rolling resistance the heap's surface spheres keep rolling for seconds: a rest not
  // reached within rest_max_time is said, not hidden.
  if (!s["rest"]["converged"].get<bool>())
    EXPECT_NE(s["warnings"].dump().find("the heap did not come to rest"), std::string::npos) << s["warnings"].dump();
  // 50 mm/s on a 60 mm column at ~180 Pa: I ~ 1.4e-2, warned of.
  EXPECT_GT(s["inertial_number"]["value"].get<double>(), 1e-3);
  EXPECT_NE(s["warnings"].dump().find("the inertial number of the lift"), std::string::npos) << s["warnings"].dump();
  EXPECT_NE(stdout_.find("angle of repose"), std::string::npos) << stdout_;
}

TEST_F(SmallRepose, TheSameSeedGivesTheSameHeapBitForBit) {
  const fs::path again = scratch_dir("small-repose-again");
  const CliResult r = run_colza("run repose --quiet --config " + kConfig + " --out " + again.string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_EQ(read_file(again / "heap.txt"), read_file(out_ / "heap.txt"));
}

TEST(Repose, WithoutRollingResistanceAndWithLightDampingNoHeapForms) {
  // colza's contact law has no rolling resistance: a sphere on the plate or on the heap rolls
  // on without loss, and spheres without rolling resistance form no stable heap (physics.md
  // section 8: rolling resistance is what raises the angle). With light local damping (0.1)
  // the column spreads into a layer: no surface sphere stands two diameters high, no cone is
  // fitted, and the summary says so. (With the paper's 0.7 the damping slows the collapse so
  // much that a heap stands for seconds without coming to rest: the fixture's run.)
  const auto s = run_small_repose(scratch_dir("repose-light-damping"), "--set integration.damping=0.1");
  ASSERT_FALSE(s.empty());
  EXPECT_FALSE(s["angle_of_repose"]["valid"].get<bool>()) << s["angle_of_repose"].dump();
  EXPECT_NE(s["warnings"].dump().find("no cone could be fitted"), std::string::npos) << s["warnings"].dump();
}

TEST(Repose, OnAGluedLayerTheHeapRestsAndNoSphereReachesThePlate) {
  // repose.base = "glued_layer": a monolayer of fixed spheres covers a 210 mm disc of the
  // plate (scenario/glued_layer.hpp) and the heap stands on it. Its lowest spheres can no
  // longer roll away on the bare plate, so a heap of frictional spheres without rolling
  // resistance comes to rest (on the bare plate it does not: the fixture's run). Checked:
  // the heap rests, its angle is fitted, the summary describes the base, and no free sphere
  // within the glued disc (a diameter from its rim) touches the plate.
  const fs::path out = scratch_dir("repose-glued");
  const auto s = run_small_repose(
      out, "--set repose.base=glued_layer --set repose.generation_height=0.18 --set repose.rest_max_time=8");
  ASSERT_FALSE(s.empty());
  EXPECT_TRUE(s["rest"]["converged"].get<bool>()) << s["rest"].dump();
  EXPECT_TRUE(s["angle_of_repose"]["valid"].get<bool>()) << s["angle_of_repose"].dump();
  EXPECT_EQ(s["base"]["kind"], "glued_layer");
  EXPECT_GT(s["base"]["glued_spheres"].get<int>(), 400);
  const double disc_radius = 0.5 * s["base"]["glued_layer_diameter"].get<double>();
  EXPECT_NEAR(disc_radius, 0.105, 1e-12);  // 3.5 cylinder diameters
  // The base stands about a diameter (6-7 mm) above the plate.
  EXPECT_GT(s["base"]["base_height"].get<double>(), 0.006);
  EXPECT_LT(s["base"]["base_height"].get<double>(), 0.007);
  // heap.txt: the free spheres only, `x y z r` (comment lines start with #).
  std::istringstream heap(read_file(out / "heap.txt"));
  std::string line;
  std::size_t spheres = 0, on_plate = 0;
  while (std::getline(heap, line)) {
    if (line.empty() || line[0] == '#') continue;
    double x, y, z, radius;
    std::istringstream(line) >> x >> y >> z >> radius;
    ++spheres;
    if (std::hypot(x, y) < disc_radius - 0.007 && z - radius < 1e-4) ++on_plate;
  }
  EXPECT_EQ(spheres, s["particles"].get<std::size_t>());
  EXPECT_EQ(on_plate, 0u);
}

TEST(Repose, BadInputIsExit2NamingTheKey) {
  const fs::path out = scratch_dir("repose-bad") / "out";
  const std::string narrow = expect_refused(out, "--set repose.cylinder_diameter=0.02", "repose.cylinder_diameter");
  EXPECT_NE(narrow.find("narrower than 5 particle diameters"), std::string::npos) << narrow;
  expect_refused(out, "--set repose.base=carpet", "repose.base");
  expect_refused(out, "--set repose.base=glued_layer --set repose.glued_layer_diameter=0.07",
                 "repose.glued_layer_diameter");
  expect_refused(out, "--set repose.lift_speed=0", "repose.lift_speed");
}
