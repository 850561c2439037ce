// Loads on a wall that its net force does not show: the oedometer's cylinder takes radial
// forces that cancel in its net force vector.
#pragma once
#include "contact/contact_store.hpp"
#include "core/types.hpp"

namespace colza {

// Sum of the normal forces (N, compression positive) of the touching contacts between the
// particles and wall `wall`, from the contact histories of the last force pass. For the
// oedometer's cylinder it is the radial force on the wall: the normal of a sphere-cylinder
// contact is radial.
double wall_normal_force_sum(const ContactStore& contacts, Index wall);

}  // namespace colza
