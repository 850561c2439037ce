// Sample preparation steps shared by the oedometer and the shear box:
// settling under gravity to a mean unbalanced force, discarding spheres above a rim,
// and installing contact bonds at a chosen moment.
#pragma once
#include "config/config_error.hpp"
#include "config/run_config.hpp"
#include "engine/stepper.hpp"
#include "io/progress.hpp"
#include "scenario/generation.hpp"

namespace colza {

struct SettleResult {
  bool converged = false;
  std::uint64_t steps = 0;
  double simulated_time = 0.0;         // s
  double mean_unbalanced_force = 0.0;  // N, at the end
};

// Runs until the mean unbalanced force per particle (|F_contact + m g|, mean over free
// particles; PFC's measure) falls below `threshold`, checked every `check_interval` steps,
// or until `max_time` of simulated time has passed.
SettleResult settle(World& world, Stepper& stepper, double threshold, double max_time,
                    std::uint64_t check_interval, Progress& progress);

// Generates the configured sample (sample.count spheres of particle.diameter_min ..
// diameter_max, seed, sample.max_placement_attempts) in `region` and adds it to the world.
// When not all fit, a ConfigError names sample.count and advises raising `height_key` (the
// generation volume's height). Returns the number placed.
std::size_t place_generated_sample(World& world, const RunConfig& c, const GenerationRegion& region,
                                   const std::string& height_key);

// The sample a test starts from: positions and radii only, at rest, without contact
// histories, exactly what its packing file gives back. `from_settled`: a settled world's
// particles; `from_packing`: a packing file (`key`: its config key, for errors).
ParticleArrays sample_at_rest(const ParticleArrays& from_settled, double density);
ParticleArrays sample_from_packing(const std::string& file, const std::string& key, double density);

// A freshly generated sample's preparation, the same for the oedometer and the shear box:
// stored in space order (store_in_space_order), the stepper prepared, then settled under
// gravity to the [sample] criterion (settle_unbalanced_force, settle_max_time,
// settle_check_interval) without an energy ledger (none is reported for settling).
SettleResult settle_generated_sample(World& world, Stepper& stepper, const SampleSpec& sample, Progress& progress);

// The error for a sample with no sphere left in its container after settling (`where`:
// "below the rim"). With a fixed time step above the critical estimate of the stage's start
// the motion blew up and the spheres flew off, so it names integration.time_step; otherwise
// sample.count.
ConfigError no_sphere_left_error(const RunConfig& c, const Stepper& stepper, const std::string& where);

// Removes the spheres whose top (z + r) lies above `z_top`; their contacts go with them.
// Returns the number removed.
std::size_t discard_above(World& world, Stepper& stepper, double z_top);

// Stores the particles in the Morton order of their cells (neighbour/spatial_order.hpp),
// cells of one largest diameter, so that contacts join bodies close in memory; contacts and
// their history follow the renumbering. Called on generated samples after generation and
// after the discard; a packing read from a file keeps the file's order.
void store_in_space_order(World& world, Stepper& stepper);

// Puts a contact bond on every particle-particle pair touching now (un >= -gap, m).
// Returns the number of bonds installed. The candidate lists are rebuilt first, so every pair
// with a gap below the stepper's Verlet skin is a candidate; a gap of the skin or wider
// cannot be honoured and throws std::invalid_argument (the config check refuses
// contact.bond_gap >= integration.verlet_skin before a run starts). Rebuilding the lists
// changes no result: forces are summed in pair order and a candidate that is not touching
// carries no force, so which pairs are candidates never shows in the physics. When a pair
// within the gap becomes a contact, the automatic time step is evaluated again at once
// (a new contact stiffens its spheres).
std::size_t install_bonds(World& world, Stepper& stepper, double gap);

}  // namespace colza
