// Neighbour search (neighbour/neighbour_search.hpp): the candidate list is every pair closer
// than r_i + r_j + skin, in (first, second) order with first < second, whatever the cell
// grid does; the rebuild test fires exactly when a particle or a wall has moved more than
// skin/2 since the last build (the Verlet-list criterion: two spheres each moving less than
// skin/2 cannot close a gap of skin).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "contact/contact_store.hpp"
#include "core/particles.hpp"
#include "neighbour/neighbour_search.hpp"
#include "walls/wall.hpp"

using namespace colza;

namespace {

constexpr double kSkin = 0.5e-3;  // m

// A polydisperse cloud (radii 2.9-3.6 mm, rapeseed-sized) in a 60 mm box, overlaps allowed:
// dense enough that every particle has several candidates.
ParticleArrays cloud(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> at(-0.03, 0.03), radius(2.9e-3, 3.6e-3);
  ParticleArrays p;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = at(rng), y = at(rng), z = at(rng) + 0.03;
    p.add(Vec3(x, y, z), radius(rng), 1250.0);
  }
  return p;
}

// Every pair i < j with |x_j - x_i| < r_i + r_j + skin, not both anchored, in (i, j) order.
std::vector<std::pair<Index, Index>> brute_force_pairs(const ParticleArrays& p) {
  std::vector<std::pair<Index, Index>> pairs;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      if (p.fixed[i] == kAnchored && p.fixed[j] == kAnchored) continue;
      const double reach = p.radius[i] + p.radius[j] + kSkin;
      if ((p.position[j] - p.position[i]).norm() < reach)
        pairs.emplace_back(static_cast<Index>(i), static_cast<Index>(j));
    }
  return pairs;
}

std::vector<std::pair<Index, Index>> listed_pairs(const ContactStore& s) {
  std::vector<std::pair<Index, Index>> pairs;
  for (std::size_t c = 0; c < s.particle_pairs.size(); ++c)
    pairs.emplace_back(s.particle_pairs.first[c], s.particle_pairs.second[c]);
  return pairs;
}

std::vector<Wall> floor_and_envelope() {
  return {Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()),
          Wall::cylinder("envelope", Vec3::Zero(), Vec3::UnitZ(), 0.032, 0.0, 0.07)};
}

// A unit vector with three equal components: a displacement along it moves every coordinate
// by |d| / sqrt(3), the case the rebuild test's per-coordinate filter is closest to missing.
Vec3 diagonal() { return Vec3(1.0, -1.0, 1.0).normalized(); }

}  // namespace

TEST(NeighbourSearch, CandidatesAreExactlyThePairsWithinReachInPairOrder) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    ParticleArrays p = cloud(900, seed);
    ContactStore store;
    NeighbourSearch search(kSkin);
    search.rebuild(p, floor_and_envelope(), store);
    const auto expected = brute_force_pairs(p);
    ASSERT_GT(expected.size(), 900u) << "seed " << seed;  // a real neighbourhood
    EXPECT_EQ(listed_pairs(store), expected) << "seed " << seed;
    EXPECT_EQ(store.particle_pairs.history.size(), expected.size());
  }
}

// Two anchored spheres (a glued base) are never candidates; an anchored and a free one are,
// and so are two with a prescribed motion (a micro test's).
TEST(NeighbourSearch, TwoAnchoredSpheresAreNeverCandidates) {
  ParticleArrays p = cloud(900, 5);
  std::size_t anchored_pairs = 0;
  for (std::size_t i = 0; i < p.size(); i += 2) p.fixed[i] = i % 4 == 0 ? kAnchored : kPrescribed;
  for (std::size_t i = 0; i < p.size(); i += 4)
    for (std::size_t j = i + 4; j < p.size(); j += 4)
      anchored_pairs += (p.position[j] - p.position[i]).norm() < p.radius[i] + p.radius[j] + kSkin;
  ASSERT_GT(anchored_pairs, 20u);  // the rule has pairs to leave out
  ContactStore store;
  NeighbourSearch(kSkin).rebuild(p, floor_and_envelope(), store, 2);
  const auto expected = brute_force_pairs(p);
  ASSERT_GT(expected.size(), 900u);
  EXPECT_EQ(listed_pairs(store), expected);
}

// The search splits particles in ranges over threads (from 1024 particles on, 512 per
// thread at least) and concatenates the ranges' lists: the same list at any thread count.
TEST(NeighbourSearch, ThreadsGiveTheSameList) {
  ParticleArrays p = cloud(3000, 6);
  ContactStore one;
  NeighbourSearch(kSkin).rebuild(p, floor_and_envelope(), one, 1);
  EXPECT_EQ(listed_pairs(one), brute_force_pairs(p));
  for (int threads : {2, 3, 5}) {
    ContactStore many;
    NeighbourSearch(kSkin).rebuild(p, floor_and_envelope(), many, threads);
    EXPECT_EQ(listed_pairs(many), listed_pairs(one)) << threads << " threads";
  }
}

