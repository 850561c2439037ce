// The generic scene: particles listed in the config or read from a packing file, walls
// with prescribed velocities, a fixed number of steps, and a time series of chosen
// particles' state, each wall's force and the energy budget. Used by the two-body
// checks and by the YADE cross-check (micro scenes, and macro runs from a packing).
#pragma once
#include "contact/slots.hpp"
#include "config/run_config.hpp"
#include "core/stage_timing.hpp"
#include "io/progress.hpp"
#include "io/snapshot.hpp"
#include "io/table.hpp"

namespace colza {

struct SceneResult {
  Table series;
  std::vector<StageTiming> stages;
  std::uint64_t steps = 0;
  bool stopped_by_condition = false;  // scene.stop_unbalanced_force was reached before scene.steps
  double dt = 0.0;
  std::size_t bonds_installed = 0;
  ParticleArrays final_state;
  SnapshotSeries snapshots;  // none unless a snapshot interval was given
};

// The empty series (column names and units) for the given recorded particles and wall
// count. Per particle k: pK_{x,y,z} position x(t), pK_v{x,y,z} velocity v(t - dt/2),
// pK_w{x,y,z} angular velocity, pK_f{x,y,z} and pK_t{x,y,z} contact force and torque of
// step t; per wall w: wW_f{x,y,z} force exerted on it by the particles, wW_{x,y,z} its
// origin; then contacts, bonds and the model's energy channels (J; engine/energy.hpp
// energy_columns: the paper's law has nine, a mechanism adds its own after wall_work).
Table scene_table(const std::vector<std::int64_t>& particles, std::size_t walls, const ContactModel& model);

// `snapshot_interval` (s; 0 = none): particle snapshots (scenario/snapshot_recorder.hpp).
SceneResult run_scene(const RunConfig& config, Progress& progress, double snapshot_interval = 0.0);

}  // namespace colza
