// The integrator's particle ranges (integrate/integrate_range.hpp) built for x86-64-v3 (AVX2, FMA; no FMA is formed from a * b + c: -ffp-contract=off).
#if !defined(__AVX2__) || !defined(__FMA__)
#error "integrate/isa/integrate_range_avx2.cpp must be compiled with -march=x86-64-v3"
#endif
#define COLZA_KERNEL_NAMESPACE kernels_avx2
#include "integrate/integrate_range_body.hpp"
