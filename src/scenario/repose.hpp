// The angle of repose test (physics.md section 8; config: config/repose_spec.hpp): spheres
// generated in an open-ended cylinder standing on a base plate, settled and cut at
// fill_height, handed on at rest; the cylinder is lifted at lift_speed until its lower end
// clears the highest sphere by a diameter, then stopped, and the heap is left to rest until
// the mean unbalanced force falls below rest_unbalanced_force; a cone is fitted to the heap's
// surface (analysis/heap_angle.hpp). The base plate has its own friction (base_friction); with
// repose.base = "glued_layer" a monolayer of fixed spheres covers a disc of it
// (scenario/glued_layer.hpp), the column is generated above it and the heap stands on it.
#pragma once
#include <vector>

#include "analysis/heap_angle.hpp"
#include "config/run_config.hpp"
#include "core/stage_timing.hpp"
#include "io/progress.hpp"
#include "io/snapshot.hpp"
#include "io/table.hpp"
#include "scenario/settling.hpp"

namespace colza {

struct ReposeResult {
  std::size_t particles_generated = 0;
  std::size_t particles = 0;           // in the column, after the cut
  ParticleArrays glued_layer;          // the fixed spheres of a glued base (none on a bare plate)
  double base_height = 0.0;            // m, the heap's base: 0, or the glued layer's mean top
  double column_height = 0.0;          // m, the highest top before the lift
  double column_bulk_density = 0.0;    // kg/m^3, mass / (cylinder area x (column_height - base_height))
  SettleResult settling;               // the column's
  double lift_time = 0.0;              // s of simulated time
  SettleResult rest;                   // the heap's
  HeapAngle heap;
  std::size_t spheres_beyond_heap = 0; // farther from the axis than the heap's radius + 2 diameters
  double dt = 0.0;                     // s, the last step
  std::uint64_t steps = 0;             // lift and rest
  std::vector<StageTiming> stages;
  ParticleArrays column;               // the settled column at rest (packing.txt)
  ParticleArrays final_state;          // the heap (its free spheres)
  SnapshotSeries snapshots;            // the lift, and the heap at rest, glued layer included (none unless an interval was given)
};

// `snapshot_interval` (s; 0 = none): particle snapshots of the lift from its start, and the
// heap at rest at the end (scenario/snapshot_recorder.hpp).
ReposeResult run_repose(const RunConfig& config, Progress& progress, double snapshot_interval = 0.0);

// The cone-fit settings of the config (sectors, fit range; the heap's axis is the cylinder's),
// the heap standing at `base_height` (m; ReposeResult::base_height).
HeapFitSettings repose_fit_settings(const ReposeSpec& r, double base_height);

// The heap's profile, one row per sphere: rho (m, its distance from the axis), azimuth_deg
// (deg, atan2(y, x)), top (m, z + r - base_height: its height above the heap's base, the
// plate or the glued layer's mean top) and in_fit (1 for a surface sphere the cone `fit` was
// fitted to, else 0): heap_profile.csv, a valid measured heap profile
// (calibration/measured_heap_profile.hpp, which ignores in_fit).
Table heap_profile_table(const ParticleArrays& heap, double base_height, const HeapAngle& fit);

}  // namespace colza
