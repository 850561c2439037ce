#include "scenario/settling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/format_number.hpp"
#include "scenario/sample_preparation.hpp"

namespace colza {

namespace {

// The share of the free particles with no touching contact, after a force pass.
double share_touching_nothing(const World& world) {
  const ParticleArrays& p = world.particles;
  const std::vector<std::uint8_t> touches = world.contacts.particles_in_pairs(p.size(), /*touching_only=*/true);
  std::size_t free = 0, alone = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.fixed[i]) continue;
    ++free;
    alone += touches[i] == 0;
  }
  return free > 0 ? static_cast<double>(alone) / static_cast<double>(free) : 0.0;
}

}  // namespace

SettleResult settle(World& world, Stepper& stepper, double threshold, double max_time,
                    std::uint64_t check_interval, Progress& progress) {
  SettleResult r;
  const double t0 = world.time;
  progress.start_stage("settling");
  const double log_start = std::log10(std::max(threshold * 10.0, 1e-30));
  // The unbalanced force is read on check steps only (the loop ends on one): the other
  // steps skip its sum. The damping work is summed as the caller asked (its ledger).
  const IntegrationSums caller_sums = stepper.integration_sums();
  // Nothing is read between the halves of a step here: on the steps without sums the
  // threaded force loop may advance the particles itself (Stepper::set_between_halves).
  const Stepper::BetweenHalves caller_between = stepper.between_halves();
  stepper.set_between_halves(Stepper::BetweenHalves::kWallsOnly);
  while (true) {
    const bool check = (r.steps + 1) % check_interval == 0;
    stepper.set_integration_sums({.unbalanced = check, .damping_work = caller_sums.damping_work});
    stepper.step(world);
    ++r.steps;
    if (check) {
      r.mean_unbalanced_force = stepper.last_integration().mean_unbalanced_force;
      if (r.mean_unbalanced_force < threshold) {
        r.share_touching_nothing = share_touching_nothing(world);
        if (r.share_touching_nothing <= kMaxShareTouchingNothing) {
          r.converged = true;
          break;
        }
      }
      if (world.time - t0 >= max_time) break;
      if (progress.active()) {
        // Progress on a log scale of the unbalanced force, from 10x the threshold down to it.
        const double f = std::clamp((log_start - std::log10(r.mean_unbalanced_force)) / 1.0, 0.0, 1.0);
        char detail[96];
        std::snprintf(detail, sizeof detail, "t = %.3f s, mean unbalanced force %.2e N (target %.1e)",
                      world.time - t0, r.mean_unbalanced_force, threshold);
        progress.update(f > 0.0 ? f : -1.0, detail);
      }
    }
  }
  if (!r.converged) r.share_touching_nothing = share_touching_nothing(world);  // the last check's, for the warning
  stepper.set_integration_sums(caller_sums);
  stepper.set_between_halves(caller_between);
  stepper.require_sound_state(world);  // a blow-up within the last check interval, too
  progress.end_stage();
  r.simulated_time = world.time - t0;
  return r;
}

SettleResult settle_generated_sample(World& world, Stepper& stepper, const SampleSpec& sample, Progress& progress) {
  store_in_space_order(world, stepper);
  stepper.prepare(world);
  stepper.set_integration_sums({.unbalanced = true, .damping_work = false});
  return settle(world, stepper, sample.settle_unbalanced_force, sample.settle_max_time,
                static_cast<std::uint64_t>(sample.settle_check_interval), progress);
}

NewSample settle_new_sample(World& world, const RunConfig& c, const GenerationRegion& region,
                            const std::string& height_key, double rim, const std::string& where, Progress& progress,
                            StageClock& clock) {
  Stepper stepper(make_physics(c));
  NewSample s;
  s.generated = place_generated_sample(world, c, region, height_key);
  s.settling = settle_generated_sample(world, stepper, c.sample, progress);
  clock.count_steps(s.settling.steps, s.generated);
  discard_above(world, stepper, rim);
  store_in_space_order(world, stepper);
  s.at_rest = sample_at_rest(world.particles, c.particle.density);
  if (s.at_rest.size() == 0) throw no_sphere_left_error(c, stepper, where);
  return s;
}

ConfigError no_sphere_left_error(const RunConfig& c, const Stepper& stepper, const std::string& where) {
  const double critical = stepper.critical_time_step_at_prepare();
  if (stepper.fixed_time_step_too_large())
    return ConfigError(c.origin_of("integration.time_step"), "integration.time_step",
                       "no sphere is left " + where + " after settling: the fixed time step " +
                           format_significant(c.integration.time_step, 6) + " s exceeds the critical estimate " +
                           format_significant(critical, 6) +
                           " s, so the motion blew up and the spheres flew off; use \"auto\" or a smaller step");
  return ConfigError(c.origin_of("sample.count"), "sample.count", "no sphere is left " + where + " after settling");
}

}  // namespace colza
