#include "scenario/scene.hpp"

#include <utility>

#include "engine/energy.hpp"
#include "engine/stepper.hpp"
#include "scenario/bonds.hpp"
#include "scenario/snapshot_recorder.hpp"

namespace colza {

Table scene_table(const std::vector<std::int64_t>& particles, std::size_t walls, const ContactModel& model) {
  std::vector<std::string> names{"step", "time"}, units{"1", "s"};
  const char* axes[3] = {"x", "y", "z"};
  // "p3_", "w0_": appended, not "p" + std::to_string(...): GCC 12 warns (-Wrestrict) falsely on that form.
  const auto prefix = [](char kind, std::int64_t index) {
    std::string p(1, kind);
    p += std::to_string(index);
    p += '_';
    return p;
  };
  const auto add = [&](const std::string& name, const char* unit) {
    names.push_back(name);
    units.push_back(unit);
  };
  for (std::int64_t k : particles) {
    const std::string p = prefix('p', k);
    const std::pair<const char*, const char*> quantities[] = {{"", "m"}, {"v", "m/s"}, {"w", "rad/s"}, {"f", "N"}, {"t", "N m"}};
    for (const auto& [q, unit] : quantities)
      for (const char* a : axes) add(p + q + a, unit);
  }
  for (std::size_t w = 0; w < walls; ++w) {
    const std::string p = prefix('w', static_cast<std::int64_t>(w));
    const std::pair<const char*, const char*> quantities[] = {{"f", "N"}, {"", "m"}};
    for (const auto& [q, unit] : quantities)
      for (const char* a : axes) add(p + q + a, unit);
  }
  for (const char* e : {"contacts", "bonds"}) add(e, "1");
  for (const std::string& e : energy_columns(model)) add(e, "J");  // the model's channels (engine/energy.hpp)
  return Table(std::move(names), std::move(units));
}

SceneResult run_scene(const RunConfig& c, Progress& progress, double snapshot_interval) {
  SceneResult r;
  const SceneSpec& s = c.scene;
  Stepper stepper(make_physics(c));
  World world;
  for (const SceneParticle& sp : s.particles) {
    const Index i = world.particles.add(sp.position, sp.radius, c.particle.density, 0, sp.velocity, sp.angular_velocity);
    world.particles.fixed[i] = sp.fixed ? kPrescribed : kFree;
  }
  world.walls = s.walls;
  stepper.prepare(world);
  if (installs_bonds_at_a_moment(c.contact.bond_install)) r.bonds_installed = install_bonds(world, stepper, c.contact.bond_gap);
  r.dt = world.dt;
  r.series = scene_table(s.record_particles, world.walls.size(), c.contact);

  StageClock clock("scene");
  progress.start_stage("scene");
  const std::uint64_t total = static_cast<std::uint64_t>(s.steps);
  std::vector<double> row;
  SnapshotRecorder snapshots(snapshot_interval, world.time);
  std::uint64_t n = 0;
  bool last = false;
  for (; !last; ++n) {
    stepper.step(world, [&](const World& w) {
      // The stop condition looks at the unbalanced force of the previous step (known here).
      const bool condition = s.stop_unbalanced_force > 0.0 && n > 0 &&
                             stepper.last_integration().mean_unbalanced_force < s.stop_unbalanced_force;
      r.stopped_by_condition = condition && n + 1 < total;
      last = condition || n + 1 == total;
      if (n % static_cast<std::uint64_t>(s.record_interval) != 0 && !last) return;
      row.clear();
      row.push_back(static_cast<double>(w.step));
      row.push_back(w.time);
      const ParticleArrays& p = w.particles;
      for (std::int64_t k : s.record_particles)
        for (const Vec3* v : {&p.position[k], &p.velocity[k], &p.angular_velocity[k], &p.force[k], &p.torque[k]})
          row.insert(row.end(), v->data(), v->data() + 3);
      for (const Wall& wall : w.walls) {
        row.insert(row.end(), wall.force.data(), wall.force.data() + 3);
        row.insert(row.end(), wall.origin.data(), wall.origin.data() + 3);
      }
      row.insert(row.end(), {static_cast<double>(w.contacts.touching_particle_contacts() + w.contacts.touching_wall_contacts()),
                             static_cast<double>(w.contacts.bonded_contacts())});
      const std::vector<double> energies = energy_values(c.contact, stepper.energy(w), stepper.ledger());
      row.insert(row.end(), energies.begin(), energies.end());
      r.series.add_row(row);
    });
    snapshots.observe(world);
    if (n % 1000 == 0) progress.update(static_cast<double>(n) / total, "");
  }
  stepper.require_sound_state(world);  // a blow-up within the last check interval, too
  snapshots.record(world);
  r.snapshots = snapshots.take();
  progress.end_stage();
  clock.count_steps(n, world.particles.size());
  r.stages.push_back(clock.finish());
  r.steps = n;
  r.final_state = world.particles;
  return r;
}

}  // namespace colza
