// ForcePartition (engine/force_partition.hpp): the invariants the threaded force loop relies
// on, checked on random sorted pair lists for 1 to 40 ranges (more ranges than particles
// included). The bit-for-bit agreement of the threaded loop with the serial one is checked
// in test_force_paths.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_int_distribution.hpp>

#include "engine/force_partition.hpp"

using namespace colza;

namespace {

constexpr std::size_t kParticles = 30, kWalls = 3;

ContactStore random_store(unsigned seed) {
  boost::random::mt19937 rng(seed);
  boost::random::uniform_int_distribution<unsigned> pick(0, kParticles - 1);
  std::set<std::pair<Index, Index>> pairs;
  while (pairs.size() < 120) {
    const Index a = pick(rng), b = pick(rng);
    if (a != b) pairs.insert({std::min(a, b), std::max(a, b)});
  }
  std::vector<Index> first, second;
  for (const auto& [a, b] : pairs) {
    first.push_back(a);
    second.push_back(b);
  }
  std::set<std::pair<Index, Index>> wall_pairs;
  while (wall_pairs.size() < 25) wall_pairs.insert({pick(rng) % kWalls, pick(rng)});
  std::vector<Index> wall, particle;
  for (const auto& [w, p] : wall_pairs) {
    wall.push_back(w);
    particle.push_back(p);
  }
  ContactStore store;
  store.adopt_particle_pairs(std::move(first), std::move(second));
  store.adopt_wall_pairs(std::move(wall), std::move(particle));
  return store;
}

std::size_t range_in(const std::vector<std::size_t>& begin, std::size_t q) {
  std::size_t r = 0;
  while (begin[r + 1] <= q) ++r;
  return r;
}
std::size_t range_of(const ForcePartition& part, std::size_t q) { return range_in(part.particle_begin, q); }
std::size_t finishing_range_of(const ForcePartition& part, std::size_t q) { return range_in(part.finish_begin, q); }

void check_invariants(const ContactStore& store, const ForcePartition& part, int threads) {
  const auto& pp = store.particle_pairs;
  const auto& pw = store.wall_pairs;
  const std::size_t T = static_cast<std::size_t>(threads);
  ASSERT_EQ(part.particle_begin.size(), T + 1);
  EXPECT_EQ(part.particle_begin.front(), 0u);
  EXPECT_EQ(part.particle_begin.back(), kParticles);
  for (std::size_t t = 0; t < T; ++t) {
    EXPECT_LE(part.particle_begin[t], part.particle_begin[t + 1]);
    // pair range t = the pairs whose first body is in particle range t
    for (std::size_t c = part.pair_begin[t]; c < part.pair_begin[t + 1]; ++c) EXPECT_EQ(range_of(part, pp.first[c]), t);
  }
  ASSERT_EQ(part.finish_begin.size(), T + 1);
  EXPECT_EQ(part.finish_begin.front(), 0u);
  EXPECT_EQ(part.finish_begin.back(), kParticles);
  for (std::size_t t = 0; t < T; ++t) EXPECT_LE(part.finish_begin[t], part.finish_begin[t + 1]);
  EXPECT_EQ(part.pair_begin.front(), 0u);
  EXPECT_EQ(part.pair_begin.back(), pp.size());
  // boundary <=> a partner in another range; every pair of a boundary particle has a slot
  std::vector<std::uint8_t> boundary(kParticles, 0);
  for (std::size_t c = 0; c < pp.size(); ++c)
    if (range_of(part, pp.first[c]) != range_of(part, pp.second[c])) boundary[pp.second[c]] = 1;
  EXPECT_EQ(part.boundary, boundary);
  std::set<Index> slots;
  for (std::size_t c = 0; c < pp.size(); ++c) {
    const bool needs = boundary[pp.first[c]] || boundary[pp.second[c]];
    EXPECT_EQ(part.slot[c] != ForcePartition::kNoSlot, needs) << "pair " << c;
    if (needs) EXPECT_TRUE(slots.insert(part.slot[c]).second) << "slot used twice";
  }
  EXPECT_EQ(slots.size(), part.slot_force.size());
  // each boundary particle's gather list = all its pairs, in pair order, with its role
  for (std::size_t b = 0; b < part.boundary_particles.size(); ++b) {
    const Index q = part.boundary_particles[b];
    EXPECT_TRUE(boundary[q]);
    std::vector<Index> expected;
    for (std::size_t c = 0; c < pp.size(); ++c) {
      if (pp.first[c] == q) expected.push_back(2 * part.slot[c] + 1);
      if (pp.second[c] == q) expected.push_back(2 * part.slot[c]);
    }
    const std::vector<Index> got(part.gather_entries.begin() + part.gather_start[b],
                                 part.gather_entries.begin() + part.gather_start[b + 1]);
    EXPECT_EQ(got, expected) << "particle " << q;
    const std::size_t r = finishing_range_of(part, q);
    EXPECT_GE(b, part.boundary_begin[r]);
    EXPECT_LT(b, part.boundary_begin[r + 1]);
  }
  EXPECT_EQ(part.boundary_particles.size(),
            static_cast<std::size_t>(std::count(boundary.begin(), boundary.end(), std::uint8_t{1})));
  // wall pairs: range t of wall w holds exactly that wall's pairs with particles in
  // finishing range t
  std::size_t covered = 0;
  for (std::size_t w = 0; w < kWalls; ++w)
    for (std::size_t t = 0; t < T; ++t)
      for (std::size_t c = part.wall_pair_begin[w * (T + 1) + t]; c < part.wall_pair_begin[w * (T + 1) + t + 1];
           ++c, ++covered) {
        EXPECT_EQ(pw.wall[c], w);
        EXPECT_EQ(finishing_range_of(part, pw.particle[c]), t);
      }
  EXPECT_EQ(covered, pw.size());
}

}  // namespace

