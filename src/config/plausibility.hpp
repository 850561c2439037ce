// Values a run accepts but an oilseed bulk in the oedometer or the shear box is unlikely to
// have. Most are a unit slip that would otherwise give a finished run with meaningless
// numbers: a friction angle in degrees for a coefficient, millimetres for metres, g/cm^3 for
// kg/m^3, kPa for Pa, mm/min for m/s, kN/m for N/m. Each warning names the key, its origin
// (file or --set), the value, the range expected and the likely slip. `colza run` prints them
// before the run starts and keeps them in summary.json's "warnings".
#pragma once
#include <string>
#include <vector>
#include "config/run_config.hpp"

namespace colza {

// Least normal stress of a lab direct shear test (Pa): a shear box load below it is taken
// for kPa (a warning for a run's load here; an error for a calibration's measured loads,
// calibration/spec_measured_shear.cpp). The paper's loads are 25.75..78.75 kPa.
inline constexpr double kLeastLabNormalStress = 100.0;

struct ImplausibleSetting {
  std::string origin;  // the config file, "--set KEY", or where the normal stresses came from
  std::string key;     // the config key; "" for a normal stress given as --normal-stress
  std::string reason;  // the value, the range expected, the likely slip
  // "ORIGIN: key 'KEY': REASON", as a ConfigError reads.
  std::string text() const { return origin + (key.empty() ? "" : ": key '" + key + "'") + ": " + reason; }
};

// `normal_stresses` (Pa): the shear box's loads this run applies (--normal-stress, or
// shear_box.normal_stresses for a series), with `stress_origin` naming where they came
// from; empty for the oedometer. Scene runs are physics checks with deliberate odd values:
// they get none.
std::vector<ImplausibleSetting> implausible_settings(const RunConfig& c, Scenario scenario,
                                                     const std::vector<double>& normal_stresses = {},
                                                     const std::string& stress_origin = "");

}  // namespace colza
