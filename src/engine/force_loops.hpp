// The force loops of one step (internal to the stepper): every particle pair, then every
// wall pair, through the law the model asks for (the baseline's batched kernels, a lane
// mechanism or the generic tier), serially or on the stepper's threads
// (engine/force_partition.hpp). They are the hot path, so they are compiled once per
// instruction set (engine/isa/force_loops_<isa>.cpp, all from engine/force_loops_body.hpp)
// and core/kernel_isa.hpp chooses one copy at run time (force_loops_for). Every copy gives the
// same bits.
#pragma once
#include "core/kernel_isa.hpp"
#include "core/materials.hpp"
#include "engine/force_partition.hpp"
#include "engine/pair_sinks.hpp"
#include "engine/world.hpp"

namespace colza {

// What one step's force loops read and write (Stepper::compute_forces fills it).
struct ForceLoopJob {
  const PhysicsSettings& physics;
  World& world;  // forces, torques, contact histories and the walls' sums are written
  const PairTable& pairs;
  // Not null: the threaded loop on this partition (built for this step's pair lists).
  // Null: the serial loops.
  ForcePartition* partition;
  // Not null (threaded loop only): each thread moves its finishing range's particles as soon
  // as their forces are final (Stepper::set_between_halves).
  const IntegratorSettings* motion;
  bool keep_slip;  // compute and sum the slip energy (the energy ledger is kept this step)
};

// One compiled copy of the force loops: this step's forces, torques, histories and wall sums;
// the ledger terms and break counts go to `totals`.
using ForceLoops = void (*)(const ForceLoopJob& job, detail::ForceLoopTotals& totals);

// The compiled copy for `isa` (which must be built: kernel_isa_built).
ForceLoops force_loops_for(KernelIsa isa);

// The copies (each defined only when src/CMakeLists.txt builds it).
namespace kernels_generic {
void force_loops(const ForceLoopJob& job, detail::ForceLoopTotals& totals);
}
namespace kernels_avx2 {
void force_loops(const ForceLoopJob& job, detail::ForceLoopTotals& totals);
}
namespace kernels_avx512 {
void force_loops(const ForceLoopJob& job, detail::ForceLoopTotals& totals);
}

}  // namespace colza
