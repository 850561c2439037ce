// Seeded random non-overlapping placement (physics.md section 4, "Generation"):
// same request and seed -> the same packing bit for bit; spheres inside the region,
// non-overlapping, diameters uniform on [d_min, d_max].
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "scenario/generation.hpp"

using namespace colza;

namespace {

GenerationRequest box_request(std::uint64_t seed) {
  GenerationRequest r;
  // 50 mm cube, 200 spheres of 6-7 mm: solid fraction about 200 * pi/6 (6.5e-3)^3 / 1.25e-4 = 0.23,
  // well below the random sequential addition limit (~0.38).
  r.region = GenerationRegion::box(Vec3(0.0, 0.0, 0.0), Vec3(0.05, 0.05, 0.05));
  r.count = 200;
  r.diameter_min = 6e-3;
  r.diameter_max = 7e-3;
  r.seed = seed;
  return r;
}

GenerationRequest cylinder_request(std::uint64_t seed) {
  GenerationRequest r;
  // The oedometer's generation region: diameter 100 mm, height 200 mm (here 100 mm, 500 spheres).
  r.region = GenerationRegion::vertical_cylinder(Vec3(0.01, -0.02, 0.0), 0.05, 0.1);
  r.count = 500;
  r.diameter_min = 6e-3;
  r.diameter_max = 7e-3;
  r.seed = seed;
  return r;
}

bool bitwise_equal(const std::vector<PackedSphere>& a, const std::vector<PackedSphere>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double da[4] = {a[i].position.x(), a[i].position.y(), a[i].position.z(), a[i].radius};
    const double db[4] = {b[i].position.x(), b[i].position.y(), b[i].position.z(), b[i].radius};
    if (std::memcmp(da, db, sizeof da) != 0) return false;
  }
  return true;
}

void check_packing(const GenerationRequest& req, const std::vector<PackedSphere>& s) {
  ASSERT_EQ(s.size(), req.count);
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double d = 2.0 * s[i].radius;
    EXPECT_GE(d, req.diameter_min) << i;
    EXPECT_LE(d, req.diameter_max) << i;
    const Vec3& x = s[i].position;
    // Inside the region (whole sphere, not only its centre).
    EXPECT_GE(x.z() - s[i].radius, req.region.lo.z()) << i;
    EXPECT_LE(x.z() + s[i].radius, req.region.hi.z()) << i;
    if (req.region.shape == GenerationRegion::Shape::kBox) {
      for (int k = 0; k < 2; ++k) {
        EXPECT_GE(x[k] - s[i].radius, req.region.lo[k]) << i;
        EXPECT_LE(x[k] + s[i].radius, req.region.hi[k]) << i;
      }
    } else {
      const double rho = std::hypot(x.x() - req.region.axis_point.x(), x.y() - req.region.axis_point.y());
      EXPECT_LE(rho + s[i].radius, req.region.radius * (1 + 1e-15)) << i;
    }
    // Non-overlapping: |xi - xj| >= Ri + Rj for every pair (brute force, n^2/2 checks).
    for (std::size_t j = 0; j < i; ++j)
      ASSERT_GE((s[j].position - x).norm(), s[i].radius + s[j].radius) << i << " overlaps " << j;
  }
}

}  // namespace

TEST(Generation, SameSeedSamePackingBitForBit) {
  for (const GenerationRequest& req : {box_request(42), cylinder_request(42)}) {
    const auto a = generate_spheres(req);
    const auto b = generate_spheres(req);
    ASSERT_EQ(a.size(), req.count);
    EXPECT_TRUE(bitwise_equal(a, b));
  }
}

// The same seed gives the same spheres on every machine and with every compiler: the first
// three spheres of box_request(7), bit for bit, as an independent implementation of
// mt19937_64, Boost's uniform_real_distribution and the draw order gives them
// (tests/unit/generation_reference.py prints these numbers).
TEST(GenerationReference, FirstSpheresOfSeed7AreTheReferenceImplementationsBits) {
  const std::vector<PackedSphere> reference = {
      {Vec3(0.03589528423245017, 0.01285790343819985, 0.045035523822985424), 0.003377192652076429},
      {Vec3(0.015426435831373698, 0.019872272720786698, 0.02980943903892166), 0.0033778725173700484},
      {Vec3(0.01835532115260589, 0.008436203877161956, 0.006184044668853322), 0.003416084186187875},
  };
  GenerationRequest req = box_request(7);
  req.count = reference.size();
  const auto spheres = generate_spheres(req);
  ASSERT_EQ(spheres.size(), reference.size());
  for (std::size_t i = 0; i < reference.size(); ++i) {
    EXPECT_EQ(spheres[i].position.x(), reference[i].position.x()) << i;
    EXPECT_EQ(spheres[i].position.y(), reference[i].position.y()) << i;
    EXPECT_EQ(spheres[i].position.z(), reference[i].position.z()) << i;
    EXPECT_EQ(spheres[i].radius, reference[i].radius) << i;
  }
}

