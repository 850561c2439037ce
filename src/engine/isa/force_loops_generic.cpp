// The force loops (engine/force_loops.hpp) built for the build's baseline instruction set
// (src/CMakeLists.txt: x86-64 by default; the only copy on other architectures).
#define COLZA_KERNEL_NAMESPACE kernels_generic
#include "engine/force_loops_body.hpp"
