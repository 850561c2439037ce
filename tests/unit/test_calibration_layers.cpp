// The layers the calibration shares with other callers, each on a case worked by hand: a
// run's outputs as named features (run_features.hpp), the lab-test table (lab_tests.hpp),
// realisations batched with other points (replicates.hpp) and one table's unread keys
// (ConfigNode::reject_unread_keys, as the spec readers use it).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "calibration/lab_tests.hpp"
#include "calibration/replicates.hpp"
#include "calibration/run_features.hpp"
#include "config/config_error.hpp"
#include "config/config_reader.hpp"

using namespace colza;
using namespace colza::calibration;

namespace {

TEST(RunFeatures, EveryNumberOfTheOutputsAndOfEachLoadIsNamed) {
  const nlohmann::json outputs = {{"cohesion", 1200.0},
                                  {"tan_phi", 0.5},
                                  {"particles", 417},
                                  {"settling_converged", true},
                                  {"stop_reason", "stop_force"},
                                  {"loads",
                                   {{{"normal_stress", 25750.0}, {"shear_strength", 14000.0}, {"consolidated", true}},
                                    {{"normal_stress", 78750.0}, {"shear_strength", 40500.0}}}}};
  const Features f = output_features(outputs);
  EXPECT_EQ(f.at("cohesion"), 1200.0);
  EXPECT_EQ(f.at("tan_phi"), 0.5);
  EXPECT_EQ(f.at("particles"), 417.0);
  EXPECT_EQ(f.count("settling_converged"), 0u);  // true/false and text are not features
  EXPECT_EQ(f.count("stop_reason"), 0u);
  EXPECT_EQ(f.at(load_feature_name(25750.0, "shear_strength")), 14000.0);
  EXPECT_EQ(f.at("load-78750Pa/shear_strength"), 40500.0);
  EXPECT_EQ(f.at("load-78750Pa/normal_stress"), 78750.0);
  EXPECT_EQ(f.count("load-25750Pa/consolidated"), 0u);
  EXPECT_EQ(f.size(), 3u + 2u + 2u);
}

TEST(RunFeatures, LoadUnloadCyclesAndBranchesAreNumberedFromOne) {
  LoadUnloadAnalysis a;
  a.branches.resize(2);
  a.branches[0].moduli.push_back({50000.0, 2.0e6, 0.4, 0, 0, 5, 1});
  a.branches[1].moduli.push_back({50000.0, kNotAvailable, kNotAvailable, 0, 0, 2, 1});
  a.branches[1].lateral_ratio_end = 0.6;
  a.cycles.push_back({0, 1, 150.0, 0.02, 0.015, 0.005});
  const Features f = load_unload_features(a);
  EXPECT_EQ(f.at("cycle1/loop_area"), 150.0);
  EXPECT_EQ(f.at("cycle1/strain_at_turn"), 0.02);
  EXPECT_EQ(f.at("cycle1/permanent_strain"), 0.015);
  EXPECT_EQ(f.at("cycle1/rebound_strain"), 0.005);
  EXPECT_EQ(f.at("branch1/modulus@50000Pa"), 2.0e6);
  EXPECT_EQ(f.at("branch1/lateral_ratio@50000Pa"), 0.4);
  EXPECT_EQ(f.count("branch2/modulus@50000Pa"), 0u);  // not available: left out
  EXPECT_EQ(f.at("branch2/lateral_ratio_end"), 0.6);
  EXPECT_EQ(f.size(), 7u);
}

TEST(LabTests, EachStageHasItsScenarioAndMeasuredReader) {
  for (const Stage stage : {Stage::kDensity, Stage::kCompression, Stage::kShear, Stage::kLoadUnload, Stage::kRepose}) {
    const LabTest& t = lab_test(stage);
    EXPECT_EQ(t.name, to_string(stage));
    EXPECT_EQ(t.scenario, stage == Stage::kShear    ? Scenario::kShear
                          : stage == Stage::kRepose ? Scenario::kRepose
                                                    : Scenario::kOedometer);
    EXPECT_EQ(scenario_of(stage), t.scenario);
    EXPECT_NE(t.read_spec_measured, nullptr);
    EXPECT_FALSE(t.features.empty());
  }
  EXPECT_NE(lab_test("load_unload").read_curve_features, nullptr);
  EXPECT_NE(lab_test("shear_curve").read_curve_features, nullptr);
  EXPECT_THROW(lab_test("triaxial"), std::out_of_range);
}

TEST(LabTests, AFeatureNameMatchesItsFamilysPattern) {
  // "<...>" stands for one or more characters other than '/'.
  const LabTest& cycles = lab_test("load_unload");
  for (const char* name : {"cycle1/rebound_strain", "cycle12/loop_area", "branch2/modulus@20000Pa",
                           "branch1/lateral_ratio@1.5e+05Pa", "branch3/lateral_ratio_end", "bulk_density"})
    EXPECT_TRUE(names_a_feature_of(cycles, name)) << name;
  for (const char* name : {"cycle/rebound_strain", "cycle1/x/rebound_strain", "branch2/modulus@Pa", "rebound_strain",
                           "cycle1/rebound_strain2", "c1"})
    EXPECT_FALSE(names_a_feature_of(cycles, name)) << name;
  EXPECT_TRUE(names_a_feature_of(lab_test("shear_curve"), "load-25750Pa/peak_strength"));
  EXPECT_FALSE(names_a_feature_of(lab_test("repose"), "angle_of_repose"));
}

TEST(Replicates, PointsAndRealisationsComeBackInOrder) {
  const ForwardModel model = [](const Eigen::VectorXd& x) { return Eigen::VectorXd::Constant(1, 10.0 * x[0]); };
  const ReplicateModel other = [](const Eigen::VectorXd& x, int k) { return Eigen::VectorXd::Constant(1, x[0] + k); };
  const std::vector<Eigen::VectorXd> points = {Eigen::VectorXd::Constant(1, 1.0), Eigen::VectorXd::Constant(1, 2.0)};
  const BatchWithReplicates b = evaluate_with_replicates(model, other, points, points[1], 3, 2);
  ASSERT_EQ(b.points.size(), 2u);
  ASSERT_EQ(b.replicates.size(), 3u);
  EXPECT_EQ(b.points[0][0], 10.0);
  EXPECT_EQ(b.points[1][0], 20.0);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(b.replicates[static_cast<std::size_t>(k)][0], 2.0 + k + 1);
  // 20, 3, 4, 5: mean 8, squares about it 144 + 25 + 16 + 9 = 194, s = sqrt(194 / 3).
  const Eigen::VectorXd s = realisation_scatter({b.points[1], b.replicates[0], b.replicates[1], b.replicates[2]});
  EXPECT_NEAR(s[0], std::sqrt(194.0 / 3.0), 1e-12);
}

TEST(ConfigNodeUnreadKeys, ATableIsCheckedAloneAndASubTableCountsWhenOneOfItsKeysWasRead) {
  const ConfigReader reader =
      ConfigReader::from_string("[m]\na = 1\nb = 2\n[[m.c]]\nx = 1\n[n]\nradius = 1\n", "spec.toml");
  const ConfigNode m = reader.root().table("m");
  EXPECT_TRUE(m.exists());
  EXPECT_FALSE(reader.root().table("absent").exists());
  EXPECT_EQ(m.keys(), (std::vector<std::string>{"a", "b", "c"}));
  m.number("a", 0.0);
  for (const ConfigNode& c : m.table_array("c")) c.number("x", 0.0);
  try {
    m.reject_unread_keys("not read");
    FAIL() << "b was not read";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), "spec.toml");
    EXPECT_EQ(e.key(), "m.b");
    EXPECT_EQ(e.reason(), "not read");
  }
  m.get("b");
  EXPECT_NO_THROW(m.reject_unread_keys("not read"));  // [n] is another table
  EXPECT_EQ(reader.root().table("n").misspelt_hint("radus"), " (the table has 'radius': misspelt?)");
}

}  // namespace
