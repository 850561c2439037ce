// Settings a run accepts but seeds are unlikely to have (config/plausibility.hpp): the paper's
// own configurations give no warning; each unit slip gives one, naming the key and the slip.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "config/plausibility.hpp"

namespace colza {
namespace {

bool any_contains(const std::vector<std::string>& warnings, const std::string& text) {
  for (const auto& w : warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

const std::string kShearConfig = std::string(COLZA_SOURCE_DIR) + "/data/shear.toml";
const std::string kOedometerConfig = std::string(COLZA_SOURCE_DIR) + "/data/oedometer.toml";

TEST(Plausibility, ThePapersConfigurationsGiveNone) {
  const RunConfig oedometer = load_run_config(Scenario::kOedometer, kOedometerConfig, {});
  EXPECT_TRUE(implausible_settings(oedometer, Scenario::kOedometer).empty());
  const RunConfig builtin = load_run_config(Scenario::kOedometer, "", {});
  EXPECT_TRUE(implausible_settings(builtin, Scenario::kOedometer).empty());
  const RunConfig shear = load_run_config(Scenario::kShear, kShearConfig, {});
  EXPECT_TRUE(implausible_settings(shear, Scenario::kShear, shear.shear_box.normal_stresses, "x").empty());
}

TEST(Plausibility, AFrictionAngleInDegreesIsNamed) {
  const RunConfig c = load_run_config(Scenario::kOedometer, kOedometerConfig, {"particle.friction=20"});
  const auto w = implausible_settings(c, Scenario::kOedometer);
  ASSERT_EQ(w.size(), 1u);
  // atan(20) = 87.14 deg; tan(20 deg) = 0.36397.
  EXPECT_NE(w[0].find("--set particle.friction: key 'particle.friction': 20 "), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("87.1 deg"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("20 deg is mu = 0.364"), std::string::npos) << w[0];
}

TEST(Plausibility, UnitSlipsOfLengthDensityGravityAndSpeedAreNamed) {
  RunConfig c = load_run_config(Scenario::kOedometer, kOedometerConfig, {});
  c.particle.diameter_min = 6.0;  // mm for m (the container checks catch most such slips first)
  c.particle.diameter_max = 7.0;
  c.particle.density = 1.25;      // g/cm^3 for kg/m^3
  c.integration.gravity = Vec3(0.0, 0.0, 9.81);
  c.oedometer.piston_speed = 500.0;  // mm/min for m/s
  const auto w = implausible_settings(c, Scenario::kOedometer);
  EXPECT_TRUE(any_contains(w, "key 'particle.diameter_min': 6 m"));
  EXPECT_TRUE(any_contains(w, "key 'particle.diameter_max': 7 m"));
  EXPECT_TRUE(any_contains(w, "key 'particle.density': 1.25 kg/m^3"));
  EXPECT_TRUE(any_contains(w, "key 'integration.gravity': [0, 0, 9.81]"));
  EXPECT_TRUE(any_contains(w, "key 'oedometer.piston_speed': 500 m/s"));
}

// The mean contact's overlap share at the oedometer's stop force, 0.87 sigma d / Kn with
// sigma = 30 kN / (pi 0.05^2 m^2) = 3.8197 MPa, d = 6.5 mm, Kn = 437e3 / 2 = 218.5 kN/m (series
// rule): pi / 3.6 * 3.8197e6 * 0.0065 / 218.5e3 = 0.0992, below the 0.25 limit; with the
// stiffness given in kN/m (437), Kn = 218.5 N/m and the share is 99.2, i.e. 9916 %.
TEST(Plausibility, ASpringInKilonewtonsPerMetreIsNamed) {
  const RunConfig c = load_run_config(Scenario::kOedometer, kOedometerConfig, {"particle.normal_stiffness=437"});
  const auto w = implausible_settings(c, Scenario::kOedometer);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("key 'particle.normal_stiffness': 437 N/m"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("3.82 MPa"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("~9916 %"), std::string::npos) << w[0];
}

TEST(Plausibility, ANormalStressInKilopascalsNamesWhereItCameFrom) {
  const RunConfig c = load_run_config(Scenario::kShear, kShearConfig, {});
  const auto flag = implausible_settings(c, Scenario::kShear, {25.75}, "--normal-stress");
  ASSERT_EQ(flag.size(), 1u);
  EXPECT_EQ(flag[0].rfind("--normal-stress: normal stress 25.75 Pa is outside", 0), 0u) << flag[0];
  EXPECT_TRUE(implausible_settings(c, Scenario::kShear, {25750.0}, "--normal-stress").empty());
}

TEST(Plausibility, SceneRunsAreNotJudged) {
  RunConfig c;
  c.particle.friction = 20.0;
  c.integration.gravity = Vec3::Zero();
  EXPECT_TRUE(implausible_settings(c, Scenario::kScene).empty());
}

}  // namespace
}  // namespace colza
