#include "analysis/inertial_number.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace colza {

double inertial_number(double strain_rate, double diameter, double particle_density, double pressure) {
  if (!(strain_rate > 0.0) || !(diameter > 0.0) || !(particle_density > 0.0) || !(pressure > 0.0))
    throw std::invalid_argument("the inertial number needs a positive strain rate, diameter, density and pressure");
  return strain_rate * diameter * std::sqrt(particle_density / pressure);
}

double oedometer_strain_rate(double piston_speed, double sample_height) { return piston_speed / sample_height; }

double shear_zone_thickness(double mean_diameter, double sample_height) {
  return std::min(kShearZoneDiameters * mean_diameter, sample_height);
}

double shear_box_strain_rate(double shear_speed, double mean_diameter, double sample_height) {
  return shear_speed / shear_zone_thickness(mean_diameter, sample_height);
}

}  // namespace colza
