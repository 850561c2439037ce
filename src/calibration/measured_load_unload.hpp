// A measured oedometer load-unload curve (format: data/measured/README.md). CSV, '#' comment
// lines allowed, one header line, then one row per sample, in time order:
//
//   piston_displacement   m   the piston's travel from where it met the sample's top (down +)
//   piston_force          N   compression positive
//   radial_force          N   optional: the sum of the normal forces on the cylinder's wall
//
// Other columns are ignored, so colza's own curve.csv of a load-unload run is a valid curve.
// Its features come from analysis/oedometer_cycles.hpp, the code that reduces colza's runs.
#pragma once
#include <string>
#include <vector>

#include "analysis/oedometer_cycles.hpp"

namespace colza::calibration {

inline constexpr const char* kPistonDisplacementColumn = "piston_displacement";
inline constexpr const char* kPistonForceColumn = "piston_force";
inline constexpr const char* kRadialForceColumn = "radial_force";

struct MeasuredLoadUnload {
  std::string file;
  std::vector<double> travel, force, radial;  // m, N, N (radial empty: the file has none)
};

// Reads one curve. Errors (ConfigError naming spec_file, key and the CSV's path): missing file
// or column, a cell that is not a number, fewer than 2 rows.
MeasuredLoadUnload read_measured_load_unload(const std::string& csv, const std::string& spec_file,
                                             const std::string& key);

// Its features for a sample of the given geometry. A travel at or beyond the sample's height
// (a curve in mm?) or a curve without a loading branch is a ConfigError naming the file.
LoadUnloadAnalysis measured_load_unload_features(const MeasuredLoadUnload& curve, const OedometerGeometry& geometry,
                                                 const CycleAnalysisSettings& settings, const std::string& spec_file,
                                                 const std::string& key);

}  // namespace colza::calibration
