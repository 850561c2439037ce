// The force loops (engine/force_loops.hpp) built for x86-64-v4: AVX-512 (F, CD, BW, DQ, VL),
// eight contacts per vector instruction (src/CMakeLists.txt sets -march=x86-64-v4 and 512-bit
// vectors). No FMA is formed from the code's a * b + c (-ffp-contract=off), so the results
// are the generic copy's bits.
#if !defined(__AVX512F__) || !defined(__AVX512VL__)
#error "engine/isa/force_loops_avx512.cpp must be compiled with -march=x86-64-v4"
#endif
#define COLZA_KERNEL_NAMESPACE kernels_avx512
#include "engine/force_loops_body.hpp"
