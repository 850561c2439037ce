// A measured direct shear curve as calibration input (format: data/measured/README.md).
// CSV, '#' comment lines allowed, one header line, then one row per sample:
//
//   shear_displacement   m    relative displacement of the box halves, strictly increasing
//   shear_stress         Pa   shear force / nominal area of the box
//
// Other columns are ignored, so colza's own load-<sigma>Pa/curve.csv is a valid curve. The
// shear strength is derived exactly as for the simulation (analysis/shear_strength.hpp): the
// mean shear stress of the rows inside the strength window [start, end] (m).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "analysis/shear_strength.hpp"

namespace colza::calibration {

inline constexpr const char* kShearDisplacementColumn = "shear_displacement";
inline constexpr const char* kShearStressColumn = "shear_stress";

struct MeasuredShearCurve {
  std::string file;
  double normal_stress = 0.0;      // Pa, as the spec states it
  StrengthWindow window;           // m
  std::size_t rows = 0;
  double max_displacement = 0.0;   // m, the curve's last displacement
  std::size_t window_points = 0;   // rows inside the window
  double shear_strength = 0.0;     // Pa, mean shear stress over the window
};

// Reads and checks one curve. Errors (ConfigError naming spec_file, key and the CSV's path):
// missing file, missing column, a cell that is not a number, displacement not strictly
// increasing, a curve that ends before the window does, fewer than 2 rows in the window.
// Uneven displacement steps inside the window add a warning.
MeasuredShearCurve read_measured_shear_curve(const std::string& csv, double normal_stress, StrengthWindow window,
                                             const std::string& spec_file, const std::string& key,
                                             std::vector<std::string>& warnings);

}  // namespace colza::calibration
