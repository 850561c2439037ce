// [repose]: the angle of repose test (physics.md section 8). Spheres are generated in a
// vertical open-ended cylinder standing on a base plate, settled, cut at fill_height; the
// cylinder is lifted at lift_speed until its lower end clears the highest sphere by a
// diameter; the heap is left to rest (rest_unbalanced_force); a cone is fitted to its surface
// (analysis/heap_angle.hpp). The base is the bare plate, or the plate with a monolayer of the
// test's spheres glued to it (scenario/glued_layer.hpp) over a disc of glued_layer_diameter.
#pragma once
#include <cstdint>

#include "config/config_reader.hpp"

namespace colza {

enum class ReposeBase { kPlate, kGluedLayer };

// The config's name of a base: "plate" | "glued_layer".
inline const char* repose_base_name(ReposeBase b) { return b == ReposeBase::kPlate ? "plate" : "glued_layer"; }

struct ReposeSpec {
  ReposeBase base = ReposeBase::kPlate;  // "plate" | "glued_layer"
  double glued_layer_diameter = 0.0;    // m, of the glued disc; read: default 3.5 x cylinder_diameter
  double cylinder_diameter = 0.080;     // m
  double fill_height = 0.080;           // m, spheres above are discarded after settling
  double generation_height = 0.250;     // m, spheres are generated in the cylinder up to here
  double lift_speed = 0.005;            // m/s (5 mm/s, a slow lab lift)
  double base_friction = 0.23;          // particle-base friction (-); default wall.friction
  double rest_unbalanced_force = 1e-4;  // N, the heap is at rest below this mean unbalanced force
  double rest_max_time = 5.0;           // s of simulated time for the rest
  std::int64_t sectors = 16;            // of the cone fit
  double fit_inner = 0.25, fit_outer = 0.75;  // fit range, fractions of the heap's radius
};

// Reads [repose]; `particle_diameter_max` and `wall_friction` for checks and defaults. A
// cylinder narrower than 5 particle diameters (it would arch and not empty), a fill above the
// generation height or a fit range outside 0 <= inner < outer <= 1 is a ConfigError naming
// the key. A glued layer no wider than the cylinder plus two particle diameters is one too.
ReposeSpec read_repose(const ConfigNode& t, double particle_diameter_max, double wall_friction);

}  // namespace colza
