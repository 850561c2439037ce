// The integrator's state update over a range of particles (internal to integrate/integrator.cpp):
// the hot loop of the motion, compiled once per instruction set
// (integrate/isa/integrate_range_<isa>.cpp, all from integrate/integrate_range_body.hpp) and
// chosen at run time by core/kernel_isa.hpp, like the force loops. Every copy gives the same
// bits.
#pragma once
#include <cstddef>
#include "core/kernel_isa.hpp"
#include "core/particles.hpp"
#include "integrate/integrator.hpp"

namespace colza {

// What a range reports of the sums over its particles.
struct RangeReport {
  std::size_t free_count = 0;
  double unbalanced_sum = 0.0, max_unbalanced = 0.0, damping_work = 0.0;
};

// Advances particles [begin, end) by one step (integrator.cpp's integrate_step explains the
// sums): the wanted sums go to `r`, or with `unbalanced_out` |load| of each particle there.
using IntegrateRange = void (*)(ParticleArrays& p, const IntegratorSettings& s, double dt, std::size_t begin,
                                std::size_t end, RangeReport& r, double* unbalanced_out, IntegrationSums sums);
// The compiled copy for `isa` (which must be built: kernel_isa_built).
IntegrateRange integrate_range_for(KernelIsa isa);

namespace kernels_generic {
void integrate_range(ParticleArrays& p, const IntegratorSettings& s, double dt, std::size_t begin, std::size_t end,
                     RangeReport& r, double* unbalanced_out, IntegrationSums sums);
}
namespace kernels_avx2 {
void integrate_range(ParticleArrays& p, const IntegratorSettings& s, double dt, std::size_t begin, std::size_t end,
                     RangeReport& r, double* unbalanced_out, IntegrationSums sums);
}
namespace kernels_avx512 {
void integrate_range(ParticleArrays& p, const IntegratorSettings& s, double dt, std::size_t begin, std::size_t end,
                     RangeReport& r, double* unbalanced_out, IntegrationSums sums);
}

}  // namespace colza
