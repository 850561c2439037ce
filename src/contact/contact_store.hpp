// Candidate pairs from the neighbour search and the contact history kept by pair.
// Particle pairs form a half list (first < second), sorted by (first, second); wall
// pairs are sorted by (wall, particle). A rebuild hands its new sorted lists to
// `adopt_*`, which carries each surviving pair's history over by a merge.
#pragma once
#include <cstdint>
#include <vector>
#include "contact/history.hpp"
#include "contact/slot_state.hpp"
#include "core/types.hpp"

namespace colza {

// Each list keeps, beside the core histories, the slots' state: `slot_state` holds
// size() x stride doubles (ContactStore::slot_state_layout), row c for pair c; empty for the
// baseline.
struct ParticlePairList {
  std::vector<Index> first, second;
  std::vector<ContactHistory> history;
  std::vector<double> slot_state;
  std::size_t size() const { return first.size(); }
};

struct WallPairList {
  std::vector<Index> wall, particle;
  std::vector<ContactHistory> history;
  std::vector<double> slot_state;
  std::size_t size() const { return wall.size(); }
};

class ContactStore {
 public:
  ParticlePairList particle_pairs;
  WallPairList wall_pairs;

  // Replace the candidate lists, keeping the history of pairs present in both old and new
  // lists. A bonded pair missing from the new list is kept (a bond holds beyond the skin).
  void adopt_particle_pairs(std::vector<Index> first, std::vector<Index> second);
  void adopt_wall_pairs(std::vector<Index> wall, std::vector<Index> particle);

  // The slots' per-pair state (contact/slot_state.hpp). A layout other than the present one
  // starts every row at zero (the Stepper sets its model's layout when it prepares a world).
  void set_slot_state_layout(const SlotStateLayout& layout);
  const SlotStateLayout& slot_state_layout() const { return layout_; }
  // The slot-state row of particle pair c or wall pair c (kZeroSlotRow when the layout has none).
  const double* particle_pair_state(std::size_t c) const { return row(particle_pairs.slot_state, c); }
  const double* wall_pair_state(std::size_t c) const { return row(wall_pairs.slot_state, c); }

  // Rename particles after removal/reordering (old_to_new[i] == kRemoved drops the pair).
  void renumber_particles(const std::vector<Index>& old_to_new);

  // Bumped whenever adopt_* or renumber_particles replaces the lists, so that derived
  // index structures (the threaded force loop's ForcePartition) know when to rebuild.
  std::uint64_t revision() const { return revision_; }

  // Per particle (`particle_count` of them): 1 if it is in a particle or wall pair, else 0;
  // with `touching_only`, counting only the pairs that touch (after a force pass).
  std::vector<std::uint8_t> particles_in_pairs(std::size_t particle_count, bool touching_only) const;

  std::size_t touching_particle_contacts() const;
  std::size_t touching_wall_contacts() const;
  std::size_t bonded_contacts() const;

 private:
  const double* row(const std::vector<double>& rows, std::size_t c) const {
    return layout_.stride == 0 ? kZeroSlotRow : rows.data() + c * layout_.stride;
  }
  std::uint64_t revision_ = 0;
  SlotStateLayout layout_;
};

}  // namespace colza
