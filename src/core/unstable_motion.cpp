#include "core/unstable_motion.hpp"

#include <cmath>

namespace colza {

std::optional<std::size_t> first_non_finite_position(const ParticleArrays& particles) {
  const std::size_t n = particles.size();
  if (n == 0) return std::nullopt;
  const double* x = particles.position.data()->data();
  // Multiplying by 0 keeps finite values at 0 (no overflow of the sum) and turns NaN and
  // infinities into NaN.
  double probe = 0.0;
#pragma omp simd reduction(+ : probe)
  for (std::size_t k = 0; k < 3 * n; ++k) probe += 0.0 * x[k];
  if (probe == 0.0) return std::nullopt;
  for (std::size_t i = 0; i < n; ++i)
    if (!particles.position[i].allFinite()) return i;
  return std::nullopt;
}

}  // namespace colza
