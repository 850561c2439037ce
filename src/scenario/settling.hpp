// Settling under gravity to a mean unbalanced force, shared by the oedometer and the shear
// box, and the error for a sample that lost every sphere while settling. The other steps of
// a sample's preparation: scenario/sample_preparation.hpp; contact bonds: scenario/bonds.hpp.
#pragma once
#include <cstdint>
#include <string>

#include "config/config_error.hpp"
#include "config/run_config.hpp"
#include "engine/stepper.hpp"
#include "io/progress.hpp"

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

}  // namespace colza
