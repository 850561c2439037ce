// What each lab test's inertial number is made of (analysis/inertial_number.hpp; docs/running.md,
// "Inertial number"): the strain rate, grain size, particle density and confining stress
// of an oedometer, a shear load and an angle-of-repose lift, from the config and the run.
#pragma once
#include "config/run_config.hpp"
#include "io/lab_features_json.hpp"

namespace colza {

// Oedometer: gamma_dot = piston_speed / packing_height (1/s), p the largest piston stress,
// max_force / cylinder area (Pa).
InertialNumberInputs oedometer_inertial_inputs(const RunConfig& c, double packing_height, double max_force);

// Shear load: gamma_dot = shear_speed / min(10 mean diameters, shear_box.height), p the normal
// stress (Pa).
InertialNumberInputs shear_inertial_inputs(const RunConfig& c, double normal_stress);

// Repose lift: gamma_dot = lift_speed / column_height, p the column's mean vertical stress
// rho_bulk |g| H / 2 (hydrostatic; the wall's friction carries some of it).
InertialNumberInputs repose_inertial_inputs(const RunConfig& c, double column_height, double column_bulk_density);

}  // namespace colza
