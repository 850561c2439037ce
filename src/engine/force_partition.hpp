// How the threaded force loop (engine/stepper.cpp) shares the pairs among T threads, and
// its buffers.
//
// The serial loop adds, for every particle q, in this order: the pairs (k, q), k < q, in
// pair order (q is the second body), then the pairs (q, j) in pair order (q is the first
// body), then q's wall pairs in wall-pair order. The threaded loop must reproduce that
// sequence of additions to give the same bits at any thread count.
//
// Particles are cut into T contiguous index ranges holding about the same number of pairs.
// Thread t computes the pairs whose first body is in its range (the pair list is sorted by
// first body, so they are contiguous and in pair order) and the wall pairs of its particles.
// * An "inner" particle has all its partners in its own range: every contribution it gets
//   comes from its own thread, in pair order, so it is added at once (the serial scatter).
// * A "boundary" particle has a partner in a lower range, whose thread computes that pair
//   at an unknown time. All pairs of a boundary particle are stored in slots; after a
//   barrier its thread sums them in pair order (the gather list), then adds its walls.
// With Morton-ordered particles the ranges are compact regions and boundary particles are
// a thin layer (a few per cent), so nearly all pairs take the serial scatter's cost.
//
// Balance: the cuts are fractions of the pair list. Pairs do not cost the same (touching
// pairs take the batched kernel, others the scalar test; wall pairs add to their range),
// so the cuts move towards equal measured busy time of the ranges: at every neighbour
// rebuild, and every kStepsPerRebalance steps in between (a slow loading may keep its
// lists for tens of thousands of steps). A new system (another particle count) starts
// from equal pair counts. The partition never changes a result (every particle's sum keeps the serial
// order), so timing-driven cuts keep runs bit for bit reproducible.
#pragma once
#include <cstdint>
#include <vector>
#include "contact/contact_store.hpp"
#include "core/types.hpp"
#include "engine/pair_sinks.hpp"

namespace colza {

struct ForcePartition {
  static constexpr Index kNoSlot = ~Index{0};

  int threads = 0;
  std::vector<std::size_t> particle_begin;  // T + 1: range t is [particle_begin[t], particle_begin[t + 1])
  std::vector<std::size_t> pair_begin;      // T + 1: pairs whose first body is in range t
  std::vector<std::uint8_t> boundary;       // per particle: 1 = summed from slots after the barrier
  std::vector<Index> slot;                  // per pair: its slot, or kNoSlot (scattered at once)
  std::vector<Vec3> slot_force, slot_torque_1, slot_torque_2;  // per slot: F on body 2, torque on 1, on 2
  std::vector<Index> boundary_particles;    // ascending
  std::vector<std::size_t> boundary_begin;  // T + 1: boundary particles of range t
  // For boundary particle b (index into boundary_particles): gather_entries[gather_start[b]
  // .. gather_start[b + 1]) are its pairs in pair order, as 2 slot + role (role 1: body 1).
  std::vector<Index> gather_start, gather_entries;
  // wall_pair_begin[w * (T + 1) + t]: the first wall pair of wall w whose particle is in
  // range t (wall pairs are sorted by wall, then particle).
  std::vector<std::size_t> wall_pair_begin;
  std::vector<Vec3> wall_force;             // per wall pair: force on the particle (N)
  std::vector<std::uint8_t> wall_carries;   // per wall pair: 1 when it carried force this step
  std::vector<detail::LogSink> pair_logs;   // per range (pair order)
  std::vector<detail::LogSink> wall_logs;   // [w * T + t] (wall-pair order: w, then t)
  std::vector<double> busy_seconds;         // per range: time spent on its pairs since the build
  std::uint64_t steps_since_build = 0;      // counted by the force loop

  static constexpr std::uint64_t kStepsPerRebalance = 1000;

  // True when built for this pair list (same revision and storage), particle count,
  // wall count and thread count, less than kStepsPerRebalance steps ago.
  bool matches(const ContactStore& contacts, std::size_t n_particles, std::size_t n_walls, int threads) const;
  void build(const ContactStore& contacts, std::size_t n_particles, std::size_t n_walls, int threads);

 private:
  // Moves cut_fraction_ towards equal busy time, from busy_seconds of the current cuts.
  void rebalance();
  std::vector<double> cut_fraction_;        // T + 1 cuts as fractions of the pair list
  std::uint64_t revision_ = ~std::uint64_t{0};
  const Index* first_data_ = nullptr;
  std::size_t n_pairs_ = 0, n_particles_ = 0, n_walls_ = 0;
};

}  // namespace colza
