// Settling under gravity to a mean unbalanced force, shared by the oedometer and the shear
// box, and the error for a sample that lost every sphere while settling. The other steps of
// a sample's preparation: scenario/sample_preparation.hpp; contact bonds: scenario/bonds.hpp.
#pragma once
#include <cstdint>
#include <string>

#include "config/config_error.hpp"
#include "config/run_config.hpp"
#include "engine/stepper.hpp"
#include "core/stage_timing.hpp"
#include "io/progress.hpp"
#include "scenario/generation.hpp"

namespace colza {

struct SettleResult {
  bool converged = false;
  std::uint64_t steps = 0;
  double simulated_time = 0.0;         // s
  double mean_unbalanced_force = 0.0;  // N, at the end
  double share_touching_nothing = 0.0;  // of the free particles, at the end
  // Whether this run settled the sample: one from a packing file (or a resumed series' kept
  // sample) took no settling step.
  bool in_this_run() const { return steps > 0; }
};

// At rest, nearly every sphere of a sample under gravity rests on something: the paper's
// settled samples have none (oedometer) or 0.6 % (shear box) touching nothing. A sample whose
// spheres are still falling has many.
inline constexpr double kMaxShareTouchingNothing = 0.10;

// Runs until the mean unbalanced force per particle (|F_contact + m g|, mean over free
// particles; PFC's measure) falls below `threshold` while no more than
// kMaxShareTouchingNothing of the free particles touch nothing (a sphere in flight does not:
// the criterion alone is met by a sample in which enough spheres have landed while others
// still fall), checked every `check_interval` steps, or until `max_time` of simulated time
// has passed.
SettleResult settle(World& world, Stepper& stepper, double threshold, double max_time,
                    std::uint64_t check_interval, Progress& progress);

// A freshly generated sample's preparation, the same for the oedometer and the shear box:
// stored in space order (store_in_space_order), the stepper prepared, then settled under
// gravity to the [sample] criterion (settle_unbalanced_force, settle_max_time,
// settle_check_interval) without an energy ledger (none is reported for settling).
SettleResult settle_generated_sample(World& world, Stepper& stepper, const SampleSpec& sample, Progress& progress);

// A new sample, the same steps for the oedometer and the shear box: generated in `region` of
// `world` (its container built; `height_key` names the generation height for the error when
// not all spheres fit), settled (settle_generated_sample, its steps counted on `clock`), cut
// at `rim` (z, m: discard_above), stored in space order, then handed on at rest (no
// velocities, spins or contact histories: sample_at_rest), which is exactly the sample its
// packing file gives back. So a run from the `packing.txt` a run wrote repeats that run's
// test bit for bit, and the YADE cross-check, which reads the packing file, starts from the
// state colza's own runs start from. Throws no_sphere_left_error (`where`) if none is left.
struct NewSample {
  ParticleArrays at_rest;
  std::size_t generated = 0;
  SettleResult settling;
};
NewSample settle_new_sample(World& world, const RunConfig& c, const GenerationRegion& region,
                            const std::string& height_key, double rim, const std::string& where, Progress& progress,
                            StageClock& clock);

// The error for a sample with no sphere left in its container after settling (`where`:
// "below the rim"). With a fixed time step above the critical estimate of the stage's start
// the motion blew up and the spheres flew off, so it names integration.time_step; otherwise
// sample.count.
ConfigError no_sphere_left_error(const RunConfig& c, const Stepper& stepper, const std::string& where);

}  // namespace colza
