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

// Which strength a calibration reads from a curve (spec: measured.strength): the mean over
// the stationary window (the paper's, physics.md section 4) or the peak, the largest mean
// over a trailing interval of peak_width (analysis/shear_strength.hpp). The same definition
// is applied to the measured curves and to the simulation's.
struct StrengthDefinition {
  bool peak = false;
  StrengthWindow window;      // m, window mode
  double peak_width = 0.001;  // m, peak mode
  std::string describe() const;  // one line for reports
};

struct MeasuredShearCurve {
  std::string file;
  double normal_stress = 0.0;      // Pa, as the spec states it
  std::size_t rows = 0;
  double max_displacement = 0.0;   // m, the curve's last displacement
  std::size_t window_points = 0;   // rows inside the window (peak mode: inside the peak's interval)
  double peak_displacement = 0.0;  // m, peak mode: where the peak's interval ends
  double shear_strength = 0.0;     // Pa, by `strength`
};

// The strength of a curve given as columns (m, Pa) by the definition; `samples` = rows used
// (0: the curve is too short for the definition).
double curve_strength(const std::vector<double>& displacement, const std::vector<double>& shear_stress,
                      const StrengthDefinition& definition, std::size_t& samples, double& peak_displacement);

// Reads and checks one curve. Errors (ConfigError naming spec_file, key and the CSV's path):
// missing file, missing column, a cell that is not a number, displacement not strictly
// increasing, a displacement beyond the box's length `box_length` (m: a curve in mm),
// a curve that ends before the window does, fewer than 2 rows in the window.
// Uneven displacement steps inside the window add a warning.
// Peak mode: a curve shorter than the peak width, or fewer than 2 rows in the peak's
// interval, is an error; a peak in the curve's last peak width adds a warning.
MeasuredShearCurve read_measured_shear_curve(const std::string& csv, double normal_stress,
                                             const StrengthDefinition& strength, const std::string& spec_file,
                                             const std::string& key, std::vector<std::string>& warnings,
                                             double box_length);

}  // namespace colza::calibration
