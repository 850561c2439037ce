#include "scenario/repose.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scenario/glued_layer.hpp"
#include "scenario/sample_preparation.hpp"
#include "scenario/snapshot_recorder.hpp"

namespace colza {

namespace {

// Wall 0: the base plate (plane z = 0, facing up, wall material `base_material`); wall 1: the
// cylinder, from z = 0 up through the generation volume. A glued base's spheres touch
// neither: they are glued to the plate, and the cylinder stands on them.
void build_repose_container(World& world, const ReposeSpec& r, std::uint16_t base_material) {
  Wall base = Wall::plane("base", Vec3::Zero(), Vec3::UnitZ());
  base.material = base_material;
  base.meets_fixed_spheres = false;
  world.walls.push_back(base);
  Wall cylinder = Wall::cylinder("cylinder", Vec3::Zero(), Vec3::UnitZ(), 0.5 * r.cylinder_diameter, 0.0,
                                 r.generation_height);
  cylinder.meets_fixed_spheres = false;
  world.walls.push_back(cylinder);
}

double highest_top(const ParticleArrays& p) {
  double top = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) top = std::max(top, p.position[i].z() + p.radius[i]);
  return top;
}

// The fixed spheres glued to the plate (none on a bare plate), seeded by the run's seed.
ParticleArrays glued_base(const RunConfig& c) {
  const ReposeSpec& rs = c.repose;
  if (rs.base == ReposeBase::kPlate) return {};
  GluedLayerRequest q;
  q.disc_radius = 0.5 * rs.glued_layer_diameter;
  q.diameter_min = c.particle.diameter_min;
  q.diameter_max = c.particle.diameter_max;
  q.density = c.particle.density;
  q.seed = c.seed;
  return glued_layer(q);
}

// The surface the heap stands on: the plate (0), or the glued layer's mean top (m).
double base_height_of(const ParticleArrays& glued) {
  if (glued.size() == 0) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < glued.size(); ++i) sum += glued.position[i].z() + glued.radius[i];
  return sum / static_cast<double>(glued.size());
}

// The free spheres of `p` (the glued ones are the base, not the heap).
ParticleArrays free_spheres(const ParticleArrays& p) {
  ParticleArrays free = p;
  std::vector<std::uint8_t> keep(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) keep[i] = p.fixed[i] ? 0 : 1;
  free.compact(keep);
  return free;
}

}  // namespace

HeapFitSettings repose_fit_settings(const ReposeSpec& r, double base_height) {
  HeapFitSettings s;
  s.base_height = base_height;
  s.sectors = static_cast<std::size_t>(r.sectors);
  s.inner = r.fit_inner;
  s.outer = r.fit_outer;
  return s;
}

Table heap_profile_table(const ParticleArrays& heap, double base_height, const HeapAngle& fit) {
  Table profile({"rho", "azimuth_deg", "top", "in_fit"}, {"m", "deg", "m", "1"});
  std::vector<char> in_fit(heap.size(), 0);
  for (const std::size_t i : fit.fit_spheres)
    if (i < heap.size()) in_fit[i] = 1;
  for (std::size_t i = 0; i < heap.size(); ++i) {
    const double x = heap.position[i].x(), y = heap.position[i].y();
    profile.add_row({std::hypot(x, y), std::atan2(y, x) * 180.0 / kPi,
                     heap.position[i].z() + heap.radius[i] - base_height, in_fit[i] ? 1.0 : 0.0});
  }
  return profile;
}

