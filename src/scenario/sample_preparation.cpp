#include "scenario/sample_preparation.hpp"

#include <algorithm>

#include "config/config_error.hpp"
#include "io/packing_file.hpp"
#include "neighbour/spatial_order.hpp"

namespace colza {

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
    if (!from_settled.fixed[i]) at_rest.add(from_settled.position[i], from_settled.radius[i], density);
  return at_rest;
}

ParticleArrays sample_from_packing(const std::string& file, const std::string& key, double density) {
  ParticleArrays sample;
  for (const PackedSphere& s : read_packing(file, key)) sample.add(s.position, s.radius, density);
  return sample;
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

}  // namespace colza
