#include "scenario/oedometer.hpp"

#include <algorithm>
#include <cstdio>

#include "scenario/bonds.hpp"
#include "scenario/generation.hpp"
#include "scenario/sample_preparation.hpp"
#include "scenario/snapshot_recorder.hpp"
#include "scenario/wall_load.hpp"

namespace colza {

void build_oedometer_container(World& world, const OedometerSpec& o) {
  const double radius = 0.5 * o.cylinder_diameter;
  world.walls.push_back(Wall::plane("bottom", Vec3::Zero(), Vec3::UnitZ()));
  // The envelope reaches up through the whole generation volume (the paper generates in
  // 100 mm x 200 mm and discards above the 80 mm rim after settling).
  world.walls.push_back(Wall::cylinder("envelope", Vec3::Zero(), Vec3::UnitZ(), radius, 0.0,
                                       std::max(o.generation_height, o.cylinder_height)));
}

std::size_t add_oedometer_piston(World& world, const OedometerSpec& o, double top) {
  Wall piston = Wall::plane("piston", Vec3(0.0, 0.0, top), -Vec3::UnitZ());
  piston.velocity = Vec3(0.0, 0.0, -o.piston_speed);
  world.walls.push_back(piston);
  return world.walls.size() - 1;
}

Table cycle_curve_columns() {
  return Table({"time", "piston_displacement", "piston_force", "contacts", "bonds", "radial_force",
                "cylinder_friction_force", "branch"},
               {"s", "m", "N", "1", "1", "N", "N", "1"});
}

CycleAnalysisSettings simulated_cycle_settings(const OedometerCycleSpec& cycles) {
  CycleAnalysisSettings s;
  s.modulus_stresses = cycles.modulus_stresses;
  s.modulus_window = cycles.modulus_window;
  s.reversal_tolerance = 0.0;
  return s;
}

namespace {

// The rows of one branch of a load-unload curve (its `branch` column equal to `b`).
std::vector<double> branch_rows(const Table& curve, const std::string& column, double b) {
  const std::vector<double>& x = curve.column(column);
  const std::vector<double>& branch = curve.column("branch");
  std::vector<double> out;
  for (std::size_t k = 0; k < x.size(); ++k)
    if (branch[k] == b) out.push_back(x[k]);
  return out;
}

double total_mass(const ParticleArrays& p) {
  double m = 0.0;
  for (double mi : p.mass) m += mi;
  return m;
}

}  // namespace

OedometerResult run_oedometer(const RunConfig& c, Progress& progress, double snapshot_interval) {
  OedometerResult r;
  const OedometerSpec& o = c.oedometer;
  World world;
  build_oedometer_container(world, o);

  // --- preparation: a settled sample at rest, new or from a packing file --------------
  StageClock prep_clock("settling");
  if (o.packing_file.empty()) {
    World settling_world;  // the sample settles in a world of its own, handed on at rest
    build_oedometer_container(settling_world, o);
    NewSample s = settle_new_sample(
        settling_world, c,
        GenerationRegion::vertical_cylinder(Vec3::Zero(), 0.5 * o.cylinder_diameter, o.generation_height),
        "oedometer.generation_height", o.cylinder_height, "below the rim", progress, prep_clock);
    world.particles = std::move(s.at_rest);
    r.particles_generated = s.generated;
    r.settling = s.settling;
  } else {
    world.particles = sample_from_packing(o.packing_file, "oedometer.packing_file", c.particle.density);
    r.particles_generated = world.particles.size();
  }
  Stepper stepper(make_physics(c));
  stepper.prepare(world);
  if (c.contact.bond_install == BondInstallMoment::kAfterSettling) r.bonds_installed = install_bonds(world, stepper, c.contact.bond_gap);
  discard_above(world, stepper, o.cylinder_height);  // a packing file may reach above the rim; a new sample does not
  r.particles = world.particles.size();
  r.stages.push_back(prep_clock.finish());
  if (r.particles == 0)
    throw no_sphere_left_error(c, stepper, "below the rim");

  // --- piston at the top of the packing ------------------------------------------
  double top = 0.0;
  for (std::size_t i = 0; i < world.particles.size(); ++i)
    top = std::max(top, world.particles.position[i].z() + world.particles.radius[i]);
  r.packing_height = top;
  const double area = kPi * 0.25 * o.cylinder_diameter * o.cylinder_diameter;
  r.bulk_density = total_mass(world.particles) / (area * top);
  const std::size_t piston_id = add_oedometer_piston(world, o, top);
  const std::size_t envelope_id = 1;  // build_oedometer_container: the floor, then the envelope
  stepper.prepare(world);
  if (c.contact.bond_install == BondInstallMoment::kBeforeLoading) r.bonds_installed = install_bonds(world, stepper, c.contact.bond_gap);
  r.settled = world.particles;

  // --- loading ----------------------------------------------------------------------
  StageClock load_clock("loading");
  progress.start_stage("loading");
  const double t_start = world.time;
  SnapshotRecorder snapshots(snapshot_interval, t_start);
  r.dt_min = r.dt_max = world.dt;
  bool stop = false;
  std::uint64_t load_steps = 0;
  // oedometer.cycles: the piston heads for targets[branch] (Pa), down on even branches, up on
  // odd ones, and turns in the step after the one whose force reached the target.
  const std::vector<double>& targets = o.cycles.targets;
  const bool cycling = o.cycles.enabled();
  if (cycling) r.curve = cycle_curve_columns();
  std::size_t branch = 0;
  bool turn = false;
  stepper.set_integration_sums({.unbalanced = false, .damping_work = false});  // neither is read while loading
  stepper.set_between_halves(Stepper::BetweenHalves::kWallsOnly);  // the observer reads the piston and contact counts
  while (!stop) {
    stepper.step(world, [&](const World& w) {
      const Wall& p = w.walls[piston_id];
      const double travel = top - p.origin.z();
      const double force = p.force.z();  // particles push the piston up: compression positive
      r.max_force = std::max(r.max_force, force);
      if (cycling) {
        const double stress = force / area;
        turn = branch % 2 == 0 ? stress >= targets[branch] : stress <= targets[branch];
      }
      if (force >= o.stop_force) r.stop_reason = "stop_force";
      else if (travel >= o.max_piston_travel) r.stop_reason = "max_piston_travel";
      else if (turn && branch + 1 == targets.size()) r.stop_reason = "cycles_completed";
      stop = !r.stop_reason.empty();
      if (load_steps % static_cast<std::uint64_t>(o.record_interval) == 0 || stop || turn) {
        const double contacts =
            static_cast<double>(w.contacts.touching_particle_contacts() + w.contacts.touching_wall_contacts());
        if (!cycling) {
          r.curve.add_row({w.time - t_start, travel, force, contacts, static_cast<double>(w.contacts.bonded_contacts())});
        } else {
          r.curve.add_row({w.time - t_start, travel, force, contacts, static_cast<double>(w.contacts.bonded_contacts()),
                           wall_normal_force_sum(w.contacts, static_cast<Index>(envelope_id)),
                           0.0 - w.walls[envelope_id].force.z(), static_cast<double>(branch)});  // 0 - f: no "-0"
        }
      }
      if (progress.active() && load_steps % 2000 == 0) {
        char detail[96];
        std::snprintf(detail, sizeof detail, "travel %.2f mm, piston force %.2f kN, dt %.3g s", 1e3 * travel, 1e-3 * force, w.dt);
        progress.update(std::max(force / o.stop_force, travel / o.max_piston_travel), detail);
      }
    });
    ++load_steps;
    snapshots.observe(world);
    if (turn && !stop) {  // reverse: the next branch heads for the next target
      ++branch;
      world.walls[piston_id].velocity = Vec3(0.0, 0.0, branch % 2 == 0 ? -o.piston_speed : o.piston_speed);
      turn = false;
    }
    r.dt_min = std::min(r.dt_min, world.dt);
    r.dt_max = std::max(r.dt_max, world.dt);
  }
  stepper.require_sound_state(world);  // a blow-up within the last check interval, too
  snapshots.record(world);
  r.snapshots = snapshots.take();
  progress.end_stage();
  load_clock.count_steps(load_steps, world.particles.size());
  r.stages.push_back(load_clock.finish());
  r.steps = r.settling.steps + load_steps;
  if (!cycling) {
    r.fit = fit_compression_curve(r.curve.column("piston_displacement"), r.curve.column("piston_force"),
                                  o.fit_force_min, o.fit_force_max);
  } else {
    r.targets_reached = branch + (r.stop_reason == "cycles_completed" ? 1 : 0);
    r.fit = fit_compression_curve(branch_rows(r.curve, "piston_displacement", 0.0),
                                  branch_rows(r.curve, "piston_force", 0.0), o.fit_force_min, o.fit_force_max);
    if (r.curve.rows() >= 2)
      r.cycles = analyse_load_unload(r.curve.column("piston_displacement"), r.curve.column("piston_force"),
                                     r.curve.column("radial_force"), {area, top, o.cylinder_diameter},
                                     simulated_cycle_settings(o.cycles));
  }
  r.final_state = world.particles;
  r.bonds_broken_tension = stepper.events().bonds_broken_tension;
  r.bonds_broken_shear = stepper.events().bonds_broken_shear;
  return r;
}

}  // namespace colza