ReposeResult run_repose(const RunConfig& c, Progress& progress, double snapshot_interval) {
  const ReposeSpec& rs = c.repose;
  ReposeResult r;

  // --- the column: generated, settled in the cylinder (the base with the walls' friction),
  // cut at fill_height, at rest --------------------------------------------------------
  StageClock prep_clock("settling");
  r.glued_layer = glued_base(c);
  r.base_height = base_height_of(r.glued_layer);
  {
    World settling_world;
    build_repose_container(settling_world, rs, 0);
    settling_world.particles = r.glued_layer;
    const double above_layer = highest_top(r.glued_layer);
    NewSample s = settle_new_sample(settling_world, c,
                                    GenerationRegion::vertical_cylinder(Vec3(0.0, 0.0, above_layer),
                                                                        0.5 * rs.cylinder_diameter,
                                                                        rs.generation_height - above_layer),
                                    "repose.generation_height", rs.fill_height, "below repose.fill_height", progress,
                                    prep_clock);
    r.column = std::move(s.at_rest);
    r.particles_generated = s.generated;
    r.settling = s.settling;
  }
  r.particles = r.column.size();
  r.column_height = highest_top(r.column);
  double mass = 0.0;
  for (double m : r.column.mass) mass += m;
  r.column_bulk_density =
      mass / (kPi * 0.25 * rs.cylinder_diameter * rs.cylinder_diameter * (r.column_height - r.base_height));
  r.stages.push_back(prep_clock.finish());

  // --- the heap: the base plate gets its own friction (wall material 1) ------------------
  PhysicsSettings physics = make_physics(c);
  WallMaterial base = physics.wall_materials.at(0);
  base.name = "base";
  base.friction = rs.base_friction;
  physics.wall_materials.push_back(base);
  World world;
  build_repose_container(world, rs, 1);
  world.particles = r.glued_layer;
  for (std::size_t i = 0; i < r.column.size(); ++i)
    world.particles.add(r.column.position[i], r.column.radius[i], c.particle.density);
  Stepper stepper(physics);
  stepper.prepare(world);
  const std::size_t cylinder = 1;
  const double d_max = c.particle.diameter_max;

  StageClock lift_clock("lift");
  progress.start_stage("lift");
  world.walls[cylinder].velocity = Vec3(0.0, 0.0, rs.lift_speed);
  stepper.set_integration_sums({.unbalanced = false, .damping_work = false});
  stepper.set_between_halves(Stepper::BetweenHalves::kWallsOnly);
  const double t0 = world.time;
  SnapshotRecorder snapshots(snapshot_interval, t0);
  std::uint64_t lift_steps = 0;
  // Lifted until the cylinder's lower end clears the highest sphere by a diameter (checked
  // every 100 steps; a sphere can only fall, so the column's top only sinks).
  while (true) {
    stepper.step(world);
    ++lift_steps;
    snapshots.observe(world);
    if (lift_steps % 100 != 0) continue;
    const double bottom = world.walls[cylinder].origin.z();
    const double top = highest_top(world.particles);
    if (bottom > top + d_max) break;
    if (progress.active() && lift_steps % 2000 == 0) {
      char detail[96];
      std::snprintf(detail, sizeof detail, "cylinder lifted %.1f mm of %.1f mm", 1e3 * bottom, 1e3 * (top + d_max));
      progress.update(bottom / (top + d_max), detail);
    }
  }
  stepper.require_sound_state(world);
  world.walls[cylinder].velocity = Vec3::Zero();
  r.lift_time = world.time - t0;
  progress.end_stage();
  lift_clock.count_steps(lift_steps, world.particles.size());
  r.stages.push_back(lift_clock.finish());

  StageClock rest_clock("rest");
  r.rest = settle(world, stepper, rs.rest_unbalanced_force, rs.rest_max_time,
                  static_cast<std::uint64_t>(c.sample.settle_check_interval), progress);
  rest_clock.count_steps(r.rest.steps, world.particles.size());
  r.stages.push_back(rest_clock.finish());
  r.steps = lift_steps + r.rest.steps;
  r.dt = world.dt;
  snapshots.record(world);  // the heap at rest
  r.snapshots = snapshots.take();

  r.final_state = free_spheres(world.particles);
  const ParticleArrays& p = r.final_state;
  std::vector<double> x(p.size()), y(p.size()), z(p.size()), radius(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    x[i] = p.position[i].x();
    y[i] = p.position[i].y();
    z[i] = p.position[i].z();
    radius[i] = p.radius[i];
  }
  r.heap = fit_heap_angle(x, y, z, radius, repose_fit_settings(rs, r.base_height));
  for (std::size_t i = 0; i < p.size(); ++i)
    if (std::hypot(x[i], y[i]) > r.heap.radius + 2.0 * d_max) ++r.spheres_beyond_heap;
  return r;
}

}  // namespace colza
