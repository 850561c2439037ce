#include "integrate/integrate_range.hpp"

namespace colza {

IntegrateRange integrate_range_for(KernelIsa isa) {
  switch (isa) {
    case KernelIsa::kGeneric: return &kernels_generic::integrate_range;
#ifdef COLZA_KERNELS_AVX2
    case KernelIsa::kAvx2: return &kernels_avx2::integrate_range;
#endif
#ifdef COLZA_KERNELS_AVX512
    case KernelIsa::kAvx512: return &kernels_avx512::integrate_range;
#endif
    default: return nullptr;
  }
}

}  // namespace colza
