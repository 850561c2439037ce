#include "scenario/shear_box.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "analysis/shear_strength.hpp"
#include "contact/slots.hpp"
#include "engine/wall_stiffness.hpp"
#include "scenario/bonds.hpp"
#include "scenario/generation.hpp"
#include "scenario/sample_preparation.hpp"
#include "scenario/snapshot_recorder.hpp"
#include "scenario/plate_servo.hpp"

namespace colza {

double PlateServo::advance_speed(double force, double contact_stiffness, double dt) const {
  const double v = relaxation * (target_force - force) / (contact_stiffness * dt);
  return std::clamp(v, -max_speed, max_speed);
}

namespace {

Wall& wall_named(World& world, const std::string& name) {
  for (Wall& w : world.walls)
    if (w.name == name) return w;
  throw std::logic_error("shear box: no wall named " + name);
}

// Sets the edge of side wall `name` that lies on the shear plane (z = shear_plane, through
// the wall's centre line).
void set_shear_plane_edge(World& world, const std::string& name, double shear_plane, EdgeContact contact) {
  Wall& w = wall_named(world, name);
  set_edge_contact(w, Vec3(w.origin.x(), w.origin.y(), shear_plane), contact);
}

}  // namespace

ShearBoxWalls build_shear_box(World& world, const ShearBoxSpec& b, double wall_top) {
  ShearBoxWalls ids;
  auto add = [&](Wall w, std::vector<std::size_t>& group) {
    group.push_back(world.walls.size());
    world.walls.push_back(std::move(w));
  };
  const double L = b.length, W = b.width, sp = b.shear_plane;
  const Vec3 ex = Vec3::UnitX(), ey = Vec3::UnitY(), ez = Vec3::UnitZ();
  // Lower half, z in [0, sp]; it moves in +x, so x = 0 is its trailing side.
  add(Wall::rectangle("lower_bottom", Vec3(L / 2, W / 2, 0), ez, ex, L / 2, W / 2), ids.lower);
  add(Wall::rectangle("lower_trailing", Vec3(0, W / 2, sp / 2), ex, ey, W / 2, sp / 2), ids.lower);
  add(Wall::rectangle("lower_leading", Vec3(L, W / 2, sp / 2), -ex, ey, W / 2, sp / 2), ids.lower);
  add(Wall::rectangle("lower_front", Vec3(L / 2, 0, sp / 2), ey, ex, L / 2, sp / 2), ids.lower);
  add(Wall::rectangle("lower_back", Vec3(L / 2, W, sp / 2), -ey, ex, L / 2, sp / 2), ids.lower);
  // Rim: extends backwards from the trailing side at the shear plane, facing up; it closes
  // the opening left behind the upper half's trailing wall as the lower half moves on.
  add(Wall::rectangle("lower_rim", Vec3(-b.rim_length / 2, W / 2, sp), ez, ex, b.rim_length / 2, W / 2), ids.lower);
  // Upper half, z in [sp, wall_top]; held.
  const double uh = 0.5 * (wall_top - sp), uz = 0.5 * (wall_top + sp);
  add(Wall::rectangle("upper_trailing", Vec3(0, W / 2, uz), ex, ey, W / 2, uh), ids.upper);
  add(Wall::rectangle("upper_leading", Vec3(L, W / 2, uz), -ex, ey, W / 2, uh), ids.upper);
  add(Wall::rectangle("upper_front", Vec3(L / 2, 0, uz), ey, ex, L / 2, uh), ids.upper);
  add(Wall::rectangle("upper_back", Vec3(L / 2, W, uz), -ey, ex, L / 2, uh), ids.upper);
  // Rim: extends forwards from the upper half's leading side, facing down; it keeps the
  // lower half's particles that pass under it from escaping upward.
  add(Wall::rectangle("upper_rim", Vec3(L + b.rim_length / 2, W / 2, sp), -ez, ex, b.rim_length / 2, W / 2), ids.upper);
  if (b.edge_contacts == BoxEdgeContacts::kPerSurface) {
    // The front and back seams stay coplanar as the lower half slides along them: the plate
    // whose face the sphere's projection falls on takes the contact.
    for (const char* name : {"lower_front", "lower_back", "upper_front", "upper_back"})
      set_shear_plane_edge(world, name, sp, EdgeContact::kNone);
    // Each rim hands its end at the side wall to that wall's edge, the convex corner.
    Wall& lower_rim = wall_named(world, "lower_rim");
    set_edge_contact(lower_rim, Vec3(lower_rim.origin.x() + b.rim_length / 2, W / 2, sp), EdgeContact::kNone);
    Wall& upper_rim = wall_named(world, "upper_rim");
    set_edge_contact(upper_rim, Vec3(upper_rim.origin.x() - b.rim_length / 2, W / 2, sp), EdgeContact::kNone);
    set_trailing_and_leading_seams(world, b, true);
  }
  return ids;
}

void set_trailing_and_leading_seams(World& world, const ShearBoxSpec& b, bool halves_aligned) {
  if (b.edge_contacts != BoxEdgeContacts::kPerSurface) return;
  auto set = [&](const char* name, EdgeContact contact) { set_shear_plane_edge(world, name, b.shear_plane, contact); };
  if (halves_aligned) {  // coplanar plates: the one whose face the projection falls on
    for (const char* name : {"lower_trailing", "lower_leading", "upper_trailing", "upper_leading"})
      set(name, EdgeContact::kNone);
    return;
  }
  // Offset halves. The lower trailing wall's top edge and the upper leading wall's bottom
  // edge are convex corners with the rims; behind them lies the rim's face, which takes
  // the spheres there. The other two edges lie on a rim's face, out of the spheres' reach.
  set("lower_trailing", EdgeContact::kFrontOnly);
  set("upper_leading", EdgeContact::kFrontOnly);
  set("lower_leading", EdgeContact::kBothSides);
  set("upper_trailing", EdgeContact::kBothSides);
}

ShearSample prepare_shear_sample(const RunConfig& c, Progress& progress) {
  ShearSample s;
  const ShearBoxSpec& b = c.shear_box;
  if (!b.packing_file.empty()) {
    s.particles = sample_from_packing(b.packing_file, "shear_box.packing_file", c.particle.density);
    s.generated = s.particles.size();
    s.settling.converged = true;
    return s;
  }
  World world;
  build_shear_box(world, b, b.generation_height);
  StageClock clock("settling");
  NewSample fresh = settle_new_sample(world, c,
                                      GenerationRegion::box(Vec3::Zero(), Vec3(b.length, b.width, b.generation_height)),
                                      "shear_box.generation_height", b.height, "below the box top", progress, clock);
  s.particles = std::move(fresh.at_rest);
  s.generated = fresh.generated;
  s.settling = fresh.settling;
  s.stages.push_back(clock.finish());
  return s;
}

namespace {

double sum_lower_force_x(const World& w, const ShearBoxWalls& ids) {
  double fx = 0.0;
  for (std::size_t k : ids.lower) fx += w.walls[k].force.x();
  return fx;
}

std::size_t count_outside(const World& w, const ShearBoxSpec& b, double offset, double plate_z) {
  std::size_t n = 0;
  const ParticleArrays& p = w.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& x = p.position[i];
    const double tol = 0.5 * p.radius[i];
    const bool lower = x.z() < b.shear_plane;
    const double x0 = lower ? offset : 0.0;
    const bool inside = x.y() > -tol && x.y() < b.width + tol && x.z() > -tol && x.z() < plate_z + tol &&
                        x.x() > x0 - tol && x.x() < x0 + b.length + tol;
    if (!inside) ++n;
  }
  return n;
}

}  // namespace

