// A measured direct shear curve with its dilatancy, for the whole-curve features
// (analysis/shear_curve_features.hpp; format: data/measured/README.md). CSV as a measured
// shear curve (calibration/measured_shear_curve.hpp: shear_displacement in m, strictly
// increasing; shear_stress in Pa) and optionally the plate's vertical position:
//
//   plate_height   m   the top plate's height (any datum), or
//   dilatancy      m   its rise since shearing started (used when plate_height is absent)
//
// colza's own load-<sigma>Pa/curve.csv has both. The features come from the code that reduces
// colza's runs.
#pragma once
#include <string>

#include "analysis/shear_curve_features.hpp"

namespace colza::calibration {

struct MeasuredShearFeatures {
  std::string file;
  std::size_t rows = 0;
  const char* plate_column = "";  // "plate_height", "dilatancy" or "" (none)
  ShearCurveFeatures features;
};

// Errors (ConfigError naming spec_file, key and the CSV): missing file or column, a cell that is
// not a number, fewer than 2 rows, displacement not strictly increasing, a displacement beyond
// `box_length` (m: a curve in mm?).
MeasuredShearFeatures read_measured_shear_features(const std::string& csv, const ShearCurveSettings& settings,
                                                   const std::string& spec_file, const std::string& key,
                                                   double box_length);

}  // namespace colza::calibration
