// Which compiled copy of the hot kernels this process runs: the force loops
// (engine/force_loops.hpp) and the integrator's particle ranges (integrate/integrate_range.hpp).
//
// The binary is built for a portable baseline (src/CMakeLists.txt: x86-64), so it runs on any
// CPU of its architecture. The kernels, where a step spends most of its time, are also
// compiled for x86-64-v3 (AVX2, FMA) and x86-64-v4 (AVX-512) on x86-64. At the first step the
// process takes the widest copy this CPU (and its operating system) can run, or the one the
// environment variable COLZA_ISA names (generic, avx2, avx512, or auto: the widest). Every copy
// gives the same bits (KernelIsa tests), so the choice changes the speed only.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace colza {

enum class KernelIsa { kGeneric, kAvx2, kAvx512 };

// "generic", "avx2", "avx512".
const char* to_string(KernelIsa isa);
std::optional<KernelIsa> parse_kernel_isa(std::string_view name);
// The compiler's target options of the copy, e.g. "-march=x86-64-v4 -mprefer-vector-width=512";
// "not built" for a copy this binary lacks.
const char* kernel_isa_built_for(KernelIsa isa);
// Whether this binary holds the copy (generic always; avx2 and avx512 on x86-64 builds).
bool kernel_isa_built(KernelIsa isa);
// Whether the copy is built and this CPU and operating system can run it.
bool kernel_isa_runs_here(KernelIsa isa);
// Every copy that runs here, narrowest first (generic first).
std::vector<KernelIsa> kernel_isas_here();
// The widest copy that runs here.
KernelIsa widest_kernel_isa_here();

// The copy the kernels take: set_kernel_isa's, else $COLZA_ISA's (read at the first call),
// else the widest here. Throws ConfigError (config/config_error.hpp) when $COLZA_ISA names no
// copy, or one this binary lacks or this CPU cannot run.
KernelIsa active_kernel_isa();
// From now on the kernels take `isa` (tests, benchmarks). Throws std::invalid_argument when
// it does not run here.
void set_kernel_isa(KernelIsa isa);

// One line for people and result files: the copy taken and how it was chosen, and every
// copy built with its target options, e.g. "avx512 (widest here); built: generic
// (-march=x86-64), avx2 (-march=x86-64-v3), avx512 (-march=x86-64-v4 ...)". Throws as
// active_kernel_isa.
std::string kernel_isa_report();

}  // namespace colza
