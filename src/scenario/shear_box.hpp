// The paper's direct shear test (physics.md section 4): a 200 x 200 x 80 mm box of two
// halves split at 40 mm, twelve rectangles (lower half: bottom, four sides, rim; upper half:
// four sides, rim; pressure plate). The sample is generated in the box extended upward,
// settled to 1e-3 N and cut at 80 mm; the plate is servo-controlled to hold the normal
// stress; once it holds, the lower half is pulled in +x at 300 mm/min to 30 mm.
#pragma once
#include <vector>
#include "config/run_config.hpp"
#include "core/stage_timing.hpp"
#include "io/progress.hpp"
#include "io/snapshot.hpp"
#include "io/table.hpp"
#include "scenario/settling.hpp"

namespace colza {

// Wall indices of the box in World::walls.
struct ShearBoxWalls {
  std::vector<std::size_t> lower;  // bottom, four sides, rim: move together in +x
  std::vector<std::size_t> upper;  // four sides, rim: held
  std::size_t plate = 0;           // added once the sample is prepared
};

// Adds the eleven box walls (the upper sides reach up to `wall_top`). With
// box.edge_contacts = kPerSurface, the plates' shared edges are restricted (walls/wall.hpp,
// RectangleEdges) so that one surface gives one contact: the front and back side walls'
// seams at the shear plane give none beyond them (the plate whose face the sphere's
// projection falls on takes it), each rim's end at its side wall gives none (the side
// wall's edge is the convex corner), and the trailing and leading seams as set by
// set_trailing_and_leading_seams for aligned halves.
ShearBoxWalls build_shear_box(World& world, const ShearBoxSpec& box, double wall_top);

// For kPerSurface (a no-op for kPerWall): with the halves aligned the trailing and leading
// side walls' seams are coplanar and give none beyond them; once the lower half moves, the
// lower trailing wall's top edge and the upper leading wall's bottom edge become the convex
// corners with the rims and touch only spheres in front of them (behind lies the rim's face).
void set_trailing_and_leading_seams(World& world, const ShearBoxSpec& box, bool halves_aligned);

struct ShearSample {
  ParticleArrays particles;      // settled and cut at the box height, at rest
  std::size_t generated = 0;
  SettleResult settling;
  std::vector<StageTiming> stages;
};

// Generation + settling + discarding (or the packing file named in the config).
ShearSample prepare_shear_sample(const RunConfig& config, Progress& progress);

struct ShearLoadResult {
  double normal_stress_target = 0.0;   // Pa
  std::size_t particles = 0;
  bool consolidated = false;           // plate held the stress within tolerance before shearing
  double consolidation_time = 0.0;     // s (simulated), including any preconsolidation
  bool preconsolidated = false;        // held shear_box.preconsolidation_stress before unloading (when set)
  std::size_t bonds_installed = 0;
  Table curve{{"time", "shear_displacement", "shear_force", "shear_stress", "normal_stress", "plate_height",
               "dilatancy", "contacts", "bonds"},
              {"s", "m", "N", "Pa", "Pa", "m", "m", "1", "1"}};
  double shear_strength = 0.0;         // Pa, mean shear stress over the strength window
  double peak_shear_stress = 0.0;      // Pa
  double mean_normal_stress = 0.0;     // Pa, during shearing
  double mean_normal_stress_error = 0.0;  // mean |sigma - target| / target during shearing
  std::size_t particles_outside = 0;   // spheres whose centre left the box at the end
  std::uint64_t steps = 0;
  double dt = 0.0;
  std::vector<StageTiming> stages;
  ParticleArrays final_state;
  std::uint64_t bonds_broken_tension = 0, bonds_broken_shear = 0;
  SnapshotSeries snapshots;            // consolidation and shearing (none unless an interval was given)
};

// `snapshot_interval` (s; 0 = none): particle snapshots from the start of the consolidation
// (scenario/snapshot_recorder.hpp).
ShearLoadResult run_shear_load(const RunConfig& config, const ShearSample& sample, double normal_stress,
                               Progress& progress, double snapshot_interval = 0.0);

}  // namespace colza