ShearLoadResult run_shear_load(const RunConfig& c, const ShearSample& sample, double normal_stress,
                               Progress& progress, double snapshot_interval) {
  ShearLoadResult r;
  const ShearBoxSpec& b = c.shear_box;
  const double area = b.length * b.width;  // nominal area (paper: 0.04 m^2)
  r.normal_stress_target = normal_stress;
  Stepper stepper(make_physics(c));
  World world;
  ShearBoxWalls ids = build_shear_box(world, b, b.generation_height);
  world.particles = sample.particles;
  r.particles = world.particles.size();
  double top = 0.0;
  for (std::size_t i = 0; i < world.particles.size(); ++i)
    top = std::max(top, world.particles.position[i].z() + world.particles.radius[i]);
  ids.plate = world.walls.size();
  world.walls.push_back(Wall::rectangle("plate", Vec3(b.length / 2, b.width / 2, top), -Vec3::UnitZ(), Vec3::UnitX(),
                                        b.length / 2, b.width / 2));
  stepper.prepare(world);
  if (c.contact.bond_install == BondInstallMoment::kAfterSettling) r.bonds_installed = install_bonds(world, stepper, c.contact.bond_gap);

  PlateServo servo{normal_stress * area, b.servo_relaxation, b.servo_max_speed};
  auto control_plate = [&](World& w) {
    Wall& plate = w.walls[ids.plate];
    const double k = wall_normal_stiffness(w, stepper.physics(), stepper.pairs(), ids.plate);
    plate.velocity = Vec3(0.0, 0.0, -servo.advance_speed(plate.force.z(), k, w.dt));
  };

  // --- consolidation under the servo (after a preconsolidation, when set) -----------
  stepper.set_integration_sums({.unbalanced = false, .damping_work = false});  // neither is read from here on
  // Between the halves of a step only the walls (servo, forces) and contact counts are read.
  stepper.set_between_halves(Stepper::BetweenHalves::kWallsOnly);
  StageClock consolidation_clock("consolidation");
  progress.start_stage("consolidation");
  const double t0 = world.time;
  SnapshotRecorder snapshots(snapshot_interval, t0);
  std::uint64_t steps = 0;
  // Holds `stress` (Pa) until the plate force is within the tolerance and the plate still for
  // the consolidation window; false when consolidation_max_time (from this call) runs out.
  const auto consolidate_at = [&](double stress) {
    servo.target_force = stress * area;
    const double start = world.time;
    double held_since = -1.0;
    while (true) {
      stepper.begin_step(world);
      control_plate(world);
      const Wall& plate = world.walls[ids.plate];
      const double error = std::abs(plate.force.z() - servo.target_force) / servo.target_force;
      const bool held = error < b.consolidation_tolerance && std::abs(plate.velocity.z()) < b.consolidation_plate_speed;
      if (!held) held_since = -1.0;
      else if (held_since < 0.0) held_since = world.time;
      if (progress.active() && steps % 2000 == 0) {
        char detail[96];
        std::snprintf(detail, sizeof detail, "sigma %.2f kPa (target %.2f), t = %.3f s", plate.force.z() / area * 1e-3,
                      stress * 1e-3, world.time - t0);
        progress.update(-1.0, detail);
      }
      stepper.finish_step(world);
      ++steps;
      snapshots.observe(world);
      if (held_since >= 0.0 && world.time - held_since >= b.consolidation_window) return true;
      if (world.time - start >= b.consolidation_max_time) return false;
    }
  };
  if (b.preconsolidation_stress > 0.0) r.preconsolidated = consolidate_at(b.preconsolidation_stress);
  r.consolidated = consolidate_at(normal_stress);
  stepper.require_sound_state(world);  // a blow-up within the last check interval, too
  progress.end_stage();
  r.consolidation_time = world.time - t0;
  consolidation_clock.count_steps(steps, world.particles.size());
  r.stages.push_back(consolidation_clock.finish());
  if (c.contact.bond_install == BondInstallMoment::kBeforeLoading) r.bonds_installed = install_bonds(world, stepper, c.contact.bond_gap);

  // --- shearing ---------------------------------------------------------------------
  StageClock shear_clock("shearing");
  progress.start_stage("shearing");
  set_trailing_and_leading_seams(world, b, false);  // the halves part: those seams become steps
  for (std::size_t k : ids.lower) world.walls[k].velocity = Vec3(b.shear_speed, 0.0, 0.0);
  const double x0 = world.walls[ids.lower[0]].origin.x();
  const double z0 = world.walls[ids.plate].origin.z();
  const double ts = world.time;
  std::uint64_t shear_steps = 0;
  double sigma_sum = 0.0, sigma_error_sum = 0.0;
  ShearStrengthMean strength({b.strength_window_start, b.strength_window_end});
  bool done = false;
  while (!done) {
    stepper.begin_step(world);
    control_plate(world);
    const double offset = world.walls[ids.lower[0]].origin.x() - x0;
    const double shear_force = -sum_lower_force_x(world, ids);  // pull needed on the lower half (N)
    const double tau = shear_force / area;
    const double sigma = world.walls[ids.plate].force.z() / area;
    sigma_sum += sigma;
    sigma_error_sum += std::abs(sigma - normal_stress) / normal_stress;
    r.peak_shear_stress = std::max(r.peak_shear_stress, tau);
    strength.add(offset, tau);
    done = offset >= b.shear_displacement;
    if (shear_steps % static_cast<std::uint64_t>(b.record_interval) == 0 || done) {
      const double plate_z = world.walls[ids.plate].origin.z();
      r.curve.add_row({world.time - ts, offset, shear_force, tau, sigma, plate_z, plate_z - z0,
                       static_cast<double>(world.contacts.touching_particle_contacts() +
                                           world.contacts.touching_wall_contacts()),
                       static_cast<double>(world.contacts.bonded_contacts())});
    }
    if (progress.active() && shear_steps % 2000 == 0) {
      char detail[112];
      std::snprintf(detail, sizeof detail, "shear %.2f mm, tau %.2f kPa, sigma %.2f kPa", offset * 1e3, tau * 1e-3,
                    sigma * 1e-3);
      progress.update(offset / b.shear_displacement, detail);
    }
    stepper.finish_step(world);
    ++shear_steps;
    snapshots.observe(world);
  }
  stepper.require_sound_state(world);  // a blow-up within the last check interval, too
  snapshots.record(world);
  r.snapshots = snapshots.take();
  progress.end_stage();
  shear_clock.count_steps(shear_steps, world.particles.size());
  r.stages.push_back(shear_clock.finish());
  r.shear_strength = strength.value();
  r.mean_normal_stress = sigma_sum / shear_steps;
  r.mean_normal_stress_error = sigma_error_sum / shear_steps;
  r.particles_outside = count_outside(world, b, world.walls[ids.lower[0]].origin.x() - x0,
                                      world.walls[ids.plate].origin.z());
  r.steps = steps + shear_steps;
  r.dt = world.dt;
  r.final_state = world.particles;
  r.bonds_broken_tension = stepper.events().bonds_broken_tension;
  r.bonds_broken_shear = stepper.events().bonds_broken_shear;
  return r;
}

}  // namespace colza
