// Sample preparation shared by the oedometer and the shear box: generating the configured
// sample, the sample at rest a test starts from (from a settled world or a packing file),
// discarding spheres above a rim, and storing the particles in space order.
#pragma once
#include <string>

#include "config/run_config.hpp"
#include "engine/stepper.hpp"
#include "scenario/generation.hpp"

namespace colza {

// Generates the configured sample (sample.count spheres of particle.diameter_min ..
// diameter_max, seed, sample.max_placement_attempts) in `region` and adds it to the world.
// When not all fit, a ConfigError names sample.count and advises raising `height_key` (the
// generation volume's height). Returns the number placed.
std::size_t place_generated_sample(World& world, const RunConfig& c, const GenerationRegion& region,
                                   const std::string& height_key);

// The sample a test starts from: positions and radii only, at rest, without contact
// histories, exactly what its packing file gives back. `from_settled`: a settled world's
// free particles (fixed ones, a glued base, are not the sample); `from_packing`: a packing file (`key`: its config key, for errors).
ParticleArrays sample_at_rest(const ParticleArrays& from_settled, double density);
ParticleArrays sample_from_packing(const std::string& file, const std::string& key, double density);

// Removes the spheres whose top (z + r) lies above `z_top`; their contacts go with them.
// Returns the number removed.
std::size_t discard_above(World& world, Stepper& stepper, double z_top);

// Stores the particles in the Morton order of their cells (neighbour/spatial_order.hpp),
// cells of one largest diameter, so that contacts join bodies close in memory; contacts and
// their history follow the renumbering. Called on generated samples after generation and
// after the discard; a packing read from a file keeps the file's order.
void store_in_space_order(World& world, Stepper& stepper);

}  // namespace colza
