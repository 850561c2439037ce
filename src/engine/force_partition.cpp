#include "engine/force_partition.hpp"

#include <algorithm>

namespace colza {

namespace {

// Moves the cuts (T + 1 fractions of some list) towards equal busy time of the T ranges.
// Busy time is taken as a piecewise-linear function of the fraction (uniform cost within
// each old range); the new cut t sits where it reaches total * t / T. Half a step towards it
// damps timing noise. No measured time: the cuts stay.
void rebalance(std::vector<double>& cut_fraction, const std::vector<double>& busy_seconds) {
  const std::size_t T = cut_fraction.size() - 1;
  double total = 0.0;
  for (std::size_t t = 0; t < T; ++t) total += busy_seconds[t];
  if (!(total > 0.0)) return;
  std::vector<double> target(T + 1, 0.0);
  target[T] = 1.0;
  std::size_t r = 0;
  double below = 0.0;  // busy time of ranges before r
  for (std::size_t t = 1; t < T; ++t) {
    const double want = total * static_cast<double>(t) / static_cast<double>(T);
    while (r + 1 < T && below + busy_seconds[r] < want) below += busy_seconds[r++];
    const double width = cut_fraction[r + 1] - cut_fraction[r];
    const double share = busy_seconds[r] > 0.0 ? std::clamp((want - below) / busy_seconds[r], 0.0, 1.0) : 0.5;
    target[t] = cut_fraction[r] + share * width;
  }
  for (std::size_t t = 1; t < T; ++t)
    cut_fraction[t] = std::clamp(0.5 * (cut_fraction[t] + target[t]), cut_fraction[t - 1], 1.0);
}

std::vector<double> equal_cuts(std::size_t T) {
  std::vector<double> cuts(T + 1);
  for (std::size_t t = 0; t <= T; ++t) cuts[t] = static_cast<double>(t) / static_cast<double>(T);
  return cuts;
}

}  // namespace

bool ForcePartition::matches(const ContactStore& contacts, std::size_t n_particles, std::size_t n_walls,
                             int thread_count) const {
  return revision_ == contacts.revision() && first_data_ == contacts.particle_pairs.first.data() &&
         n_pairs_ == contacts.particle_pairs.size() && n_particles_ == n_particles && n_walls_ == n_walls &&
         threads == thread_count && steps_since_build < kStepsPerRebalance;
}

void ForcePartition::build(const ContactStore& contacts, std::size_t n, std::size_t n_walls, int thread_count) {
  const auto& pp = contacts.particle_pairs;
  const auto& pw = contacts.wall_pairs;
  const std::size_t n_pairs = pp.size(), T = static_cast<std::size_t>(thread_count);
  if (threads == thread_count && pair_cut_fraction_.size() == T + 1 && n_particles_ == n) {
    rebalance(pair_cut_fraction_, pair_busy_seconds);
    rebalance(finish_cut_fraction_, finish_busy_seconds);
  } else {
    pair_cut_fraction_ = equal_cuts(T);
    finish_cut_fraction_ = equal_cuts(T);
  }
  threads = thread_count;
  pair_busy_seconds.assign(T, 0.0);
  finish_busy_seconds.assign(T, 0.0);
  steps_since_build = 0;

  // Ranges: cut the pair list at the cut fractions, each cut moved back to the first pair
  // of its first body (a body's pairs stay with one thread).
  particle_begin.assign(T + 1, 0);
  pair_begin.assign(T + 1, 0);
  particle_begin[T] = n;
  pair_begin[T] = n_pairs;
  for (std::size_t t = 1; t < T; ++t) {
    const std::size_t cut =
        std::min(n_pairs, static_cast<std::size_t>(pair_cut_fraction_[t] * static_cast<double>(n_pairs)));
    std::size_t a = cut < n_pairs ? pp.first[cut] : n;
    a = std::max(a, particle_begin[t - 1]);
    particle_begin[t] = a;
    pair_begin[t] = static_cast<std::size_t>(
        std::lower_bound(pp.first.begin(), pp.first.end(), static_cast<Index>(a)) - pp.first.begin());
  }

  // Boundary particles: second body of a pair computed by another (lower) range.
  boundary.assign(n, 0);
  for (std::size_t t = 0; t < T; ++t)
    for (std::size_t c = pair_begin[t]; c < pair_begin[t + 1]; ++c)
      if (pp.second[c] >= particle_begin[t + 1]) boundary[pp.second[c]] = 1;

  // Slots: every pair with a boundary body.
  slot.assign(n_pairs, kNoSlot);
  Index n_slots = 0;
  for (std::size_t c = 0; c < n_pairs; ++c)
    if (boundary[pp.first[c]] || boundary[pp.second[c]]) slot[c] = n_slots++;
  slot_force.resize(n_slots);
  slot_torque_1.resize(n_slots);
  slot_torque_2.resize(n_slots);

  boundary_particles.clear();
  std::vector<Index> boundary_index(n, kNoSlot);
  for (std::size_t q = 0; q < n; ++q)
    if (boundary[q]) {
      boundary_index[q] = static_cast<Index>(boundary_particles.size());
      boundary_particles.push_back(static_cast<Index>(q));
    }
  // Finishing ranges: cuts at fractions of the particles.
  finish_begin.assign(T + 1, 0);
  finish_begin[T] = n;
  for (std::size_t t = 1; t < T; ++t)
    finish_begin[t] = std::clamp(static_cast<std::size_t>(finish_cut_fraction_[t] * static_cast<double>(n)),
                                 finish_begin[t - 1], n);
  boundary_begin.assign(T + 1, 0);
  for (std::size_t t = 0; t <= T; ++t)
    boundary_begin[t] = static_cast<std::size_t>(
        std::lower_bound(boundary_particles.begin(), boundary_particles.end(), static_cast<Index>(finish_begin[t])) -
        boundary_particles.begin());

  // Gather lists of the boundary particles, in pair order.
  const std::size_t nb = boundary_particles.size();
  gather_start.assign(nb + 1, 0);
  for (std::size_t c = 0; c < n_pairs; ++c) {
    if (slot[c] == kNoSlot) continue;
    if (boundary[pp.first[c]]) ++gather_start[boundary_index[pp.first[c]] + 1];
    if (boundary[pp.second[c]]) ++gather_start[boundary_index[pp.second[c]] + 1];
  }
  for (std::size_t b = 0; b < nb; ++b) gather_start[b + 1] += gather_start[b];
  gather_entries.resize(gather_start[nb]);
  std::vector<Index> fill(gather_start.begin(), gather_start.end() - 1);
  for (std::size_t c = 0; c < n_pairs; ++c) {  // increasing c: each list is in pair order
    if (slot[c] == kNoSlot) continue;
    if (boundary[pp.first[c]]) gather_entries[fill[boundary_index[pp.first[c]]]++] = 2 * slot[c] + 1;
    if (boundary[pp.second[c]]) gather_entries[fill[boundary_index[pp.second[c]]]++] = 2 * slot[c];
  }

  // Wall pairs: sorted by (wall, particle), so each wall's pairs split by range by search.
  wall_pair_begin.assign(n_walls * (T + 1), 0);
  for (std::size_t w = 0; w < n_walls; ++w) {
    const auto seg_begin = std::lower_bound(pw.wall.begin(), pw.wall.end(), static_cast<Index>(w));
    const auto seg_end = std::lower_bound(seg_begin, pw.wall.end(), static_cast<Index>(w + 1));
    const std::size_t offset = static_cast<std::size_t>(seg_begin - pw.wall.begin());
    const auto p_begin = pw.particle.begin() + static_cast<std::ptrdiff_t>(offset);
    const auto p_end = pw.particle.begin() + (seg_end - pw.wall.begin());
    for (std::size_t t = 0; t <= T; ++t)
      wall_pair_begin[w * (T + 1) + t] = static_cast<std::size_t>(
          std::lower_bound(p_begin, p_end, static_cast<Index>(finish_begin[t])) - pw.particle.begin());
  }
  wall_force.resize(pw.size());
  wall_carries.resize(pw.size());
  pair_logs.resize(T);
  wall_logs.resize(n_walls * T);

  revision_ = contacts.revision();
  first_data_ = pp.first.data();
  n_pairs_ = n_pairs;
  n_particles_ = n;
  n_walls_ = n_walls;
}

}  // namespace colza
