// One DEM cycle (YADE's pipeline, PFC's cycle):
//   neighbour lists (if stale) -> contact geometry -> contact law -> forces on bodies
//   -> leapfrog integration with local damping -> walls move -> clock advances.
#pragma once
#include <vector>
#include "engine/energy.hpp"
#include "engine/pair_sinks.hpp"
#include "engine/world.hpp"
#include "neighbour/neighbour_search.hpp"

namespace colza {

// What happened to contacts in the last step.
struct ContactEvents {
  std::uint64_t bonds_broken_tension = 0;
  std::uint64_t bonds_broken_shear = 0;
};

class Stepper {
 public:
  explicit Stepper(PhysicsSettings physics);

  // Sets world.dt from the settings (fixed or critical estimate) and forces a neighbour rebuild.
  void prepare(World& world);
  void step(World& world) {
    begin_step(world);
    finish_step(world);
  }
  // Same, calling observer(world) between the force computation and the integration: the
  // observer sees positions x(t), velocities v(t - dt/2) and the forces of step t, which is
  // what a YADE PyRunner placed before NewtonIntegrator sees.
  template <class Observer>
  void step(World& world, Observer&& observer) {
    begin_step(world);
    observer(static_cast<const World&>(world));
    finish_step(world);
  }
  // The two halves of a step: time step update, neighbour lists and forces; then
  // integration, wall motion and the clock.
  void begin_step(World& world);
  void finish_step(World& world);
  void run(World& world, std::uint64_t steps);

  // Call after particles were added, removed or reordered, or walls added.
  void invalidate_neighbours() { neighbours_.invalidate(); }
  void update_time_step(World& world);
  // Stored plus dissipated energies: constant (up to O(dt^2)) when the bookkeeping is complete.
  EnergySnapshot energy(const World& world) const { return measure_energy(world, physics_, pairs_); }

  const PhysicsSettings& physics() const { return physics_; }
  const PairTable& pairs() const { return pairs_; }
  const IntegrationReport& last_integration() const { return last_integration_; }
  const EnergyLedger& ledger() const { return ledger_; }
  const ContactEvents& events() const { return events_; }  // cumulative
  const NeighbourSearch& neighbours() const { return neighbours_; }
  void rebuild_neighbours_now(World& world) { neighbours_.rebuild(world.particles, world.walls, world.contacts); }

 private:
  void compute_forces(World& world);
  // Per-particle gather lists of the particle pairs (threaded force path, see stepper.cpp).
  void update_gather_lists(const World& world);
  PhysicsSettings physics_;
  PairTable pairs_;
  NeighbourSearch neighbours_;
  IntegrationReport last_integration_;
  EnergyLedger ledger_;
  ContactEvents events_;

 public:
  // Scratch of the threaded force path (kept to avoid reallocation). For particle p,
  // entries[start[p] .. start[p + 1]) lists its particle pairs in pair order as
  // 2 c + role (role 0: p is body 2, role 1: p is body 1), and
  // wall_entries[wall_start[p] .. wall_start[p + 1]) its wall pairs in wall-pair order.
  struct GatherScratch {
    std::uint64_t revision = ~std::uint64_t{0};
    const Index* first_data = nullptr;
    std::size_t n_pairs = 0, n_particles = 0;
    std::vector<Index> start, entries;
    std::vector<Vec3> pair_force, torque_1, torque_2;  // per pair: F on 2, torque on 1, torque on 2
    std::vector<Index> wall_start, wall_entries;
    std::vector<Vec3> wall_force, wall_torque;          // per wall pair: force and torque on the particle
    std::vector<std::uint8_t> wall_carries;             // per wall pair: 1 when it carries force
    std::vector<double> unbalanced;                   // per particle (integrator)
    std::vector<detail::LogSink> chunk_logs;          // per work chunk of the force loop
  };

 private:
  GatherScratch gather_;
};

}  // namespace colza
