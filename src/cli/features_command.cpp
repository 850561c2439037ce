#include "cli/features_command.hpp"

#include <algorithm>
#include <cstdio>

#include "calibration/measured_load_unload.hpp"
#include "calibration/measured_shear_features.hpp"
#include "config/config_error.hpp"
#include "core/types.hpp"
#include "io/lab_features_json.hpp"

namespace colza {

namespace {

nlohmann::json load_unload(const FeaturesOptions& o) {
  using namespace calibration;
  if (!(o.cylinder_diameter > 0.0)) throw ConfigError("--cylinder-diameter", "", "is required (m, > 0)");
  if (!(o.height > 0.0)) throw ConfigError("--height", "", "is required (m, > 0: the sample's height at zero travel)");
  const MeasuredLoadUnload m = read_measured_load_unload(o.csv, "--csv", "");
  CycleAnalysisSettings s;
  s.modulus_stresses = o.modulus_stresses;
  const double area = kPi * 0.25 * o.cylinder_diameter * o.cylinder_diameter;
  if (s.modulus_stresses.empty()) s.modulus_stresses = {0.5 * *std::max_element(m.force.begin(), m.force.end()) / area};
  if (!(s.modulus_stresses.front() > 0.0)) throw ConfigError("--modulus-stresses", "", "every stress must be > 0 Pa");
  s.modulus_window = o.modulus_window;
  s.reversal_tolerance = o.reversal_tolerance;
  const LoadUnloadAnalysis a =
      measured_load_unload_features(m, {area, o.height, o.cylinder_diameter}, s, "--csv", "");
  nlohmann::json j = load_unload_json(a, s);
  j["file"] = o.csv;
  j["packing_height"] = o.height;
  j["cylinder_diameter"] = o.cylinder_diameter;
  return {{"load_unload", j}};
}

nlohmann::json shear(const FeaturesOptions& o) {
  if (!(o.window_start < o.window_end)) throw ConfigError("--window-start", "", "must be below --window-end (m)");
  ShearCurveSettings s;
  s.window = {o.window_start, o.window_end};
  s.peak_width = o.peak_width;
  s.stiffness_fraction = o.stiffness_fraction;
  const calibration::MeasuredShearFeatures m =
      calibration::read_measured_shear_features(o.csv, s, "--csv", "", o.box_length);
  nlohmann::json j = shear_features_json(m.features, s);
  j["file"] = o.csv;
  j["rows"] = m.rows;
  j["plate_column"] = m.plate_column;
  return {{"curve_features", j}};
}

}  // namespace

int features_command(const FeaturesOptions& o) {
  try {
    const nlohmann::json j = o.test == "load-unload" ? load_unload(o) : shear(o);
    std::printf("%s\n", j.dump(2).c_str());
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "colza: error: %s\n", e.what());
    return 2;
  }
  return 0;
}

}  // namespace colza
