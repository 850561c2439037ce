// The ceilings of a roofline for one core of the machine it runs on: the triad bandwidth
// a = b + s c (24 B moved per element) with a working set that fits the L2 cache, the L3
// cache and main memory, and the rate of independent multiplies and adds without FMA (colza
// is compiled with -ffp-contract=off). ARCHITECTURE.md (Performance, roofline) sets colza's
// step against them. Built with -march=native: a measuring tool for the machine it runs on,
// not a program to ship.
//   ./build/tests/bench/colza_roofline_ceilings
#include <chrono>
#include <cstdio>
#include <vector>

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// GB/s of the triad over a working set of `bytes` (three arrays), ~4 GB moved.
double triad_bandwidth(std::size_t bytes) {
  const std::size_t n = bytes / 24;
  std::vector<double> a(n, 1.0), b(n, 2.0), c(n, 3.0);
  const int reps = static_cast<int>((std::size_t(4) << 30) / bytes);
  const auto t0 = std::chrono::steady_clock::now();
  for (int r = 0; r < reps; ++r) {
    const double s = 1.0 + r * 1e-9;
#pragma omp simd
    for (std::size_t i = 0; i < n; ++i) a[i] = b[i] + s * c[i];
    asm volatile("" ::"r"(a.data()) : "memory");
  }
  return 24.0 * static_cast<double>(n) * reps / seconds_since(t0) / 1e9;
}

// GFLOP/s of x = x * c + d over 16 independent vectors of 8 doubles (a multiply and an add
// each, not fused).
double multiply_add_rate() {
  constexpr int kChains = 16, kWidth = 8;
  alignas(64) double x[kChains][kWidth];
  for (auto& row : x)
    for (double& v : row) v = 1.0;
  constexpr long kRounds = 125000000;  // ~0.3 s
  const auto t0 = std::chrono::steady_clock::now();
  for (long it = 0; it < kRounds; ++it) {
#pragma GCC unroll 16
    for (int k = 0; k < kChains; ++k)
#pragma omp simd
      for (int l = 0; l < kWidth; ++l) x[k][l] = x[k][l] * 0.9999999 + 1e-9;
  }
  const double seconds = seconds_since(t0);
  double sum = 0.0;
  for (auto& row : x)
    for (double v : row) sum += v;
  asm volatile("" ::"r"(sum));
  return 2.0 * kRounds * kChains * kWidth / seconds / 1e9;
}

}  // namespace

int main() {
  std::printf("triad bandwidth, one core: L2-sized (0.375 MB) %.1f GB/s, L3-sized (8 MB) %.1f GB/s, "
              "memory (256 MB) %.1f GB/s\n",
              triad_bandwidth(std::size_t(384) << 10), triad_bandwidth(std::size_t(8) << 20),
              triad_bandwidth(std::size_t(256) << 20));
  std::printf("multiply and add, no FMA, one core: %.1f GFLOP/s\n", multiply_add_rate());
}
