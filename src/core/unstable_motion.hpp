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
  // fixed_time_step_too_large: the time step was fixed by the configuration above the
  // critical estimate, so the configuration is to blame (`colza run` reports it as an error
  // of integration.time_step, exit 2).
  explicit UnstableMotion(const std::string& what, bool fixed_time_step_too_large = false)
      : std::runtime_error(what), fixed_time_step_too_large_(fixed_time_step_too_large) {}
  bool fixed_time_step_too_large() const { return fixed_time_step_too_large_; }

 private:
  bool fixed_time_step_too_large_;
};

// The first particle with a non-finite (NaN or infinite) position coordinate, if any. One
// pass summing the coordinates (a NaN or an infinity makes the sum non-finite) and, only
// then, a search for the particle.
std::optional<std::size_t> first_non_finite_position(const ParticleArrays& particles);

}  // namespace colza
