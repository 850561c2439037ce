// How deep a generated sample can settle in its container, from the config alone: a sample
// too shallow for its test is refused before the run (exit 2). A walk-through ran the shear
// box with 100 spheres (the plate came to rest below the shear plane: "shear strength
// -1.075 kPa", no warning) and with a box length of 60 (mm typed for m: 0.011 kPa), and the
// oedometer with a cylinder diameter of 100 (an internal error after allocating gigabytes) or
// 1 (a "bulk density" of 47.9 kg/m^3).
#pragma once
#include "config/run_config.hpp"

namespace colza {

// The mean volume (m^3) of a sphere with diameters uniform on [diameter_min, diameter_max]:
// (pi / 6) E[d^3], E[d^3] = (dmax^4 - dmin^4) / (4 (dmax - dmin)).
double mean_sphere_volume(const ParticleSpec& particle);

// The loosest packing fraction a settled sample is taken to have, so the deepest it can
// stand: count x mean volume / (fraction x floor area). Measured on colza's samples of 6-7 mm
// spheres: 0.52 for the paper's oedometer below its rim, 0.45 for 1000 spheres in the 100 mm
// cylinder measured to the top of the highest sphere (its rough top counts as sample).
inline constexpr double kLoosestSettledFraction = 0.45;

// Refuses (ConfigError on `sample.count`, or on the container's size when that is over 50
// particle diameters: a length in mm) a generated sample that cannot be deeper than three
// layers (oedometer: 3 diameter_max) or than the shear plane plus one layer (shear box), at
// the loosest packing. Nothing for a packing file (its spheres are checked against the
// container as read) or a scene.
void require_a_sample_deep_enough(const RunConfig& c, Scenario scenario, const ConfigNode& root);

}  // namespace colza