TEST(Generation, DifferentSeedDifferentPacking) {
  const auto a = generate_spheres(box_request(1));
  const auto b = generate_spheres(box_request(2));
  ASSERT_EQ(a.size(), b.size());
  EXPECT_FALSE(bitwise_equal(a, b));
  // Not merely a shifted tail: the very first sphere differs already.
  EXPECT_NE(a[0].position, b[0].position);
}

TEST(Generation, BoxPackingInsideNonOverlappingDiametersInRange) {
  const GenerationRequest req = box_request(7);
  check_packing(req, generate_spheres(req));
}

TEST(Generation, CylinderPackingInsideNonOverlappingDiametersInRange) {
  const GenerationRequest req = cylinder_request(7);
  check_packing(req, generate_spheres(req));
}

TEST(Generation, DiametersAreUniformOnTheRange) {
  // Uniform on [6, 7] mm: mean 6.5 mm, standard deviation of the mean over n spheres
  // (1 mm / sqrt 12) / sqrt n = 0.0129 mm for n = 500. Allow 5 standard deviations.
  // Also the fraction below 6.5 mm is 1/2 +- 5 sqrt(1/4 / 500) = 0.5 +- 0.112.
  const GenerationRequest req = cylinder_request(3);
  const auto s = generate_spheres(req);
  ASSERT_EQ(s.size(), 500u);
  double sum = 0.0;
  std::size_t below = 0;
  for (const auto& p : s) {
    sum += 2 * p.radius;
    if (2 * p.radius < 6.5e-3) ++below;
  }
  const double mean = sum / s.size();
  EXPECT_NEAR(mean, 6.5e-3, 5 * 1e-3 / std::sqrt(12.0) / std::sqrt(500.0));
  EXPECT_NEAR(static_cast<double>(below) / s.size(), 0.5, 5 * std::sqrt(0.25 / 500.0));
}

// More spheres of d = 6-7 mm than a 10 mm cube can hold (at most 8, see below), with 2000
// failed placements allowed.
namespace {
GenerationRequest spheres_of_6_to_7_mm_in_a_10_mm_cube(std::size_t count) {
  GenerationRequest req;
  req.region = GenerationRegion::box(Vec3::Zero(), Vec3(0.01, 0.01, 0.01));
  req.count = count;
  req.diameter_min = 6e-3;
  req.diameter_max = 7e-3;
  req.max_attempts = 2000;
  return req;
}
}  // namespace

TEST(Generation, StopsWhenAttemptsAreExhausted) {
  // A 10 mm cube cannot hold 1000 spheres of d >= 6 mm. Volume bound: the spheres are disjoint
  // balls inside the 10 mm cube (volume 1e-6 m^3), each of volume >= pi/6 (6e-3)^3 = 1.13e-7 m^3,
  // so at most 8 fit; the generator must give up after max_attempts failures and return fewer.
  const auto s = generate_spheres(spheres_of_6_to_7_mm_in_a_10_mm_cube(1000));
  EXPECT_GE(s.size(), 1u);
  EXPECT_LE(s.size(), 8u);
}

TEST(Generation, AnImpossibleCountIsNotAllocated) {
  // 1e18 spheres in the same 10 mm cube, more than a vector can hold (reserving them throws
  // std::length_error): the generator reserves no more than could ever fit (the Kepler
  // bound, ~7 of d = 6 mm here), so it returns what fits.
  const auto s = generate_spheres(spheres_of_6_to_7_mm_in_a_10_mm_cube(1000000000000000000ULL));
  EXPECT_GE(s.size(), 1u);
  EXPECT_LE(s.size(), 8u);
}

TEST(Generation, AHugeRegionGetsLargerCellsAndTheSamePacking) {
  // A cylinder of 100 m (mm typed for m) asked for a grid of 14286 x 14286 x 29 cells of d_max
  // (std::bad_alloc). The grid now keeps to 8 cells per sphere asked for (4096 at least) by
  // taking larger cells, which find the same overlaps: the spheres placed are those of the
  // d_max grid. Here a 0.5 m cube (72^3 cells of 7 mm): 46656 spheres keep the 7 mm cells,
  // and their first 20 must be the 20 placed on a grid of 4096 cells.
  GenerationRequest many;
  many.region = GenerationRegion::box(Vec3::Zero(), Vec3(0.5, 0.5, 0.5));
  many.count = 46656;
  many.diameter_min = 6e-3;
  many.diameter_max = 7e-3;
  many.seed = 5;
  GenerationRequest few = many;
  few.count = 20;
  const auto all = generate_spheres(many);
  ASSERT_EQ(all.size(), many.count);
  const auto first = generate_spheres(few);
  ASSERT_EQ(first.size(), few.count);
  EXPECT_TRUE(bitwise_equal(first, std::vector<PackedSphere>(all.begin(), all.begin() + 20)));

  GenerationRequest huge = few;
  huge.region = GenerationRegion::vertical_cylinder(Vec3::Zero(), 50.0, 0.2);
  EXPECT_EQ(generate_spheres(huge).size(), few.count);
}
