// The paper's uniaxial compression (oedometer) test, physics.md section 4:
// generate in a 100 mm x 200 mm cylinder, settle to 1e-4 N, discard above the 80 mm rim,
// add a piston at the top of the packing and push it down at 500 mm/min, recording the
// piston force against its travel; fit F(s) = c0 + c1 s + c2 s^2 over 150 N .. 29.3 kN.
#pragma once
#include <string>
#include <vector>
#include "analysis/polyfit.hpp"
#include "config/run_config.hpp"
#include "core/stage_timing.hpp"
#include "io/progress.hpp"
#include "io/table.hpp"
#include "scenario/settling.hpp"

namespace colza {

struct OedometerResult {
  std::size_t particles_generated = 0;
  std::size_t particles = 0;          // after discarding above the rim
  double packing_height = 0.0;        // m, top of the highest sphere = piston start height
  double bulk_density = 0.0;          // kg/m^3 = particle mass / (cylinder area x packing height)
  SettleResult settling;              // none (in_this_run() false) for a packing file
  std::size_t bonds_installed = 0;
  Table curve{{"time", "piston_displacement", "piston_force", "contacts", "bonds"}, {"s", "m", "N", "1", "1"}};
  CompressionFit fit;
  double max_force = 0.0;             // N
  std::string stop_reason;            // "stop_force" or "max_piston_travel"
  double dt_min = 0.0, dt_max = 0.0;  // s, over the loading stage
  std::uint64_t steps = 0;
  std::vector<StageTiming> stages;
  ParticleArrays settled;             // packing after discarding (loading starts from it)
  ParticleArrays final_state;
  std::uint64_t bonds_broken_tension = 0, bonds_broken_shear = 0;
};

// Throws ConfigError when the configuration cannot make the sample (e.g. too many spheres).
OedometerResult run_oedometer(const RunConfig& config, Progress& progress);

// The container: the floor (plane z = 0, facing up) and the envelope (cylinder of diameter
// cylinder_diameter from z = 0 up through the generation volume).
void build_oedometer_container(World& world, const OedometerSpec& o);

// The piston: a plane at height `top` (m) facing down, moving down at piston_speed.
// Returns its wall index.
std::size_t add_oedometer_piston(World& world, const OedometerSpec& o, double top);

}  // namespace colza
