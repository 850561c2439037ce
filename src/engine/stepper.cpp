// The stepper's hot half: the two halves of a step around the force loops (engine/force_loops.hpp,
// compiled once per instruction set and chosen by core/kernel_isa.hpp). The time step and the
// stability checks are in engine/stepper_stability.cpp.
#include "engine/stepper.hpp"

#include "core/concurrent.hpp"
#include "core/interrupt.hpp"
#include "engine/force_loops.hpp"
#include "core/kernel_isa.hpp"

namespace colza {

Stepper::Stepper(PhysicsSettings physics)
    : physics_(std::move(physics)),
      slot_state_layout_(slot_state_layout(physics_.model)),
      pairs_(physics_.particle_materials, physics_.wall_materials, physics_.stiffness_rule, physics_.wall_friction),
      neighbours_(physics_.skin) {}

namespace {

// Below this many candidate pairs per thread the force loop runs serially (threading
// overhead would dominate; also keeps tiny unit-test systems on the reference path).
constexpr std::size_t kMinPairsPerThread = 1024;

}  // namespace

void Stepper::compute_forces(World& world) {
  if (world.contacts.slot_state_layout().stride != slot_state_layout_.stride)
    world.contacts.set_slot_state_layout(slot_state_layout_);
  const int threads = worker_threads_here();
  const bool threaded = threads > 1 && world.contacts.particle_pairs.size() >= kMinPairsPerThread * 2;
  if (threaded) {
    if (!partition_.matches(world.contacts, world.particles.size(), world.walls.size(), threads))
      partition_.build(world.contacts, world.particles.size(), world.walls.size(), threads);
    ++threaded_force_steps_;
  }
  // The motion goes into the threaded force loop when nothing reads the particles between the
  // halves of the step and no integration sum is wanted (set_between_halves).
  integrated_with_forces_ =
      threaded && between_halves_ == BetweenHalves::kWallsOnly && !sums_.unbalanced && !sums_.damping_work;
  const IntegratorSettings* motion = integrated_with_forces_ ? &physics_.integrator : nullptr;
  if (integrated_with_forces_) ++motion_with_forces_steps_;
  // The energy ledger is kept in the steps that sum the damping work (its one integrator
  // term): only then is the slip energy computed and summed (set_integration_sums).
  detail::ForceLoopTotals totals;
  const ForceLoopJob job{physics_, world, pairs_, threaded ? &partition_ : nullptr, motion, sums_.damping_work};
  force_loops_for(active_kernel_isa())(job, totals);
  ledger_.slip_dissipated += totals.slip;
  ledger_.bond_break_lost += totals.broken;
  ledger_.shear_break_released += totals.released;
  ledger_.wall_work += totals.wall_power * world.dt;
  ledger_.rolling_dissipated += totals.rolling;
  ledger_.viscous_dissipated += totals.viscous;
  ledger_.plastic_dissipated += totals.plastic;
  ledger_.shear_stiffness_change += totals.stiffness_change;
  events_.bonds_broken_tension += totals.broken_tension;
  events_.bonds_broken_shear += totals.broken_shear;
}

void Stepper::rebuild_neighbours(World& world) {
  neighbours_.invalidate();
  neighbours_.rebuild(world.particles, world.walls, world.contacts, worker_threads_here());
}

void Stepper::begin_step(World& world) {
  throw_if_interrupted();  // Ctrl-C or SIGTERM: unwind between steps (core/interrupt.hpp)
  if (physics_.time_step.automatic && physics_.time_step.recompute_interval > 0 &&
      world.step % physics_.time_step.recompute_interval == 0 && time_step_set_at_ != world.step)
    update_time_step(world);
  // Finite positions: before a rebuild (the cell grid cannot index a non-finite coordinate)
  // and every kFiniteCheckInterval steps (a NaN never asks for a rebuild).
  const bool rebuild = neighbours_.needs_rebuild(world.particles, world.walls);
  if (world.step % kFiniteCheckInterval == 0) require_sound_state(world);
  else if (rebuild) require_finite_positions(world);
  if (rebuild) neighbours_.rebuild(world.particles, world.walls, world.contacts, worker_threads_here());
  compute_forces(world);
}

void Stepper::finish_step(World& world) {
  if (integrated_with_forces_) {  // the motion is done; no sum was wanted
    last_integration_ = report_without_sums();
  } else {
    last_integration_ =
        integrate_step(world.particles, physics_.integrator, world.dt, worker_threads_here(), unbalanced_scratch_, sums_);
  }
  ledger_.damping_dissipated += last_integration_.damping_work;
  for (auto& wall : world.walls) wall.origin += world.dt * wall.velocity;
  world.time += world.dt;
  ++world.step;
}

void Stepper::run(World& world, std::uint64_t steps) {
  for (std::uint64_t s = 0; s < steps; ++s) step(world);
}

}  // namespace colza
