// Two limits no sound motion comes near, checked by Stepper::require_sound_state
// (engine/stepper.cpp) to stop a run whose motion has blown up (a time step above the
// stability limit) or whose contacts are far too soft for the load, before positions become
// non-finite: the deepest contact overlap against the smaller radius, and the largest
// distance a particle moves in one step against its radius.
#pragma once
#include <cstddef>
#include <vector>
#include "contact/contact_store.hpp"
#include "contact/slots.hpp"
#include "core/materials.hpp"
#include "core/particles.hpp"
#include "walls/wall.hpp"

namespace colza {

// The smaller sphere's whole radius: its centre then reaches the other sphere's surface, which
// no contact model describes. The paper's oedometer at 30 kN (3.8 MPa, kn_p = 437 kN/m)
// reaches 40 % (measured: the default oedometer's deepest overlap, session 23); a design run
// at kn_p = 300 kN/m would reach about 60 %.
inline constexpr double kOverlapLimit = 1.0;

struct DeepestOverlap {
  double ratio = 0.0;          // overlap / radius (the smaller of the two spheres')
  double overlap = 0.0;        // m
  bool with_wall = false;      // a particle-wall contact (second is then the wall's index)
  std::size_t first = 0, second = 0;
};

// Over the touching contacts, the overlap that the normal law reads from the contact's
// normal force (Fn / Kn for the linear law; a bond in tension has none) relative to the
// smaller sphere's radius (a wall's: the sphere's).
DeepestOverlap deepest_overlap(const ParticleArrays& particles, const std::vector<Wall>& walls,
                               const ContactStore& contacts, const PairTable& pairs,
                               const ContactModel& model = ContactModel{});

// A particle's radius in one step: it could then pass through a neighbour between two force
// evaluations. Sound motion stays far below: a sphere falling 0.2 m moves 2 m/s x 7e-6 s =
// 1.4e-5 m in a step, 0.4 % of a 3.25 mm radius.
inline constexpr double kStepLimit = 1.0;

struct FastestParticle {
  double ratio = 0.0;  // |v| dt / radius
  double speed = 0.0;  // m/s
  std::size_t index = 0;
};

// The particle that moves farthest in one step of dt (s) relative to its radius. A particle
// without a neighbour candidate (no particle or wall within the skin) counts only when it is
// faster than `free_flight_speed` (m/s): one that left the container and falls alone, faster
// and faster, has nothing to pass through, while the spheres of a sample blown apart are
// alone too but far faster than gravity could have made them.
FastestParticle fastest_particle(const ParticleArrays& particles, const ContactStore& contacts, double dt,
                                 double free_flight_speed);

}  // namespace colza
