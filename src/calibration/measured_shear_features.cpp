#include "calibration/measured_shear_features.hpp"

#include <algorithm>

#include "calibration/measured_csv.hpp"
#include "calibration/measured_shear_curve.hpp"
#include "config/config_error.hpp"
#include "io/format_number.hpp"

namespace colza::calibration {

MeasuredShearFeatures read_measured_shear_features(const std::string& csv, const ShearCurveSettings& settings,
                                                   const std::string& spec_file, const std::string& key,
                                                   double box_length) {
  const std::vector<std::string> header = read_csv_header(csv, spec_file, key);
  const auto has = [&](const char* c) { return std::find(header.begin(), header.end(), c) != header.end(); };
  MeasuredShearFeatures m;
  m.file = csv;
  m.plate_column = has("plate_height") ? "plate_height" : has("dilatancy") ? "dilatancy" : "";
  std::vector<std::string> columns{kShearDisplacementColumn, kShearStressColumn};
  if (*m.plate_column) columns.push_back(m.plate_column);
  std::vector<std::size_t> lines;
  const auto cols = read_csv_columns(csv, columns, spec_file, key, lines);
  m.rows = cols[0].size();
  if (m.rows < 2) throw ConfigError(spec_file, key, csv + ": a shear curve needs at least 2 rows");
  require_increasing(cols[0], lines, kShearDisplacementColumn, csv, spec_file, key);
  if (cols[0].back() > box_length)
    throw ConfigError(spec_file, key, csv + ": a shear_displacement of " + format_shortest(cols[0].back()) +
                                          " m is beyond the box's length, " + format_shortest(box_length) +
                                          " m (displacements are in metres)");
  m.features = shear_curve_features(cols[0], cols[1], *m.plate_column ? cols[2] : std::vector<double>{}, settings);
  return m;
}

}  // namespace colza::calibration
