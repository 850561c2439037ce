// A storage order of particles that follows space, for memory locality in the force loop.
// Contacts join neighbours in space; when neighbours are also neighbours in memory, the
// loads of a contact's two bodies hit the same cache lines (measured on the settled
// oedometer packing: see ARCHITECTURE.md, Performance).
#pragma once
#include <vector>
#include "core/particles.hpp"

namespace colza {

// Permutation `order` (new index k holds old particle order[k]) that sorts the particles by
// the Morton (Z-order) key of their cell in a grid of cubic cells of edge `cell_size` (m)
// anchored at the lower corner of the particles' bounding box. Particles in the same cell
// keep their relative order, so the result depends only on the positions (deterministic).
std::vector<Index> morton_cell_order(const ParticleArrays& particles, double cell_size);

}  // namespace colza