TEST(NeighbourSearch, WallCandidatesAreWithinSkinInWallThenParticleOrder) {
  ParticleArrays p = cloud(900, 4);
  const std::vector<Wall> walls = floor_and_envelope();
  ContactStore store;
  NeighbourSearch search(kSkin);
  search.rebuild(p, walls, store);
  std::vector<std::pair<Index, Index>> expected;
  for (std::size_t w = 0; w < walls.size(); ++w)
    for (std::size_t i = 0; i < p.size(); ++i) {
      const WallContactGeometry g = wall_sphere_geometry(walls[w], p.position[i], p.radius[i]);
      if (g.in_range && g.overlap > -kSkin) expected.emplace_back(static_cast<Index>(w), static_cast<Index>(i));
    }
  std::vector<std::pair<Index, Index>> listed;
  for (std::size_t c = 0; c < store.wall_pairs.size(); ++c)
    listed.emplace_back(store.wall_pairs.wall[c], store.wall_pairs.particle[c]);
  EXPECT_GT(expected.size(), 50u);
  EXPECT_EQ(listed, expected);
}

// A sphere beyond a finite cylinder's end at a build can move back into the axial range, and
// touch the wall, before the next build (the sphere and the wall each move at most skin/2,
// so its axial coordinate changes by at most a skin): the candidate test takes the
// cylinder as reaching one skin beyond each end.
TEST(NeighbourSearch, AFiniteCylinderReachesOneSkinBeyondItsEnds) {
  const double lower = 0.01, upper = 0.03, cylinder_radius = 0.02, r = 3e-3;  // m
  const std::vector<Wall> walls = {Wall::cylinder("sleeve", Vec3::Zero(), Vec3::UnitZ(), cylinder_radius, lower, upper)};
  struct Placement {
    double axial, gap;  // gap to the cylinder's surface, negative = overlap (m)
    bool candidate;
  };
  const Placement placements[] = {
      {0.5 * (lower + upper), -0.1e-3, true},   // within the range, touching
      {0.5 * (lower + upper), 0.99 * kSkin, true},
      {0.5 * (lower + upper), 1.01 * kSkin, false},
      {upper + 0.99 * kSkin, -0.1e-3, true},     // just beyond an end, but within a skin of it
      {lower - 0.99 * kSkin, -0.1e-3, true},
      {upper + 1.01 * kSkin, -0.1e-3, false},    // more than a skin beyond
      {lower - 1.01 * kSkin, -0.1e-3, false},
  };
  ParticleArrays p;
  std::vector<Index> expected;
  for (std::size_t k = 0; k < std::size(placements); ++k) {
    const double angle = 0.8 * static_cast<double>(k);  // apart from each other (no particle pairs)
    const double rho = cylinder_radius - r - placements[k].gap;
    p.add(Vec3(rho * std::cos(angle), rho * std::sin(angle), placements[k].axial), r, 1250.0);
    if (placements[k].candidate) expected.push_back(static_cast<Index>(k));
  }
  ContactStore store;
  NeighbourSearch(kSkin).rebuild(p, walls, store);
  EXPECT_EQ(store.wall_pairs.particle, expected);
  EXPECT_EQ(store.particle_pairs.size(), 0u);
}

TEST(NeighbourSearch, RebuildIsDueExactlyWhenSomethingMovedMoreThanHalfTheSkin) {
  ParticleArrays p = cloud(1000, 5);  // 15 full blocks of 64 particles and a partial one
  std::vector<Wall> walls = floor_and_envelope();
  ContactStore store;
  NeighbourSearch search(kSkin);
  EXPECT_TRUE(search.needs_rebuild(p, walls));  // never built
  search.rebuild(p, walls, store);
  EXPECT_FALSE(search.needs_rebuild(p, walls));
  const std::vector<Vec3> built = p.position;

  // Every particle moved just under skin/2, along the diagonal: no rebuild.
  for (std::size_t i = 0; i < p.size(); ++i) p.position[i] = built[i] + 0.499 * kSkin * diagonal();
  EXPECT_FALSE(search.needs_rebuild(p, walls));

  // One particle moved just over skin/2 (first block, a middle block, the partial last block).
  for (std::size_t moved : {0u, 517u, 999u}) {
    p.position = built;
    p.position[moved] += 0.501 * kSkin * diagonal();
    EXPECT_TRUE(search.needs_rebuild(p, walls)) << "particle " << moved << " along the diagonal";
    p.position = built;
    p.position[moved].x() -= 0.501 * kSkin;
    EXPECT_TRUE(search.needs_rebuild(p, walls)) << "particle " << moved << " along x";
  }

  // A wall moved more than skin/2.
  p.position = built;
  walls[0].origin.z() += 0.501 * kSkin;
  EXPECT_TRUE(search.needs_rebuild(p, walls));
  walls[0].origin.z() -= 0.002 * kSkin;  // now 0.499 skin from where it was built
  EXPECT_FALSE(search.needs_rebuild(p, walls));

  // Particles added or removed since the build: always a rebuild.
  p.add(Vec3(0.0, 0.0, 0.05), 3e-3, 1250.0);
  EXPECT_TRUE(search.needs_rebuild(p, walls));
}
