// The paper's uniaxial compression (oedometer) test, physics.md section 4:
// generate in a 100 mm x 200 mm cylinder, settle to 1e-4 N, discard above the 80 mm rim,
// add a piston at the top of the packing and push it down at 500 mm/min, recording the
// piston force against its travel; fit F(s) = c0 + c1 s + c2 s^2 over 150 N .. 29.3 kN.
#pragma once
#include <string>
#include <vector>
#include "analysis/oedometer_cycles.hpp"
#include "analysis/polyfit.hpp"
#include "config/run_config.hpp"
#include "core/stage_timing.hpp"
#include "io/progress.hpp"
#include "io/snapshot.hpp"
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
  // With oedometer.cycles the curve has three more columns (cycle_curve_columns below).
  Table curve{{"time", "piston_displacement", "piston_force", "contacts", "bonds"}, {"s", "m", "N", "1", "1"}};
  CompressionFit fit;                 // with cycles: over the first loading branch
  // oedometer.cycles: the branches' features (analysis/oedometer_cycles.hpp) and how many of
  // the targets were reached (all, unless a safety stop came first).
  LoadUnloadAnalysis cycles;
  std::size_t targets_reached = 0;
  double max_force = 0.0;             // N
  std::string stop_reason;            // "stop_force", "max_piston_travel" or (cycles) "cycles_completed"
  double dt_min = 0.0, dt_max = 0.0;  // s, over the loading stage
  std::uint64_t steps = 0;
  std::vector<StageTiming> stages;
  ParticleArrays settled;             // packing after discarding (loading starts from it)
  ParticleArrays final_state;
  std::uint64_t bonds_broken_tension = 0, bonds_broken_shear = 0;
  SnapshotSeries snapshots;           // of the loading (none unless a snapshot interval was given)
};

// The curve of a load-unload run: the single loading's columns, then radial_force (N, the
// sum of the normal forces on the cylinder), cylinder_friction_force (N, the vertical force
// the sample exerts on the cylinder, positive downward: the part of the piston's load the wall
// friction takes) and branch (0, 1, ...: the index of the target the piston is heading for).
Table cycle_curve_columns();

// The analysis settings of a simulated load-unload curve: the config's modulus stresses and
// window, and a reversal tolerance of 0 (the piston's travel is strictly monotone between
// turns, so every turn is exact).
CycleAnalysisSettings simulated_cycle_settings(const OedometerCycleSpec& cycles);

// Throws ConfigError when the configuration cannot make the sample (e.g. too many spheres).
// `snapshot_interval` (s; 0 = none): particle snapshots of the loading (scenario/snapshot_recorder.hpp).
OedometerResult run_oedometer(const RunConfig& config, Progress& progress, double snapshot_interval = 0.0);

// The container: the floor (plane z = 0, facing up) and the envelope (cylinder of diameter
// cylinder_diameter from z = 0 up through the generation volume).
void build_oedometer_container(World& world, const OedometerSpec& o);

// The piston: a plane at height `top` (m) facing down, moving down at piston_speed.
// Returns its wall index.
std::size_t add_oedometer_piston(World& world, const OedometerSpec& o, double top);

}  // namespace colza
