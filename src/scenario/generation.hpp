// Seeded random non-overlapping placement of spheres (physics.md section 4).
// Diameters are uniform on [d_min, d_max]; centres uniform in the region, rejected if the
// sphere would cross the region's boundary or overlap an earlier sphere (random sequential
// addition). Boost.Random (mt19937_64 + uniform_real_distribution) is used because its output
// is specified exactly, and the draws are made in a fixed order (a sphere's diameter, then
// its centre's z, y, x), so the same seed gives the same packing on every machine and with
// every compiler (test GenerationReference.*, from tests/unit/generation_reference.py).
#pragma once
#include <cstdint>
#include <vector>
#include "io/packing_file.hpp"

namespace colza {

struct GenerationRegion {
  enum class Shape { kBox, kCylinder } shape = Shape::kBox;
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  // box corners; cylinder: z range in lo.z()..hi.z()
  Vec3 axis_point = Vec3::Zero();             // cylinder axis (parallel to z) passes through this
  double radius = 0.0;                        // cylinder radius

  static GenerationRegion box(const Vec3& lo, const Vec3& hi);
  static GenerationRegion vertical_cylinder(const Vec3& base_centre, double radius, double height);
  bool contains(const Vec3& centre, double sphere_radius) const;
};

struct GenerationRequest {
  GenerationRegion region;
  std::size_t count = 0;
  double diameter_min = 0.0, diameter_max = 0.0;
  std::uint64_t seed = 1;
  std::uint64_t max_attempts = 1000000;  // total failed placements before giving up
};

// Returns the spheres; fewer than requested only if max_attempts was exhausted (the caller
// reports that as a configuration error).
std::vector<PackedSphere> generate_spheres(const GenerationRequest& request);

}  // namespace colza
