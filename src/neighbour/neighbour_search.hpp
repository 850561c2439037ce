// Linked-cell neighbour search with a Verlet skin.
// Candidates: particle pairs with |x2 - x1| < R1 + R2 + skin, at least one of them not
// anchored (kAnchored: two spheres that never move exert a force on each other that does
// nothing), and sphere-wall pairs (Wall::meets_fixed_spheres) whose gap is below the skin (a
// finite cylinder taken as reaching one skin beyond its ends, since the sphere's axial
// coordinate also changes by at most a skin). The lists stay
// valid while every particle and every wall has moved no more than skin/2 since the last
// build (two bodies then closed the gap by at most a skin), so rebuilds happen only when
// that is violated.
#pragma once
#include <vector>
#include "contact/contact_store.hpp"
#include "core/particles.hpp"
#include "walls/wall.hpp"

namespace colza {

class NeighbourSearch {
 public:
  explicit NeighbourSearch(double skin = 0.0) : skin_(skin) {}

  double skin() const { return skin_; }
  bool needs_rebuild(const ParticleArrays& particles, const std::vector<Wall>& walls) const;
  // Rebuild both candidate lists and carry contact history over. The particle pairs are
  // searched on up to `threads` OpenMP threads (same list at any count).
  void rebuild(const ParticleArrays& particles, const std::vector<Wall>& walls, ContactStore& contacts,
               int threads = 1);
  void invalidate() { valid_ = false; }
  std::uint64_t rebuild_count() const { return rebuilds_; }

 private:
  void build_particle_pairs(const ParticleArrays& particles, int threads, std::vector<Index>& first,
                            std::vector<Index>& second);
  struct SortedSphere {
    double x, y, z, r;
    double anchored;  // 1: an anchored sphere (ParticleArrays::fixed == kAnchored), else 0
  };
  double skin_;
  bool valid_ = false;
  std::uint64_t rebuilds_ = 0;
  std::vector<Vec3> position_at_build_;
  std::vector<Vec3> wall_origin_at_build_;
  // Scratch buffers of the cell grid (kept to avoid reallocation).
  std::vector<Index> cell_start_, cell_particles_, particle_cell_;
  std::vector<SortedSphere> sorted_;                        // positions and radii in cell order
  std::vector<std::vector<Index>> range_first_, range_second_;  // per-thread lists
};

}  // namespace colza
