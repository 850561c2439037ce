// One DEM cycle (YADE's pipeline, PFC's cycle):
//   neighbour lists (if stale) -> contact geometry -> contact law -> forces on bodies
//   -> leapfrog integration with local damping -> walls move -> clock advances.
#pragma once
#include <optional>
#include <string>
#include <vector>
#include "engine/energy.hpp"
#include "engine/force_partition.hpp"
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

  // Forces a neighbour rebuild and sets world.dt from the settings (fixed, or the critical
  // estimate counting the pairs that overlap now as contacts: no force pass has marked them
  // yet). The periodic re-evaluation does not repeat it at the same step.
  // Steps check the state every kFiniteCheckInterval steps (require_sound_state) and that
  // positions are finite before each neighbour rebuild, and throw UnstableMotion
  // (core/unstable_motion.hpp) naming the particle, dt and the critical estimate of the last
  // prepare() when it is not sound.
  void prepare(World& world);
  static constexpr std::uint64_t kFiniteCheckInterval = 100;
  // Throws UnstableMotion when a position is not finite, a particle moves more than
  // kStepLimit of its radius in a step or a contact overlaps by more than kOverlapLimit of a
  // radius (engine/motion_limits.hpp). Steps call it every
  // kFiniteCheckInterval steps; stages call it when they end, so a motion that blows up
  // within fewer steps (a stop force reached at once) is caught too.
  void require_sound_state(const World& world) const;
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
  // Builds the candidate lists now: afterwards every pair closer than the skin is a candidate
  // (install_bonds needs that). No result depends on when the lists are built.
  void rebuild_neighbours(World& world);
  // Sets world.dt from the settings, counting the contacts the last force pass marked, or
  // also the pairs that overlap now (for a state no force pass has seen in full).
  void update_time_step(World& world, CountedContacts counted = CountedContacts::kTouching);
  // Stored plus dissipated energies: constant (up to O(dt^2)) when the bookkeeping is complete.
  EnergySnapshot energy(const World& world) const { return measure_energy(world, physics_, pairs_); }

  // The critical time step estimate (no safety factor, s) when prepare() was last called.
  double critical_time_step_at_prepare() const { return critical_dt_at_prepare_; }
  // A time step fixed by the settings above that estimate: a blow-up is then the
  // configuration's doing (integration.time_step).
  bool fixed_time_step_too_large() const {
    return !physics_.time_step.automatic && physics_.time_step.fixed_dt > critical_dt_at_prepare_;
  }
  const PhysicsSettings& physics() const { return physics_; }
  const PairTable& pairs() const { return pairs_; }
  const IntegrationReport& last_integration() const { return last_integration_; }
  // The sums over particles the integration reports (integrate/integrator.hpp); all by
  // default. A stage that reads neither the unbalanced force nor the damping energy turns
  // them off; the motion is the same. The damping work is the energy ledger's integrator
  // term: with it off the ledger is not kept at all, so the force loop skips the slip energy
  // too (one division per sliding contact and a serial sum); bond-break energies and counts
  // are still summed (they are rare, and results report the counts).
  void set_integration_sums(IntegrationSums sums) { sums_ = sums; }
  IntegrationSums integration_sums() const { return sums_; }
  // What the caller reads or writes between begin_step and finish_step (or in a step's
  // observer). kWallsOnly promises that it touches only the walls and the contact store,
  // never the particles: the threaded force loop may then advance each thread's particles
  // as soon as their forces are final, inside the same parallel region (one fork and join
  // fewer per step), when no integration sum is wanted; particle states after begin_step are
  // then already those of t + dt. The motion is the same bits either way.
  enum class BetweenHalves { kParticles, kWallsOnly };
  void set_between_halves(BetweenHalves b) { between_halves_ = b; }
  BetweenHalves between_halves() const { return between_halves_; }
  const EnergyLedger& ledger() const { return ledger_; }
  const ContactEvents& events() const { return events_; }  // cumulative
  const NeighbourSearch& neighbours() const { return neighbours_; }
  // Steps whose forces took the threaded path (engine/force_partition.hpp); for tests.
  std::uint64_t threaded_force_steps() const { return threaded_force_steps_; }
  // Steps whose motion was done inside the threaded force loop (set_between_halves); for tests.
  std::uint64_t motion_with_forces_steps() const { return motion_with_forces_steps_; }

 private:
  void compute_forces(World& world);
  void require_finite_positions(const World& world) const;
  void require_bounded_speeds(const World& world) const;
  // Throws UnstableMotion: `what` happened, then what the time step was against the critical
  // estimate at prepare() and what to change, then `remedy` (e.g. "; or raise the stiffnesses").
  [[noreturn]] void throw_unstable_motion(const World& world, const std::string& what, const char* remedy = "") const;
  // world.dt = safety factor x `critical` (automatic), or the fixed dt (`critical` unused).
  void set_time_step(World& world, double critical);
  PhysicsSettings physics_;
  SlotStateLayout slot_state_layout_;  // the model's per-contact slot state (contact/slot_state.hpp)
  PairTable pairs_;
  NeighbourSearch neighbours_;
  IntegrationReport last_integration_;
  IntegrationSums sums_;
  BetweenHalves between_halves_ = BetweenHalves::kParticles;
  std::optional<std::uint64_t> time_step_set_at_;  // world.step at which dt was last set
  double critical_dt_at_prepare_ = 0.0;  // s, the critical estimate (no safety factor) at prepare()
  double prepared_at_time_ = 0.0;  // world.time at the last prepare() (s)
  bool integrated_with_forces_ = false;  // this step's motion was done by the threaded force loop
  EnergyLedger ledger_;
  ContactEvents events_;

  std::uint64_t threaded_force_steps_ = 0;
  std::uint64_t motion_with_forces_steps_ = 0;
  ForcePartition partition_;               // threaded force path (engine/force_partition.hpp)
  std::vector<double> unbalanced_scratch_;  // per particle (integrator)
};

}  // namespace colza
