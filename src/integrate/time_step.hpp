// Critical time step estimate (physics.md section 3):
//   dt = f min_i min( sqrt(m_i / k_i), sqrt(I_i / kr_i) )
// with k_i = sum over body i's contacts of (Kn + Ks), an upper bound of the largest
// eigenvalue of the body's translational contact stiffness matrix, and kr_i = sum of
// Ks R_i^2, the rotational analogue (shear spring at lever arm R_i). A body without
// contacts counts one contact with a body of its own material (PFC's convention).
// For the generic tier's slots (a model other than the baseline) Kn and Ks are the normal and
// tangential laws' tangent stiffnesses at the contact's overlap now, kr_i adds the rolling
// springs' kr, and a body without contacts counts one at an overlap of 1 % of its radius
// (a Hertz contact has no stiffness at zero overlap).
#pragma once
#include <vector>
#include "contact/contact_store.hpp"
#include "contact/slots.hpp"
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

// Which candidate pairs count as contacts. kTouching: those the last force pass marked
// touching (bonded pairs in tension included), which is current from the first force pass
// on. kTouchingOrOverlapping: also those whose bodies overlap now, for a state no force pass
// has seen yet (a packing read from a file, a sample placed in a new container): by flags
// alone it would have no contact, and its dt would come out about sqrt(coordination) too
// large (settled oedometer packing, Table 1 parameters: 1.29e-5 against 6.50e-6 s).
enum class CountedContacts { kTouching, kTouchingOrOverlapping };

// Returns min_i min(sqrt(m_i / k_i), sqrt(I_i / kr_i)) (s), without the safety factor.
double critical_time_step(const ParticleArrays& particles, const std::vector<Wall>& walls,
                          const ContactStore& contacts, const PairTable& pairs,
                          CountedContacts counted = CountedContacts::kTouching,
                          const ContactModel& model = ContactModel{});

}  // namespace colza
