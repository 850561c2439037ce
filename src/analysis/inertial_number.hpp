// The inertial number of a test (physics.md section 8; GDR MiDi 2004, da Cruz et al. 2005):
//
//   I = gamma_dot d sqrt(rho_p / p)
//
// gamma_dot the test's strain rate (1/s), d the mean particle diameter (m), rho_p the particle
// density (kg/m^3), p the confining stress (Pa). It is the ratio of the time a grain takes to
// fall into a gap under p, d sqrt(rho_p / p), to the time of the imposed deformation,
// 1 / gamma_dot. Below ~1e-3 a test is quasi-static: its result does not depend on its speed.
// The strain rates colza uses (docs/running.md, Inertial number):
//   oedometer:  gamma_dot = v_piston / H, H the sample's height (the piston's start), and p the
//               piston stress (the vertical stress the test controls);
//   shear box:  gamma_dot = v_shear / t, t the shear zone's thickness, taken as 10 mean
//               diameters (the thin end of the 10-20 d that direct and ring shear tests and DEM
//               find; a thinner zone gives a larger I, so I is not underestimated), at most the
//               sample's height; p the normal stress.
#pragma once

namespace colza {

inline constexpr double kQuasiStaticInertialNumber = 1e-3;
inline constexpr double kShearZoneDiameters = 10.0;

// Throws std::invalid_argument unless every argument is positive.
double inertial_number(double strain_rate, double diameter, double particle_density, double pressure);

double oedometer_strain_rate(double piston_speed, double sample_height);
double shear_zone_thickness(double mean_diameter, double sample_height);  // min(10 d, H)
double shear_box_strain_rate(double shear_speed, double mean_diameter, double sample_height);

}  // namespace colza
