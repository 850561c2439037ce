// The lab tests colza reproduces, one row each: the scenario that runs it, the features a
// run of it yields (run_features.hpp names; "<load>/" and "cycle<k>/", "branch<b>/" stand
// for the per-load, per-cycle and per-branch families) and the reader of its measured data:
// a calibration stage's [measured] table (spec_measured.hpp), or a measured curve file
// whose features come under the run features' names.
#pragma once
#include <string>
#include <vector>

#include "calibration/run_features.hpp"
#include "calibration/spec.hpp"
#include "config/config_reader.hpp"
#include "config/run_config.hpp"

namespace colza::calibration {

// What reading a measured curve needs beside the file: the model it is compared with (the
// cylinder, the shear box and its windows) and where the file was named, for errors.
struct MeasuredCurveContext {
  const RunConfig* model = nullptr;
  double sample_height = 0.0;  // m, load-unload: the sample's height at zero travel
  std::string spec_file, key;
};

// A stage's [measured] table -> s.problem.targets and what they came from.
using SpecMeasuredReader = void (*)(const ConfigNode& measured, Spec& s);
// A measured curve file -> its features.
using CurveFeatureReader = Features (*)(const std::string& csv, const MeasuredCurveContext& context);

struct LabTest {
  std::string name;  // "density", "compression", "shear", "load_unload", "shear_curve", "repose"
  Scenario scenario;                // the scenario a run of it is
  std::vector<std::string> features;
  SpecMeasuredReader read_spec_measured = nullptr;   // calibration stages
  CurveFeatureReader read_curve_features = nullptr;  // measured curves
  // (repose: a heap profile; a measured angle alone is one number, given as a value)
};

const std::vector<LabTest>& lab_tests();
// The row of `name`, or of a calibration stage; std::out_of_range when there is none.
const LabTest& lab_test(const std::string& name);
const LabTest& lab_test(Stage stage);
// The scenario a calibration stage's runs are.
Scenario scenario_of(Stage stage);

// The features of a test's measured curve `csv` in `model`'s geometry: a heap profile for a
// repose test, a load-unload curve for an oedometer test, which needs `n`'s `sample_height`
// (m, the sample's height at zero piston travel). A shear test's curves are per load
// (`[[tests.curves]]`), so a single curve on one is refused. `n` names the `curve` key in errors.
Features measured_test_curve_features(Scenario scenario, const std::string& csv, const ConfigNode& n,
                                      const RunConfig& model, const std::string& spec_file);

// Whether `name` is one of the test's features ("<...>" in a pattern stands for a load
// label, a cycle or branch number, a stress: one or more characters other than '/').
bool names_a_feature_of(const LabTest& test, const std::string& name);
// Its feature patterns, ", "-separated, for a message.
std::string lab_test_feature_list(const LabTest& test);

}  // namespace colza::calibration
