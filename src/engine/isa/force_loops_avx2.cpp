// The force loops (engine/force_loops.hpp) built for x86-64-v3: AVX2 and FMA, four contacts
// per vector instruction (src/CMakeLists.txt sets -march=x86-64-v3). No FMA is formed from
// the code's a * b + c (-ffp-contract=off), so the results are the generic copy's bits.
#if !defined(__AVX2__) || !defined(__FMA__)
#error "engine/isa/force_loops_avx2.cpp must be compiled with -march=x86-64-v3"
#endif
#define COLZA_KERNEL_NAMESPACE kernels_avx2
#include "engine/force_loops_body.hpp"
