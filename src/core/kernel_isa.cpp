#include "core/kernel_isa.hpp"

#include <atomic>
#include <cstdlib>
#include <stdexcept>

#include "config/config_error.hpp"

// src/CMakeLists.txt defines, for colza_core, COLZA_KERNELS_BASELINE (the build's target
// options) and, for each wider copy it builds, COLZA_KERNELS_AVX2 / COLZA_KERNELS_AVX512 (that
// copy's options).
#ifndef COLZA_KERNELS_BASELINE
#error "src/CMakeLists.txt defines COLZA_KERNELS_BASELINE for colza_core"
#endif

namespace colza {

namespace {

constexpr const char* kNames[] = {"generic", "avx2", "avx512"};
constexpr KernelIsa kAll[] = {KernelIsa::kGeneric, KernelIsa::kAvx2, KernelIsa::kAvx512};

// Whether the CPU and the operating system (its saved vector state) support the instructions
// of each x86-64 level: libgcc's __builtin_cpu_supports reads CPUID and XGETBV.
bool cpu_supports(KernelIsa isa) {
  if (isa == KernelIsa::kGeneric) return true;
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
  __builtin_cpu_init();
  if (isa == KernelIsa::kAvx2) return __builtin_cpu_supports("x86-64-v3");
  return __builtin_cpu_supports("x86-64-v4");
#elif defined(__x86_64__)
  // Compilers without the level names: the levels' features that compilers use for this code.
  __builtin_cpu_init();
  const bool v3 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
                  __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
  if (isa == KernelIsa::kAvx2) return v3;
  return v3 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
         __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
         __builtin_cpu_supports("avx512cd");
#else
  return false;
#endif
}

// The copy the kernels take (-1 before the first active_kernel_isa or set_kernel_isa) and
// who chose it.
enum class ChosenBy { kWidestHere, kEnvironment, kProgram };
std::atomic<int> chosen{-1};
std::atomic<ChosenBy> chosen_by{ChosenBy::kWidestHere};

// " generic (-march=x86-64), avx2 (-march=x86-64-v3), ...": every copy built.
std::string built_copies() {
  std::string s;
  for (KernelIsa isa : kAll)
    if (kernel_isa_built(isa))
      s += std::string(isa == KernelIsa::kGeneric ? " " : ", ") + to_string(isa) + " (" + kernel_isa_built_for(isa) + ")";
  return s;
}

KernelIsa from_environment() {
  const char* value = std::getenv("COLZA_ISA");
  const std::string name = value ? value : "";
  if (name.empty() || name == "auto") return widest_kernel_isa_here();
  const std::optional<KernelIsa> isa = parse_kernel_isa(name);
  if (!isa)
    throw ConfigError("$COLZA_ISA", "", "'" + name + "' names no copy of the kernels (generic, avx2, avx512 or auto)");
  if (!kernel_isa_built(*isa))
    throw ConfigError("$COLZA_ISA", "", "this binary has no " + name + " copy of the kernels (built:" +
                                            built_copies() + ")");
  if (!cpu_supports(*isa))
    throw ConfigError("$COLZA_ISA", "", "this CPU cannot run the " + name + " copy of the kernels (built for " +
                                            kernel_isa_built_for(*isa) + "); unset it to take the widest it runs");
  chosen_by = ChosenBy::kEnvironment;
  return *isa;
}

}  // namespace

const char* to_string(KernelIsa isa) { return kNames[static_cast<int>(isa)]; }

std::optional<KernelIsa> parse_kernel_isa(std::string_view name) {
  for (KernelIsa isa : kAll)
    if (name == to_string(isa)) return isa;
  return std::nullopt;
}

const char* kernel_isa_built_for(KernelIsa isa) {
  switch (isa) {
    case KernelIsa::kGeneric: return COLZA_KERNELS_BASELINE;
#ifdef COLZA_KERNELS_AVX2
    case KernelIsa::kAvx2: return COLZA_KERNELS_AVX2;
#endif
#ifdef COLZA_KERNELS_AVX512
    case KernelIsa::kAvx512: return COLZA_KERNELS_AVX512;
#endif
    default: return "not built";
  }
}

bool kernel_isa_built(KernelIsa isa) {
  switch (isa) {
    case KernelIsa::kGeneric: return true;
#ifdef COLZA_KERNELS_AVX2
    case KernelIsa::kAvx2: return true;
#endif
#ifdef COLZA_KERNELS_AVX512
    case KernelIsa::kAvx512: return true;
#endif
    default: return false;
  }
}

bool kernel_isa_runs_here(KernelIsa isa) { return kernel_isa_built(isa) && cpu_supports(isa); }

std::vector<KernelIsa> kernel_isas_here() {
  std::vector<KernelIsa> here;
  for (KernelIsa isa : kAll)
    if (kernel_isa_runs_here(isa)) here.push_back(isa);
  return here;
}

KernelIsa widest_kernel_isa_here() { return kernel_isas_here().back(); }

KernelIsa active_kernel_isa() {
  int isa = chosen.load(std::memory_order_relaxed);
  if (isa < 0) {
    isa = static_cast<int>(from_environment());
    chosen.store(isa, std::memory_order_relaxed);
  }
  return static_cast<KernelIsa>(isa);
}

void set_kernel_isa(KernelIsa isa) {
  if (!kernel_isa_runs_here(isa))
    throw std::invalid_argument(std::string("the ") + to_string(isa) + " copy of the kernels does not run here (built:" +
                                built_copies() + ")");
  chosen_by = ChosenBy::kProgram;
  chosen.store(static_cast<int>(isa), std::memory_order_relaxed);
}

std::string kernel_isa_report() {
  const KernelIsa active = active_kernel_isa();
  const ChosenBy by = chosen_by;
  const char* how = by == ChosenBy::kEnvironment ? "$COLZA_ISA" : by == ChosenBy::kProgram ? "set by the program" : "widest here";
  return std::string(to_string(active)) + " (" + how + "); built:" + built_copies();
}

}  // namespace colza
