// summary.json's sections for the features of physics.md section 8: a load-unload curve's
// branches and cycles, a shear curve's whole-curve features, a test's inertial number. One
// form for a simulated run and a measured file (NaN, a feature the curve does not give, is
// written as null).
#pragma once
#include <nlohmann/json.hpp>

#include "analysis/oedometer_cycles.hpp"
#include "analysis/shear_curve_features.hpp"

namespace colza {

// {"branches": [{kind, first_row, last_row, stress_start, stress_end, stress_extreme,
//   strain_start, strain_end, work, lateral_ratio_end, moduli: [{stress, modulus,
//   lateral_ratio, points, passages, stress_range}]}], "cycles": [{loading_branch, unloading_branch,
//   loop_area, strain_at_turn, permanent_strain, rebound_strain}], "radial_force": bool,
//   "modulus_window", "reversal_tolerance"}
nlohmann::json load_unload_json(const LoadUnloadAnalysis& a, const CycleAnalysisSettings& settings);

// {peak_strength, peak_displacement, peak_width, residual_strength, strength_window, drop,
//  drop_fraction, max_dilation, max_dilation_displacement, dilatancy_angle_deg,
//  dilatancy_points, initial_stiffness, stiffness_fraction, stiffness_displacement}
nlohmann::json shear_features_json(const ShearCurveFeatures& f, const ShearCurveSettings& settings);

struct InertialNumberInputs {
  double strain_rate = 0.0;        // 1/s
  double mean_diameter = 0.0;      // m
  double particle_density = 0.0;   // kg/m^3
  double pressure = 0.0;           // Pa
  const char* strain_rate_is = ""; // how gamma_dot was made, for the reader
  const char* pressure_is = "";    // which stress p is
};
// {value, strain_rate, strain_rate_is, mean_diameter, particle_density, pressure, pressure_is,
//  quasi_static_limit}; value null when the pressure is not positive.
nlohmann::json inertial_number_json(const InertialNumberInputs& in, double& value);

}  // namespace colza
