#include "engine/stepper.hpp"

#include <cmath>
#include <variant>

#include "contact/contact_law.hpp"

namespace colza {

Stepper::Stepper(PhysicsSettings physics)
    : physics_(std::move(physics)),
      pairs_(physics_.particle_materials, physics_.wall_materials, physics_.stiffness_rule),
      neighbours_(physics_.skin) {}

void Stepper::prepare(World& world) {
  neighbours_.invalidate();
  neighbours_.rebuild(world.particles, world.walls, world.contacts);
  update_time_step(world);
}

void Stepper::update_time_step(World& world) {
  world.dt = physics_.time_step.automatic
                 ? physics_.time_step.safety_factor * critical_time_step(world.particles, world.walls, world.contacts, pairs_)
                 : physics_.time_step.fixed_dt;
}

namespace {

struct ForceLoopTotals {
  double slip = 0.0, broken = 0.0, wall_power = 0.0;
  std::uint64_t broken_tension = 0, broken_shear = 0;
};

inline void count_event(ContactEvent e, ForceLoopTotals& t) {
  if (e == ContactEvent::kBondBrokeTension) ++t.broken_tension;
  if (e == ContactEvent::kBondBrokeShear) ++t.broken_shear;
}

// The force loop, compiled once per combination of slot implementations.
template <class Normal, class Tangential, class Bond>
ForceLoopTotals force_loop(const Normal& normal_law, const Tangential& tangential_law, const Bond& bond_law,
                           bool bond_new_contacts, World& world, const PairTable& pairs) {
  ForceLoopTotals totals;
  ParticleArrays& p = world.particles;
  const double dt = world.dt;
  const double half_dt = 0.5 * dt;

  auto& pp = world.contacts.particle_pairs;
  const std::size_t n_pairs = pp.size();
  for (std::size_t c = 0; c < n_pairs; ++c) {
    const Index i = pp.first[c], j = pp.second[c];
    ContactHistory& h = pp.history[c];
    const Vec3 d = p.position[j] - p.position[i];
    const double ri = p.radius[i], rj = p.radius[j];
    const double dist2 = d.squaredNorm();
    const double reach = ri + rj;
    if (!h.touching && dist2 >= reach * reach) continue;  // candidate, not in contact
    const double dist = std::sqrt(dist2);
    ContactKinematics k;
    k.normal = d / dist;
    k.overlap = reach - dist;
    const Vec3 point = p.position[i] + (ri - 0.5 * k.overlap) * k.normal;  // middle of the overlap
    const Vec3 arm_i = point - p.position[i], arm_j = point - p.position[j];
    const Vec3 rel_vel = (p.velocity[j] + p.angular_velocity[j].cross(arm_j)) -
                         (p.velocity[i] + p.angular_velocity[i].cross(arm_i));
    k.shear_increment = (rel_vel - rel_vel.dot(k.normal) * k.normal) * dt;
    k.twist_angle = half_dt * (p.angular_velocity[i] + p.angular_velocity[j]).dot(h.normal);  // previous normal (zero for a new contact)
    const PairParameters& q = pairs.particle_particle(p.material[i], p.material[j]);
    const double stored_before = h.touching ? normal_law.energy(q, h.normal_force) + tangential_law.energy(q, h.shear_force) : 0.0;
    const ContactOutcome out = evaluate_contact(normal_law, tangential_law, bond_law, q, k, h, bond_new_contacts);
    if (!out.carries_force) {
      totals.broken += stored_before;  // energy of a contact that vanished this step
      count_event(out.event, totals);
      continue;
    }
    count_event(out.event, totals);
    totals.slip += out.slip_dissipation;
    const Vec3& f = out.force_on_2;
    p.force[j] += f;
    p.force[i] -= f;
    p.torque[j] += arm_j.cross(f);
    p.torque[i] -= arm_i.cross(f);
  }

  auto& pw = world.contacts.wall_pairs;
  for (auto& wall : world.walls) {
    wall.force.setZero();
    wall.contact_count = 0;
  }
  const std::size_t n_wall_pairs = pw.size();
  for (std::size_t c = 0; c < n_wall_pairs; ++c) {
    Wall& wall = world.walls[pw.wall[c]];
    const Index i = pw.particle[c];
    ContactHistory& h = pw.history[c];
    const WallContactGeometry g = wall_sphere_geometry(wall, p.position[i], p.radius[i]);
    if (!g.in_range || (!h.touching && g.overlap < 0.0)) {
      if (h.touching) h.reset();
      continue;
    }
    ContactKinematics k;
    k.normal = g.normal;
    k.overlap = g.overlap;
    const Vec3 arm = g.point - p.position[i];
    const Vec3 rel_vel = (p.velocity[i] + p.angular_velocity[i].cross(arm)) - wall.velocity;
    k.shear_increment = (rel_vel - rel_vel.dot(k.normal) * k.normal) * dt;
    k.twist_angle = half_dt * p.angular_velocity[i].dot(h.normal);  // previous normal
    const PairParameters& q = pairs.particle_wall(p.material[i], wall.material);
    const ContactOutcome out = evaluate_contact(normal_law, tangential_law, NoBond{}, q, k, h, false);
    if (!out.carries_force) continue;
    totals.slip += out.slip_dissipation;
    const Vec3& f = out.force_on_2;
    p.force[i] += f;
    p.torque[i] += arm.cross(f);
    wall.force -= f;
    ++wall.contact_count;
    totals.wall_power += f.dot(wall.velocity);  // power of the wall on the particle (W)
  }
  return totals;
}

}  // namespace

void Stepper::compute_forces(World& world) {
  world.particles.clear_forces();
  const bool bond_new = physics_.model.bond_install == BondInstallMoment::kOnNewContacts;
  const ForceLoopTotals totals = std::visit(
      [&](const auto& normal, const auto& tangential, const auto& bond) {
        return force_loop(normal, tangential, bond, bond_new, world, pairs_);
      },
      physics_.model.normal, physics_.model.tangential, physics_.model.bond);
  ledger_.slip_dissipated += totals.slip;
  ledger_.bond_break_lost += totals.broken;
  ledger_.wall_work += totals.wall_power * world.dt;
  events_.bonds_broken_tension += totals.broken_tension;
  events_.bonds_broken_shear += totals.broken_shear;
}

void Stepper::begin_step(World& world) {
  if (physics_.time_step.automatic && physics_.time_step.recompute_interval > 0 &&
      world.step % physics_.time_step.recompute_interval == 0)
    update_time_step(world);
  if (neighbours_.needs_rebuild(world.particles, world.walls))
    neighbours_.rebuild(world.particles, world.walls, world.contacts);
  compute_forces(world);
}

void Stepper::finish_step(World& world) {
  last_integration_ = integrate_step(world.particles, physics_.integrator, world.dt);
  ledger_.damping_dissipated += last_integration_.damping_work;
  for (auto& wall : world.walls) wall.origin += world.dt * wall.velocity;
  world.time += world.dt;
  ++world.step;
}

void Stepper::run(World& world, std::uint64_t steps) {
  for (std::uint64_t s = 0; s < steps; ++s) step(world);
}

}  // namespace colza
