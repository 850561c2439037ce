#include "engine/force_loops.hpp"

namespace colza {

ForceLoops force_loops_for(KernelIsa isa) {
  switch (isa) {
    case KernelIsa::kGeneric: return &kernels_generic::force_loops;
#ifdef COLZA_KERNELS_AVX2
    case KernelIsa::kAvx2: return &kernels_avx2::force_loops;
#endif
#ifdef COLZA_KERNELS_AVX512
    case KernelIsa::kAvx512: return &kernels_avx512::force_loops;
#endif
    default: return nullptr;
  }
}

}  // namespace colza
