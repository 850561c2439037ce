// Features of a whole direct shear curve (physics.md section 8), from plain arrays so that a
// measured curve (calibration/measured_shear_curve.hpp) and a simulated one (a shear load's
// curve.csv rows) go through the same code. Rows in time order: shear displacement d (m,
// increasing), shear stress tau (Pa) and, optionally, the plate's height h (m; any offset:
// only its changes count, so a column of plate rise since the start serves as well).
//
//   * peak: the peak strength of analysis/shear_strength.hpp (the largest mean shear stress
//     over a trailing interval of width w, default 1 mm), the calibration's peak;
//   * residual: the mean shear stress over the strength window (the shear strength);
//     drop = peak - residual (Pa), and drop / peak;
//   * largest dilation: max_k (h_k - h_0) (m; negative when the sample only contracted), and
//     the displacement where it occurs;
//   * dilatancy angle at the peak: psi = atan(dh/dd), dh/dd the slope of the least-squares
//     line h(d) through the rows of the peak's interval [d_peak - w, d_peak] (the rows whose
//     mean is the peak strength), in degrees; positive when the sample dilates;
//   * initial shear stiffness: the secant k = (f tau_peak - tau_0) / (d_f - d_0) (Pa/m), d_f
//     the displacement where tau first reaches f tau_peak (interpolated between rows), f =
//     stiffness_fraction (default 0.5).
#pragma once
#include <vector>

#include "analysis/oedometer_cycles.hpp"  // kNotAvailable
#include "analysis/shear_strength.hpp"

namespace colza {

struct ShearCurveSettings {
  StrengthWindow window;             // m, the residual (stationary) window
  double peak_width = 0.001;         // m, w
  double stiffness_fraction = 0.5;   // f
};

struct ShearCurveFeatures {
  ShearPeak peak;                    // Pa, m (the interval's end), rows
  double residual = 0.0;             // Pa, the window mean (0 with no row in the window)
  std::size_t residual_samples = 0;
  double drop = kNotAvailable;       // Pa, peak - residual (NaN when either is missing)
  double drop_fraction = kNotAvailable;
  bool has_plate_height = false;
  double max_dilation = kNotAvailable;              // m
  double max_dilation_displacement = kNotAvailable; // m
  double dilatancy_angle_deg = kNotAvailable;       // deg at the peak; NaN: < 3 rows in the interval
  std::size_t dilatancy_points = 0;
  double initial_stiffness = kNotAvailable;         // Pa/m; NaN: never reached f tau_peak
  double stiffness_displacement = kNotAvailable;    // m, d_f
};

// Throws std::invalid_argument when the arrays differ in length (plate_height may be empty).
ShearCurveFeatures shear_curve_features(const std::vector<double>& displacement, const std::vector<double>& shear_stress,
                                        const std::vector<double>& plate_height, const ShearCurveSettings& settings);

}  // namespace colza