TEST(ForcePartition, RangesBoundaryLayerSlotsAndGatherListsAreConsistent) {
  for (unsigned seed : {1u, 2u, 3u})
    for (int threads : {1, 2, 3, 5, 40}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", " + std::to_string(threads) + " ranges");
      const ContactStore store = random_store(seed);
      ForcePartition part;
      part.build(store, kParticles, kWalls, threads);
      check_invariants(store, part, threads);
      EXPECT_TRUE(part.matches(store, kParticles, kWalls, threads));
      EXPECT_FALSE(part.matches(store, kParticles, kWalls, threads + 1));
    }
}

TEST(ForcePartition, RebalancedCutsKeepTheInvariantsAndFollowTheBusyTime) {
  const ContactStore store = random_store(4);
  ForcePartition part;
  part.build(store, kParticles, kWalls, 2);
  const std::size_t first_cut = part.pair_begin[1], first_finish_cut = part.finish_begin[1];
  EXPECT_EQ(first_finish_cut, kParticles / 2);  // a new system starts from equal shares
  // Range 0 was slower before the barrier: its share of the pairs must shrink. Range 1 was
  // slower after it: its share of the particles must shrink (the other cut, independently).
  part.pair_busy_seconds = {3.0, 1.0};
  part.finish_busy_seconds = {1.0, 3.0};
  part.build(store, kParticles, kWalls, 2);
  check_invariants(store, part, 2);
  EXPECT_LT(part.pair_begin[1], first_cut);
  EXPECT_GT(part.finish_begin[1], first_finish_cut);
  // A list change is seen (revision), and so is the step count for the periodic rebalance.
  ContactStore changed = store;
  changed.adopt_particle_pairs(changed.particle_pairs.first, changed.particle_pairs.second);
  EXPECT_FALSE(part.matches(changed, kParticles, kWalls, 2));
  part.steps_since_build = ForcePartition::kStepsPerRebalance;
  EXPECT_FALSE(part.matches(store, kParticles, kWalls, 2));
}
