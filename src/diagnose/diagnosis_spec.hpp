// The diagnosis spec (TOML; format and an example in data/diagnosis/README.md): the
// baseline model (one config per lab test, the calibrated parameters with their ranges),
// the measured features of each test with their uncertainties, the candidate mechanisms
// (default: candidate_catalogue.hpp) and the settings of the statistics. Every problem is a
// ConfigError naming the spec, the key and the reason (exit code 2), found before any run.
#pragma once
#include <string>
#include <vector>

#include "config/run_config.hpp"
#include "diagnose/candidate_catalogue.hpp"
#include "diagnose/diagnosis.hpp"

namespace colza::diagnose {

struct DiagnosisTest {
  std::string name;                // its features' prefix ("<name>:<feature>") and the unit held out
  Scenario scenario = Scenario::kOedometer;  // oedometer (single loading or oedometer.cycles), shear (a series) or repose
  std::string config;              // the model config, resolved against the spec's folder
  std::vector<std::string> set;    // overrides of this test ("key=value")
  std::vector<Feature> features;   // name = the run feature's name (calibration/run_features.hpp)
};

struct DiagnosisSpec {
  std::string file, title;
  std::vector<DiagnosisTest> tests;
  std::vector<calibration::Parameter> parameters;
  std::vector<CatalogueEntry> candidates;
  DiagnosisSettings settings;
  // The problem the statistics see: every test's features in order, named "<test>:<feature>".
  DiagnosisProblem problem() const;
};

DiagnosisSpec read_diagnosis_spec(const std::string& path);

}  // namespace colza::diagnose
