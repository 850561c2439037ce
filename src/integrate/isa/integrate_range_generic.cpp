// The integrator's particle ranges (integrate/integrate_range.hpp) built for the build's baseline instruction set (src/CMakeLists.txt: x86-64 by default; the only copy on other architectures).
#define COLZA_KERNEL_NAMESPACE kernels_generic
#include "integrate/integrate_range_body.hpp"
