// The integrator's particle ranges (integrate/integrate_range.hpp) built for x86-64-v4 (AVX-512; no FMA is formed from a * b + c: -ffp-contract=off).
#if !defined(__AVX512F__) || !defined(__AVX512VL__)
#error "integrate/isa/integrate_range_avx512.cpp must be compiled with -march=x86-64-v4"
#endif
#define COLZA_KERNEL_NAMESPACE kernels_avx512
#include "integrate/integrate_range_body.hpp"
