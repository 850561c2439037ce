// A run whose motion has blown up (a time step above the critical one, say) stops with this
// error instead of writing NaN curves or indexing a cell grid with a non-finite coordinate.
#pragma once
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include "core/particles.hpp"

namespace colza {

class UnstableMotion : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The first particle with a non-finite (NaN or infinite) position coordinate, if any. One
// pass summing the coordinates (a NaN or an infinity makes the sum non-finite) and, only
// then, a search for the particle.
std::optional<std::size_t> first_non_finite_position(const ParticleArrays& particles);

}  // namespace colza
