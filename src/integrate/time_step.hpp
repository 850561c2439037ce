// Critical time step estimate (physics.md section 3):
//   dt = f min_i min( sqrt(m_i / k_i), sqrt(I_i / kr_i) )
// with k_i = sum over body i's contacts of (Kn + Ks), an upper bound of the largest
// eigenvalue of the body's translational contact stiffness matrix, and kr_i = sum of
// Ks R_i^2, the rotational analogue (shear spring at lever arm R_i). A body without
// contacts counts one contact with a body of its own material (PFC's convention).
#pragma once
#include <vector>
#include "contact/contact_store.hpp"
#include "core/materials.hpp"
#include "core/particles.hpp"
#include "walls/wall.hpp"

namespace colza {

struct TimeStepSettings {
  bool automatic = true;
  double fixed_dt = 0.0;           // s, used when !automatic
  double safety_factor = 0.8;      // f (PFC's usual value)
  std::uint64_t recompute_interval = 100;  // steps between re-evaluations
};

// Returns min_i min(sqrt(m_i / k_i), sqrt(I_i / kr_i)) (s), without the safety factor.
double critical_time_step(const ParticleArrays& particles, const std::vector<Wall>& walls,
                          const ContactStore& contacts, const PairTable& pairs);

}  // namespace colza
