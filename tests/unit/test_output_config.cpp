// The [output] table (config/run_config.hpp, OutputSpec): validated like every key, defaults
// per scenario, and kept out of the resolved config when absent (a run's fingerprint is its
// physics'); the walls' quads for pictures (walls/wall_mesh.hpp); the snapshot cadence
// (scenario/snapshot_recorder.hpp).
#include <gtest/gtest.h>

#include <string>

#include "config/plausibility.hpp"
#include "config/run_config.hpp"
#include "contact/slot_registry.hpp"
#include "scenario/snapshot_recorder.hpp"
#include "walls/wall_mesh.hpp"

using namespace colza;

namespace {

ConfigError output_error(const std::string& toml) {
  try {
    read_run_config(Scenario::kOedometer, ConfigReader::from_string(toml, "test.toml"));
  } catch (const ConfigError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a ConfigError for: " << toml;
  return ConfigError("", "", "");
}

RunConfig oedometer(const std::string& toml) {
  return read_run_config(Scenario::kOedometer, ConfigReader::from_string(toml, "test.toml"));
}

}  // namespace

TEST(OutputConfig, BadValuesAreNamedWithFileKeyAndReason) {
  const ConfigError negative = output_error("[output]\nsnapshot_interval = -0.1\n");
  EXPECT_EQ(negative.file(), "test.toml");
  EXPECT_EQ(negative.key(), "output.snapshot_interval");
  EXPECT_NE(negative.reason().find("negative"), std::string::npos) << negative.reason();
  EXPECT_EQ(output_error("[output]\nsnapshot_interval = \"often\"\n").key(), "output.snapshot_interval");
  EXPECT_EQ(output_error("[output]\nplots = 1\n").key(), "output.plots");
  EXPECT_EQ(output_error("[output]\nsnapshot_intervall = 0.1\n").key(), "output.snapshot_intervall");
  EXPECT_EQ(output_error("output = 3\n").key(), "output");
}

TEST(OutputConfig, DefaultsPerScenarioAndGivenValues) {
  EXPECT_EQ(oedometer("").output.snapshot_interval, default_snapshot_interval(Scenario::kOedometer));
  EXPECT_GT(default_snapshot_interval(Scenario::kOedometer), 0.0);
  EXPECT_GT(default_snapshot_interval(Scenario::kShear), 0.0);
  EXPECT_EQ(default_snapshot_interval(Scenario::kScene), 0.0);
  EXPECT_TRUE(oedometer("").output.plots);
  const RunConfig c = oedometer("[output]\nsnapshot_interval = 0.0\nplots = false\n");
  EXPECT_EQ(c.output.snapshot_interval, 0.0);
  EXPECT_FALSE(c.output.plots);
}

TEST(OutputConfig, AnAbsentTableLeavesTheResolvedConfigAsBefore) {
  // Run reuse (calibration/run_cache.cpp) fingerprints the resolved config: output settings
  // left out must not enter it, given ones are recorded like every key.
  EXPECT_EQ(oedometer("").resolved_toml.find("output"), std::string::npos);
  EXPECT_NE(oedometer("[output]\nsnapshot_interval = 0.2\n").resolved_toml.find("snapshot_interval"),
            std::string::npos);
}

TEST(OutputConfig, ASnapshotEveryFewStepsIsWarnedOf) {
  const auto warned = [](const std::string& toml) {
    for (const ImplausibleSetting& s : implausible_settings(oedometer(toml), Scenario::kOedometer))
      if (s.key == "output.snapshot_interval") return true;
    return false;
  };
  EXPECT_TRUE(warned("[output]\nsnapshot_interval = 1e-5\n"));  // 10 us: a snapshot every other step
  EXPECT_FALSE(warned("[output]\nsnapshot_interval = 0.05\n"));
  EXPECT_FALSE(warned("[output]\nsnapshot_interval = 0.0\n"));  // none
}

TEST(WallMesh, ShapesBecomeQuadsCoveringTheParticles) {
  const Vec3 lo(-0.05, -0.05, 0.0), hi(0.05, 0.05, 0.08);
  const WallMesh rect = wall_mesh(Wall::rectangle("r", Vec3(1, 2, 3), Vec3::UnitZ(), Vec3::UnitX(), 0.1, 0.2), lo, hi, 0.0);
  ASSERT_EQ(rect.quads.size(), 1u);
  EXPECT_NEAR((rect.points[2] - rect.points[0]).norm(), 2.0 * std::hypot(0.1, 0.2), 1e-12);  // the diagonal
  // An infinite cylinder is clamped to the particles' extent along its axis (+ pad).
  const WallMesh cyl = wall_mesh(Wall::cylinder("c", Vec3::Zero(), Vec3::UnitZ(), 0.05, -1e300, 1e300), lo, hi, 0.01);
  EXPECT_EQ(cyl.quads.size(), static_cast<std::size_t>(kCylinderSegments));
  for (const Vec3& x : cyl.points) {
    EXPECT_NEAR(std::hypot(x.x(), x.y()), 0.05, 1e-12);
    EXPECT_LT(std::abs(x.z() - 0.04), 0.5 * (hi - lo).norm() + 0.01 + 1e-12);
  }
  // A plane's patch lies in the plane and reaches beyond the box's shadow on it.
  const WallMesh plane = wall_mesh(Wall::plane("p", Vec3(0, 0, 0.01), Vec3::UnitZ()), lo, hi, 0.0);
  ASSERT_EQ(plane.points.size(), 4u);
  for (const Vec3& x : plane.points) {
    EXPECT_NEAR(x.z(), 0.01, 1e-15);
    EXPECT_GE(std::max(std::abs(x.x()), std::abs(x.y())), 0.05);
  }
}

TEST(SnapshotRecorder, OneAtTheStartOneAtEachMultipleAndOneAtTheEnd) {
  World w;
  w.particles.add(Vec3::Zero(), 0.003, 1250.0);
  w.particles.clear_forces();
  w.walls.push_back(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  SnapshotRecorder r(0.1, 0.0);
  for (int k = 1; k <= 25; ++k) {  // steps of 0.01 s to 0.25 s
    w.time = 0.01 * k;
    w.step = static_cast<std::uint64_t>(k);
    r.observe(w);
  }
  r.record(w);  // the end
  r.record(w);  // once only at the same step
  const SnapshotSeries s = r.take();
  ASSERT_EQ(s.snapshots.size(), 4u);  // t = 0.01 (the first step), ~0.1, ~0.2, 0.25
  EXPECT_EQ(s.snapshots[0].step, 1u);
  EXPECT_GE(s.snapshots[1].time, 0.1 - 1e-12);
  EXPECT_EQ(s.snapshots.back().step, 25u);
  EXPECT_EQ(s.wall_names, std::vector<std::string>{"floor"});
  EXPECT_EQ(s.snapshots[0].particles(), 1u);
  EXPECT_EQ(s.snapshots[0].quads(), 1u);
  EXPECT_EQ(SnapshotRecorder(0.0, 0.0).enabled(), false);
}

TEST(ContactSummary, EachSlotNamesItsLawAndTheParametersItRunsWith) {
  const RunConfig c = oedometer(
      "[contact]\nrolling = \"elastic_plastic\"\nbond = \"load_induced\"\n"
      "[contact.elastic_plastic]\nfriction = 0.18\n"
      "[contact.load_induced]\nnormal_strength_ratio = 0.45\nshear_strength_ratio = 2.5\n");
  const nlohmann::json j = contact_summary(c.contact);
  EXPECT_EQ(j["normal"], (nlohmann::json{{"law", "linear"}}));
  EXPECT_EQ(j["damping"], (nlohmann::json{{"law", "none"}}));
  EXPECT_EQ(j["rolling"], (nlohmann::json{{"law", "elastic_plastic"}, {"friction", 0.18}, {"stiffness_factor", 1.0},
                                          {"form", "yade"}, {"at_walls", false}, {"damping_ratio", 0.0}}));
  // The rolling dashpot's ratio: above 0.5 the rocking it damps outruns the time step's margin.
  const std::string rolling = "[contact]\nrolling = \"elastic_plastic\"\n[contact.elastic_plastic]\n";
  EXPECT_EQ(contact_summary(oedometer(rolling + "damping_ratio = 0.3\n").contact)["rolling"]["damping_ratio"], 0.3);
  EXPECT_EQ(output_error(rolling + "damping_ratio = 0.7\n").key(), "contact.elastic_plastic.damping_ratio");
  EXPECT_EQ(j["bond"]["law"], "load_induced");
  EXPECT_EQ(j["bond"]["normal_strength_ratio"], 0.45);
  EXPECT_EQ(j["bond"]["shear_strength_ratio"], 2.5);
  EXPECT_EQ(j["bond"]["normal_strength_cap"], "none");  // no cap: infinite, which JSON cannot hold
  EXPECT_EQ(j["bond_install"], "never");                // a load-induced bond forms under load
}
