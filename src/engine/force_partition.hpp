// How the threaded force loop (engine/force_loops_body.hpp) shares the pairs among T threads, and
// its buffers.
//
// The serial loop adds, for every particle q, in this order: the pairs (k, q), k < q, in
// pair order (q is the second body), then the pairs (q, j) in pair order (q is the first
// body), then q's wall pairs in wall-pair order. The threaded loop must reproduce that
// sequence of additions to give the same bits at any thread count.
//
// Particles are cut into T contiguous index ranges holding about the same number of pairs.
// Thread t computes the pairs whose first body is in its range (the pair list is sorted by
// first body, so they are contiguous and in pair order).
// * An "inner" particle has all its partners in its own range: every contribution it gets
//   comes from its own thread, in pair order, so it is added at once (the serial scatter).
// * A "boundary" particle has a partner in a lower range, whose thread computes that pair
//   at an unknown time. All pairs of a boundary particle are stored in slots; after a
//   barrier they are summed in pair order (the gather list), then its walls are added.
// With Morton-ordered particles the ranges are compact regions and boundary particles are
// a thin layer (a few per cent), so nearly all pairs take the serial scatter's cost.
//
// After the barrier, a second cut of the particles into T "finishing" ranges shares the rest
// of the step: the boundary sums, the wall pairs and (when the motion goes with the forces)
// the integration. A particle's order of additions stays the serial one whatever the cut
// (its pairs are final after the barrier; its walls follow its gather, wall by wall), so the
// two cuts are chosen independently. One cut for both would leave both phases unbalanced:
// the boundary particles all belong to the higher range, whose phase 2 is therefore longer,
// and equal busy time per thread then makes its phase 1 shorter; each thread waits once.
//
// Balance: the pair cuts are fractions of the pair list, the finishing cuts fractions of the
// particles. Pairs do not cost the same (touching pairs take the batched kernel, others the
// scalar test), nor do particles (boundary sums, wall pairs), so each set of cuts moves
// towards equal measured busy time of its phase: at every neighbour rebuild, and every
// kStepsPerRebalance steps in between (a slow loading may keep its lists for tens of
// thousands of steps). A new system (another particle count) starts from equal shares. The
// partition never changes a result (every particle's sum keeps the serial order), so
// timing-driven cuts keep runs bit for bit reproducible.
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
  // Finishing ranges (after the barrier): range t is [finish_begin[t], finish_begin[t + 1]);
  // boundary_begin (T + 1): the boundary particles of finishing range t.
  std::vector<std::size_t> finish_begin;
  std::vector<std::size_t> boundary_begin;
  // For boundary particle b (index into boundary_particles): gather_entries[gather_start[b]
  // .. gather_start[b + 1]) are its pairs in pair order, as 2 slot + role (role 1: body 1).
  std::vector<Index> gather_start, gather_entries;
  // wall_pair_begin[w * (T + 1) + t]: the first wall pair of wall w whose particle is in
  // finishing range t (wall pairs are sorted by wall, then particle).
  std::vector<std::size_t> wall_pair_begin;
  std::vector<Vec3> wall_force;             // per wall pair: force on the particle (N)
  std::vector<std::uint8_t> wall_carries;   // per wall pair: 1 when it carried force this step
  std::vector<detail::LogSink> pair_logs;   // per range (pair order)
  std::vector<detail::LogSink> wall_logs;   // [w * T + t] (wall-pair order: w, then t)
  // Per range, since the build: time spent before the barrier (pairs), and after it.
  std::vector<double> pair_busy_seconds, finish_busy_seconds;
  std::uint64_t steps_since_build = 0;      // counted by the force loop

  static constexpr std::uint64_t kStepsPerRebalance = 1000;

  // True when built for this pair list (same revision and storage), particle count,
  // wall count and thread count, less than kStepsPerRebalance steps ago.
  bool matches(const ContactStore& contacts, std::size_t n_particles, std::size_t n_walls, int threads) const;
  void build(const ContactStore& contacts, std::size_t n_particles, std::size_t n_walls, int threads);

 private:
  std::vector<double> pair_cut_fraction_;    // T + 1 cuts as fractions of the pair list
  std::vector<double> finish_cut_fraction_;  // T + 1 cuts as fractions of the particles
  std::uint64_t revision_ = ~std::uint64_t{0};
  const Index* first_data_ = nullptr;
  std::size_t n_pairs_ = 0, n_particles_ = 0, n_walls_ = 0;
};

}  // namespace colza
