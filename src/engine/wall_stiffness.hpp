// The normal stiffness a wall meets in its contacts (N/m), for a servo that moves the wall
// to hold a force (the shear box's plate, scenario/plate_servo.hpp).
#pragma once
#include <cstddef>
#include "engine/world.hpp"

namespace colza {

// The sum over the wall's touching contacts of the normal law's tangent stiffness at the
// contact's overlap (read from its normal force), and at least one contact's: the linear
// law gives Kn x max(1, contacts); a law without stiffness at zero overlap (Hertz) counts
// a contact at 1 % of the first particle's radius when the wall touches nothing.
double wall_normal_stiffness(const World& world, const PhysicsSettings& physics, const PairTable& pairs,
                             std::size_t wall_index);

}  // namespace colza
