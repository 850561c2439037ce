// Contact bonds installed at a chosen moment (contact.bond_install): on every touching
// particle pair, or within a gap tolerance (contact.bond_gap).
#pragma once
#include <cstddef>

#include "engine/stepper.hpp"

namespace colza {

// Puts a contact bond on every particle-particle pair touching now (un >= -gap, m).
// Returns the number of bonds installed. The candidate lists are rebuilt first, so every pair
// with a gap below the stepper's Verlet skin is a candidate; a gap of the skin or wider
// cannot be honoured and throws std::invalid_argument (the config check refuses
// contact.bond_gap >= integration.verlet_skin before a run starts). Rebuilding the lists
// changes no result: forces are summed in pair order and a candidate that is not touching
// carries no force, so which pairs are candidates never shows in the physics. When a pair
// within the gap becomes a contact, the automatic time step is evaluated again at once
// (a new contact stiffens its spheres).
std::size_t install_bonds(World& world, Stepper& stepper, double gap);

}  // namespace colza
