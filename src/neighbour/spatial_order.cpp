#include "neighbour/spatial_order.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace colza {

namespace {

// Spreads the low 21 bits of v so that there are two zero bits between consecutive bits.
std::uint64_t spread_bits(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

}  // namespace

std::vector<Index> morton_cell_order(const ParticleArrays& particles, double cell_size) {
  const std::size_t n = particles.size();
  std::vector<Index> order(n);
  std::iota(order.begin(), order.end(), Index{0});
  if (n == 0 || !(cell_size > 0.0)) return order;
  Vec3 lower = particles.position[0];
  for (const Vec3& x : particles.position) lower = lower.cwiseMin(x);
  std::vector<std::uint64_t> key(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 cell = ((particles.position[i] - lower) / cell_size).array().floor();
    key[i] = spread_bits(static_cast<std::uint64_t>(cell.x())) |
             spread_bits(static_cast<std::uint64_t>(cell.y())) << 1 |
             spread_bits(static_cast<std::uint64_t>(cell.z())) << 2;
  }
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return key[a] < key[b]; });
  return order;
}

}  // namespace colza
