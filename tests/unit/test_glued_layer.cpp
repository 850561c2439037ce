// The glued base of the angle of repose test (scenario/glued_layer.hpp): a monolayer of fixed
// spheres resting on the plate, overlapping none, inside its disc, leaving no hole a sample
// sphere could reach the plate through, the same for the same seed.
#include <gtest/gtest.h>

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_real_distribution.hpp>
#include <cmath>

#include "core/types.hpp"
#include "scenario/glued_layer.hpp"

using namespace colza;

namespace {

// The paper's seeds (6-7 mm) over a 210 mm disc about a 60 mm cylinder: the study's repose base.
GluedLayerRequest study_base(std::uint64_t seed) {
  GluedLayerRequest q;
  q.disc_radius = 0.105;
  q.diameter_min = 0.006;
  q.diameter_max = 0.007;
  q.density = 1250.0;
  q.seed = seed;
  return q;
}

// How far (m) a sphere of radius r resting on the plate at (x, y) is from touching the
// nearest glued sphere, measured horizontally: min_k |p - c_k| - 2 sqrt(r r_k) (two spheres
// resting on the plate touch at a horizontal distance 2 sqrt(r r_k)). Negative: it overlaps
// one, so it cannot rest on the plate there.
double clearance_on_plate(const ParticleArrays& layer, double x, double y, double r) {
  double clearance = 1e9;
  for (std::size_t k = 0; k < layer.size(); ++k)
    clearance = std::min(clearance, std::hypot(x - layer.position[k].x(), y - layer.position[k].y()) -
                                        2.0 * std::sqrt(r * layer.radius[k]));
  return clearance;
}

}  // namespace

TEST(GluedLayer, SpheresRestOnThePlateInsideTheDiscAndOverlapNone) {
  const GluedLayerRequest q = study_base(7);
  const ParticleArrays layer = glued_layer(q);
  // Random sequential addition jams near 55 % of the plane covered: ~570 spheres of 6.5 mm
  // in the 105 mm disc; the fill adds smaller spheres (0.91 r_min) to the holes.
  ASSERT_GT(layer.size(), 450u);
  ASSERT_LT(layer.size(), 900u);
  const double r_fill = 0.9095 * 0.5 * q.diameter_min;  // the header's a^2 r_min
  std::size_t filled = 0;
  for (std::size_t i = 0; i < layer.size(); ++i) {
    const double r = layer.radius[i];
    EXPECT_EQ(layer.fixed[i], kAnchored);
    EXPECT_DOUBLE_EQ(layer.position[i].z(), r);
    EXPECT_GE(r, r_fill * (1.0 - 1e-4));
    EXPECT_LE(r, 0.5 * q.diameter_max);
    filled += r < 0.5 * q.diameter_min;
    EXPECT_LE(std::hypot(layer.position[i].x(), layer.position[i].y()), q.disc_radius);
    for (std::size_t j = i + 1; j < layer.size(); ++j)
      EXPECT_GE((layer.position[i] - layer.position[j]).norm(), r + layer.radius[j]) << i << ", " << j;
  }
  EXPECT_GT(filled, 0u);
}

TEST(GluedLayer, NoSampleSphereReachesThePlateThroughIt) {
  // The fill's guarantee: a sphere of radius r_min (the sample's smallest) lowered onto the
  // plate anywhere in the disc, a diameter from its rim, meets a glued sphere first.
  for (const std::uint64_t seed : {11u, 12u, 13u}) {
    const GluedLayerRequest q = study_base(seed);
    const ParticleArrays layer = glued_layer(q);
    const double r = 0.5 * q.diameter_min;
    boost::random::mt19937 rng(2024 + static_cast<std::uint32_t>(seed));
    boost::random::uniform_real_distribution<double> unit(-1.0, 1.0);
    int probes = 0;
    double widest = -1.0;
    while (probes < 20000) {
      const double x = q.disc_radius * unit(rng), y = q.disc_radius * unit(rng);
      if (std::hypot(x, y) > q.disc_radius - q.diameter_max) continue;
      ++probes;
      widest = std::max(widest, clearance_on_plate(layer, x, y, r));
    }
    EXPECT_LT(widest, 0.0) << "seed " << seed << ": a hole of " << widest << " m";
  }
}

TEST(GluedLayer, TheSameSeedGivesTheSameLayerAndAnotherSeedAnother) {
  const ParticleArrays a = glued_layer(study_base(3)), b = glued_layer(study_base(3)), c = glued_layer(study_base(4));
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.position[i], b.position[i]);
    EXPECT_EQ(a.radius[i], b.radius[i]);
  }
  EXPECT_TRUE(a.size() != c.size() || a.position[0] != c.position[0]);
}

TEST(GluedLayer, BadRequestsThrow) {
  GluedLayerRequest q = study_base(1);
  q.diameter_min = 0.008;  // above diameter_max
  EXPECT_THROW(glued_layer(q), std::invalid_argument);
  q = study_base(1);
  q.disc_radius = 0.0;
  EXPECT_THROW(glued_layer(q), std::invalid_argument);
}
