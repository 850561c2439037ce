// The stepper's cold half: setting the time step (fixed, or a safety factor times the
// critical estimate, integrate/time_step.hpp) and the checks that stop a run whose motion
// has blown up (core/unstable_motion.hpp, engine/motion_limits.hpp). The step itself is in
// engine/stepper.cpp, the force loops in engine/force_loops_body.hpp.
#include <cstdio>
#include <string>

#include "core/unstable_motion.hpp"
#include "engine/motion_limits.hpp"
#include "engine/stepper.hpp"
#include "integrate/time_step.hpp"

namespace colza {

void Stepper::prepare(World& world) {
  require_finite_positions(world);
  world.contacts.set_slot_state_layout(slot_state_layout_);
  rebuild_neighbours(world);
  // Evaluated whatever the dt setting: a fixed dt is judged against it if the motion blows up.
  critical_dt_at_prepare_ = critical_time_step(world.particles, world.walls, world.contacts, pairs_,
                                               CountedContacts::kTouchingOrOverlapping, physics_.model);
  prepared_at_time_ = world.time;
  set_time_step(world, critical_dt_at_prepare_);
}

void Stepper::update_time_step(World& world, CountedContacts counted) {
  set_time_step(world, physics_.time_step.automatic
                           ? critical_time_step(world.particles, world.walls, world.contacts, pairs_, counted, physics_.model)
                           : 0.0);
}

void Stepper::set_time_step(World& world, double critical) {
  world.dt = physics_.time_step.automatic ? physics_.time_step.safety_factor * critical : physics_.time_step.fixed_dt;
  time_step_set_at_ = world.step;
}

void Stepper::throw_unstable_motion(const World& world, const std::string& what, const char* remedy) const {
  const TimeStepSettings& ts = physics_.time_step;
  char advice[400];
  std::snprintf(advice, sizeof advice,
                "The time step is %.6g s (%s) against a critical estimate of %.6g s at the start of the stage; %s%s",
                world.dt, ts.automatic ? "automatic" : "fixed by integration.time_step", critical_dt_at_prepare_,
                ts.automatic ? "lower integration.safety_factor, or check the stiffnesses, densities and radii"
                             : "lower integration.time_step below the critical estimate",
                remedy);
  throw UnstableMotion(what + advice, fixed_time_step_too_large());
}

void Stepper::require_finite_positions(const World& world) const {
  const std::optional<std::size_t> i = first_non_finite_position(world.particles);
  if (!i) return;
  char text[240];
  std::snprintf(text, sizeof text, "the motion became unstable: particle %zu has a non-finite position at step %llu (t = %.6g s). ",
                *i, static_cast<unsigned long long>(world.step), world.time);
  throw_unstable_motion(world, text);
}

void Stepper::require_sound_state(const World& world) const {
  require_finite_positions(world);
  require_bounded_speeds(world);
  const DeepestOverlap d = deepest_overlap(world.particles, world.walls, world.contacts, pairs_, physics_.model);
  if (!(d.ratio > kOverlapLimit)) return;
  char pair[96], text[400];
  if (d.with_wall) std::snprintf(pair, sizeof pair, "particle %zu and wall '%s'", d.first, world.walls[d.second].name.c_str());
  else std::snprintf(pair, sizeof pair, "particles %zu and %zu", d.first, d.second);
  std::snprintf(text, sizeof text,
                "the motion became unstable, or the contacts are far too soft for the load: %s overlap by %.3g m, "
                "%.0f %% of %s radius, at step %llu (t = %.6g s): spheres passing through each other, which no contact "
                "model describes. ",
                pair, d.overlap, 100.0 * d.ratio, d.with_wall ? "the particle's" : "the smaller",
                static_cast<unsigned long long>(world.step), world.time);
  throw_unstable_motion(world, text, "; or raise the stiffnesses");
}

void Stepper::require_bounded_speeds(const World& world) const {
  // A free fall since the stage began gives at most |g| t (damping only slows it), plus
  // 10 m/s for a particle thrown in a scene or by a wall.
  const double free_flight_speed = physics_.integrator.gravity.norm() * (world.time - prepared_at_time_) + 10.0;
  const FastestParticle f = fastest_particle(world.particles, world.contacts, world.dt, free_flight_speed);
  if (!(f.ratio > kStepLimit)) return;
  char text[320];
  std::snprintf(text, sizeof text,
                "the motion became unstable: particle %zu moves %.3g m/s, %.3g times its radius in one step, at step %llu "
                "(t = %.6g s), so it could pass through a neighbour between two force evaluations. ",
                f.index, f.speed, f.ratio, static_cast<unsigned long long>(world.step), world.time);
  throw_unstable_motion(world, text);
}

}  // namespace colza
