// The calibration spec (a TOML file, see data/calibration/*.toml): which stage, the DEM
// configuration the runs start from, the parameters and their design, the measured data
// (files in plain formats) and the targets' uncertainties. Every problem is reported as a
// ConfigError naming the file, the key and the reason (CLI exit code 2).
// read_spec reads the top level and hands each table to its reader: [model] to
// spec_model.hpp, [[parameters]], [fit], [sequential] and [scatter] to spec_design.hpp,
// [measured] to the stage's reader in the lab-test table (lab_tests.hpp, spec_measured.hpp);
// the fields are read through a ConfigNode in the spec's words (spec_fields.hpp).
#pragma once
#include <map>
#include <set>
#include <string>
#include <vector>

#include "calibration/calibrate.hpp"
#include "calibration/measured_shear_curve.hpp"
#include "config/run_config.hpp"

namespace colza::calibration {

enum class Stage { kDensity, kCompression, kShear, kLoadUnload, kRepose };
const char* to_string(Stage s);

struct Spec {
  std::string file;                 // the spec's path
  Stage stage = Stage::kDensity;
  std::string title;
  std::string model_config;         // DEM config path (resolved against the spec's folder)
  std::vector<std::string> model_set;  // overrides applied to every run ("key=value")
  bool shared_packing = false;      // density/compression: settle once at the design centre, load every run from it
  RunConfig base;                   // the model config as read (overrides applied), for validation and fit ranges
  // The packing file every run loads (the config's oedometer.packing_file or
  // shear_box.packing_file, not a shared packing): then the seed changes nothing, and another
  // seed is the same run, not another realisation. Empty when the seed makes the sample.
  std::string fixed_packing_file;
  bool correlation_given = false;   // [measured] correlation set (else shear: derived from the measured
                                    // loads; compression: independent)
  Problem problem;                  // parameters, targets, design, sequential settings
  std::vector<double> loads;        // shear: normal stresses of each design run's series (Pa)
  // What the targets were derived from, for the report.
  std::string measured_file;        // compression, load_unload, repose: the curve; shear: the results CSV (empty when curves are given)
  std::vector<std::pair<double, double>> measured_points;  // shear: (sigma, tau) in Pa; compression: empty
  std::vector<MeasuredShearCurve> measured_curves;         // shear: the curves the strengths came from, if any
  StrengthDefinition strength;      // shear: which strength the targets are made of (measured.strength)
  double measured_fit_r2 = 0.0;     // compression: R^2 of the measured curve's quadratic; shear: of the line
  double measured_c0 = 0.0;         // compression: c0 of the measured curve (N), not a target
  // load_unload, repose: every feature the measured curve gives (run_features.hpp names, SI),
  // and the targets read off it rather than stated.
  std::map<std::string, double> measured_curve_features;
  std::set<std::string> targets_from_curve;
  std::vector<std::string> warnings;
};

// Reads and checks everything (files exist, curves reach their range, enough design points).
Spec read_spec(const std::string& path);

}  // namespace colza::calibration
