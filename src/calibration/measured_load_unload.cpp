#include "calibration/measured_load_unload.hpp"

#include <algorithm>

#include "calibration/measured_csv.hpp"
#include "config/config_error.hpp"
#include "io/format_number.hpp"

namespace colza::calibration {

MeasuredLoadUnload read_measured_load_unload(const std::string& csv, const std::string& spec_file,
                                             const std::string& key) {
  const auto cols = read_csv_columns_with_optional(csv, {kPistonDisplacementColumn, kPistonForceColumn},
                                                   {kRadialForceColumn}, spec_file, key);
  if (cols[0].size() < 2) throw ConfigError(spec_file, key, csv + ": a load-unload curve needs at least 2 rows");
  MeasuredLoadUnload m;
  m.file = csv;
  m.travel = cols[0];
  m.force = cols[1];
  m.radial = cols[2];  // empty without the column
  return m;
}

LoadUnloadAnalysis measured_load_unload_features(const MeasuredLoadUnload& m, const OedometerGeometry& g,
                                                 const CycleAnalysisSettings& settings, const std::string& spec_file,
                                                 const std::string& key) {
  const double deepest = *std::max_element(m.travel.begin(), m.travel.end());
  if (deepest >= g.height)
    throw ConfigError(spec_file, key, m.file + ": a piston_displacement of " + format_shortest(deepest) +
                                          " m reaches the sample's height, " + format_shortest(g.height) +
                                          " m (displacements are in metres)");
  LoadUnloadAnalysis a = analyse_load_unload(m.travel, m.force, m.radial, g, settings);
  if (std::none_of(a.branches.begin(), a.branches.end(), [](const CurveBranch& b) { return b.loading; }))
    throw ConfigError(spec_file, key, m.file + ": the curve has no loading branch (piston_displacement never grows)");
  return a;
}

}  // namespace colza::calibration
