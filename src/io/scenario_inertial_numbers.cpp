#include "io/scenario_inertial_numbers.hpp"

#include "analysis/inertial_number.hpp"
#include "core/types.hpp"

namespace colza {

namespace {

double mean_diameter(const RunConfig& c) { return 0.5 * (c.particle.diameter_min + c.particle.diameter_max); }

}  // namespace

InertialNumberInputs oedometer_inertial_inputs(const RunConfig& c, double packing_height, double max_force) {
  const double area = kPi * 0.25 * c.oedometer.cylinder_diameter * c.oedometer.cylinder_diameter;
  return {oedometer_strain_rate(c.oedometer.piston_speed, packing_height), mean_diameter(c), c.particle.density,
          max_force / area, "piston_speed / packing_height", "the largest piston stress (max_force / cylinder area)"};
}

InertialNumberInputs shear_inertial_inputs(const RunConfig& c, double normal_stress) {
  const double d = mean_diameter(c);
  return {shear_box_strain_rate(c.shear_box.shear_speed, d, c.shear_box.height), d, c.particle.density, normal_stress,
          "shear_speed / min(10 mean diameters, shear_box.height)", "the normal stress"};
}

InertialNumberInputs repose_inertial_inputs(const RunConfig& c, double column_height, double column_bulk_density) {
  return {oedometer_strain_rate(c.repose.lift_speed, column_height), mean_diameter(c), c.particle.density,
          0.5 * column_bulk_density * c.integration.gravity.norm() * column_height, "lift_speed / column_height",
          "the column's mean vertical stress, column_bulk_density |g| column_height / 2"};
}

}  // namespace colza
