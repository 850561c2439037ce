// The cone fit of a heap's surface (analysis/heap_angle.hpp) on synthetic heaps of spheres
// whose surface lies on a cone of known angle.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_real_distribution.hpp>
#include <cmath>

#include "analysis/heap_angle.hpp"
#include "core/types.hpp"

using namespace colza;

namespace {

struct Heap {
  std::vector<double> x, y, z, r;
  void add(double rho, double theta, double top, double radius) {
    x.push_back(rho * std::cos(theta));
    y.push_back(rho * std::sin(theta));
    z.push_back(top - radius);
    r.push_back(radius);
  }
};

// Spheres of d = 6.5 mm whose tops lie on the cone top = h - rho tan(alpha), h = 60 mm, at
// random azimuths and distances out to the cone's foot, plus as many buried spheres (tops 1-3
// diameters below the surface) that must not count as surface.
Heap cone(double alpha_deg, std::uint32_t seed) {
  Heap heap;
  const double h = 0.060, r = 0.00325, t = std::tan(alpha_deg * kPi / 180.0);
  boost::random::mt19937 rng(seed);
  boost::random::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 3000; ++k) {
    const double rho = h / t * std::sqrt(unit(rng)), theta = 2.0 * kPi * unit(rng);
    heap.add(rho, theta, h - rho * t, r);
    heap.add(rho, theta, h - rho * t - 2.0 * r * (1.0 + 2.0 * unit(rng)), r);
  }
  return heap;
}

}  // namespace

TEST(HeapAngle, RecoversTheAngleOfSpheresOnACone) {
  // Every surface sphere's top lies on the cone, so the fitted line through (rho, top) is the
  // cone's generatrix: the angle to rounding, and an error of ~0.
  for (double alpha : {20.0, 27.5, 35.0}) {
    const Heap heap = cone(alpha, 7);
    const HeapAngle a = fit_heap_angle(heap.x, heap.y, heap.z, heap.r, {});
    ASSERT_TRUE(a.valid) << alpha;
    EXPECT_NEAR(a.angle_deg, alpha, 0.1) << alpha;
    EXPECT_LT(a.angle_error_deg, 1e-6) << alpha;
    EXPECT_NEAR(a.intercept, 0.060, 1e-9) << alpha;
    // The heap's radius: where the surface falls to two diameters above the base,
    // rho = (h - 2 d) / tan(alpha), to within a radial bin (one diameter).
    const double radius = (0.060 - 0.013) / std::tan(alpha * kPi / 180.0);
    EXPECT_NEAR(a.radius, radius, 0.0065) << alpha;
    EXPECT_NEAR(a.height, 0.060, 0.002) << alpha;
    EXPECT_GT(a.points, 50u) << alpha;
    // The fit's spheres, named by index: as many as its points, each a sphere on the cone
    // (cone() adds it at an even index, the buried one below it at the odd one after), in the
    // fit's range of rho.
    ASSERT_EQ(a.fit_spheres.size(), a.points) << alpha;
    for (const std::size_t i : a.fit_spheres) {
      EXPECT_EQ(i % 2, 0u) << alpha << ": sphere " << i << " is buried";
      const double rho = std::hypot(heap.x[i], heap.y[i]);
      EXPECT_TRUE(rho >= a.fit_rho_min && rho <= a.fit_rho_max) << alpha << ": sphere " << i;
    }
  }
}

TEST(HeapAngle, ARoughSurfaceGivesTheAngleWithinItsError) {
  // Tops jittered by up to +/- half a radius (uniform): the angle within 3 of its standard
  // errors and within 0.5 deg, and an error of a few hundredths of a degree, not zero.
  Heap heap = cone(30.0, 11);
  boost::random::mt19937 rng(3);
  boost::random::uniform_real_distribution<double> jitter(-0.5 * 0.00325, 0.5 * 0.00325);
  for (std::size_t i = 0; i < heap.z.size(); i += 2) heap.z[i] += jitter(rng);
  const HeapAngle a = fit_heap_angle(heap.x, heap.y, heap.z, heap.r, {});
  ASSERT_TRUE(a.valid);
  EXPECT_NEAR(a.angle_deg, 30.0, std::max(0.5, 3.0 * a.angle_error_deg));
  EXPECT_GT(a.angle_error_deg, 0.0);
  EXPECT_LT(a.angle_error_deg, 0.5);
}

TEST(HeapAngle, AFlatLayerIsNoHeap) {
  // One layer of spheres on the plate: no top reaches two diameters, R = 0, no fit.
  Heap heap;
  for (int k = 0; k < 100; ++k) heap.add(0.001 * k, 0.1 * k, 0.0065, 0.00325);
  const HeapAngle a = fit_heap_angle(heap.x, heap.y, heap.z, heap.r, {});
  EXPECT_FALSE(a.valid);
  EXPECT_EQ(a.radius, 0.0);
}

TEST(HeapAngle, ASphereOrTwoStackedOnALayerIsNoHeap) {
  // A spread layer (tops at one diameter, 6.5 mm) with two spheres stacked near its centre,
  // tops at 12.1 and 13 mm: the second reaches two diameters above the base, so R = 6.5 mm,
  // under three bins (19.5 mm): no fit, whatever the few points near the axis would slope.
  Heap heap;
  for (int k = 0; k < 300; ++k) heap.add(0.0005 * k, 0.37 * k, 0.0065, 0.00325);
  heap.add(0.004, 0.0, 0.0065 + 0.0056, 0.00325);
  heap.add(0.0065, 1.0, 0.0065 + 0.0065, 0.00325);
  const HeapAngle a = fit_heap_angle(heap.x, heap.y, heap.z, heap.r, {});
  EXPECT_FALSE(a.valid);
  EXPECT_LT(a.radius, 3.0 * 0.0065);
}
