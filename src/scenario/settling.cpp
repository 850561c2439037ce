#include "scenario/settling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "io/format_number.hpp"
#include "io/packing_file.hpp"
#include "neighbour/spatial_order.hpp"

namespace colza {

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
        r.converged = true;
        break;
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
  stepper.set_integration_sums(caller_sums);
  stepper.set_between_halves(caller_between);
  stepper.require_sound_state(world);  // a blow-up within the last check interval, too
  progress.end_stage();
  r.simulated_time = world.time - t0;
  return r;
}

std::size_t discard_above(World& world, Stepper& stepper, double z_top) {
  ParticleArrays& p = world.particles;
  std::vector<std::uint8_t> keep(p.size(), 1);
  std::size_t removed = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.position[i].z() + p.radius[i] > z_top) {
      keep[i] = 0;
      ++removed;
    }
  const std::vector<Index> old_to_new = p.compact(keep);
  world.contacts.renumber_particles(old_to_new);
  stepper.invalidate_neighbours();
  return removed;
}

void store_in_space_order(World& world, Stepper& stepper) {
  ParticleArrays& p = world.particles;
  if (p.size() == 0) return;
  const double diameter = 2.0 * *std::max_element(p.radius.begin(), p.radius.end());
  const std::vector<Index> order = morton_cell_order(p, diameter);
  std::vector<Index> old_to_new(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) old_to_new[order[k]] = static_cast<Index>(k);
  p.permute(order);
  world.contacts.renumber_particles(old_to_new);
  stepper.invalidate_neighbours();
}

std::size_t place_generated_sample(World& world, const RunConfig& c, const GenerationRegion& region,
                                   const std::string& height_key) {
  GenerationRequest req;
  req.region = region;
  req.count = static_cast<std::size_t>(c.sample.count);
  req.diameter_min = c.particle.diameter_min;
  req.diameter_max = c.particle.diameter_max;
  req.seed = c.seed;
  req.max_attempts = static_cast<std::uint64_t>(c.sample.max_placement_attempts);
  const std::vector<PackedSphere> spheres = generate_spheres(req);
  if (spheres.size() < req.count)
    throw ConfigError(c.origin_of("sample.count"), "sample.count",
                      "only " + std::to_string(spheres.size()) + " of " + std::to_string(req.count) +
                          " spheres fit without overlap in the generation volume; lower sample.count or raise " +
                          height_key);
  for (const PackedSphere& s : spheres) world.particles.add(s.position, s.radius, c.particle.density);
  return spheres.size();
}

ParticleArrays sample_at_rest(const ParticleArrays& from_settled, double density) {
  ParticleArrays at_rest;
  for (std::size_t i = 0; i < from_settled.size(); ++i)
    at_rest.add(from_settled.position[i], from_settled.radius[i], density);
  return at_rest;
}

ParticleArrays sample_from_packing(const std::string& file, const std::string& key, double density) {
  ParticleArrays sample;
  for (const PackedSphere& s : read_packing(file, key)) sample.add(s.position, s.radius, density);
  return sample;
}

SettleResult settle_generated_sample(World& world, Stepper& stepper, const SampleSpec& sample, Progress& progress) {
  store_in_space_order(world, stepper);
  stepper.prepare(world);
  stepper.set_integration_sums({.unbalanced = true, .damping_work = false});
  return settle(world, stepper, sample.settle_unbalanced_force, sample.settle_max_time,
                static_cast<std::uint64_t>(sample.settle_check_interval), progress);
}

std::size_t install_bonds(World& world, Stepper& stepper, double gap) {
  if (!(gap < stepper.physics().skin)) {
    std::ostringstream why;
    why.precision(15);  // as the config check's message: a gap a hair above the skin must not print as it
    why << "bond gap " << gap << " m is not below the Verlet skin " << stepper.physics().skin << " m";
    throw std::invalid_argument(why.str());
  }
  // A pair that was not a candidate at the last build may have closed by up to the skin since
  // (each sphere moves at most skin/2 between builds): only a fresh list holds every pair
  // whose gap is below the skin.
  stepper.rebuild_neighbours(world);
  const ParticleArrays& p = world.particles;
  auto& pairs = world.contacts.particle_pairs;
  std::size_t installed = 0, new_contacts = 0;
  for (std::size_t c = 0; c < pairs.size(); ++c) {
    const Index i = pairs.first[c], j = pairs.second[c];
    const Vec3 d = p.position[j] - p.position[i];
    const double dist = d.norm();
    const double overlap = p.radius[i] + p.radius[j] - dist;
    if (overlap < -gap) continue;
    ContactHistory& h = pairs.history[c];
    if (!h.touching) {  // a pair within the gap tolerance becomes a (bonded) contact now
      h.reset();
      h.touching = 1;
      h.normal = d / dist;
      ++new_contacts;
    }
    if (!h.bonded) {
      h.bonded = 1;
      ++installed;
    }
  }
  // New contacts stiffen their spheres (k_i grows by kn + ks each), so the critical time step
  // may have dropped: evaluate it now rather than at the next recompute_interval. Overlaps
  // count too: right after prepare() (a packing read from a file) no force pass has flagged
  // the wall contacts, which the flags alone would leave out.
  if (new_contacts > 0) stepper.update_time_step(world, CountedContacts::kTouchingOrOverlapping);
  return installed;
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
