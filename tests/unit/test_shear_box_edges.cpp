// Where the shear box's plates meet (walls/wall.hpp, RectangleEdges; shear_box.edge_contacts): with
// "per_wall" every plate touches a sphere on its own, so a sphere at the seam of the upper and
// lower side walls, or at the convex corner of a rim and its side wall, gets two contacts;
// with "per_surface" it gets one. One force pass on one sphere, no gravity, 10 um overlap.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/stepper.hpp"
#include "scenario/shear_box.hpp"

using namespace colza;

namespace {

constexpr double kR = 3.25e-3;       // m
constexpr double kOverlap = 1e-5;    // m, with the face or edge the sphere is placed against
constexpr double kWallKn = 4000e3;   // N/m, the wall's normal stiffness (contact stiffness: "contact" rule)

struct OneSphere {
  std::vector<std::size_t> touching_walls;
  Vec3 force = Vec3::Zero();
};

// The box of data/shear.toml's size; the lower half moved by `shear` (m) along x.
OneSphere touch(const Vec3& centre, BoxEdgeContacts edges, double shear = 0.0) {
  ShearBoxSpec box;
  box.edge_contacts = edges;
  World world;
  build_shear_box(world, box, box.height);
  if (shear > 0.0) {
    for (Wall& w : world.walls)
      if (w.name.rfind("lower_", 0) == 0) w.origin.x() += shear;
    set_trailing_and_leading_seams(world, box, false);
  }
  world.particles.add(centre, kR, 1250.0);
  PhysicsSettings s;
  s.particle_materials = {{"seed", 1250.0, 437e3, 437e3, 0.0}};
  s.wall_materials = {{"wall", kWallKn, kWallKn, 0.0}};
  s.stiffness_rule = StiffnessRule::kContact;
  s.integrator.gravity = Vec3::Zero();
  s.time_step.automatic = false;
  s.time_step.fixed_dt = 1e-6;
  Stepper stepper(s);
  stepper.prepare(world);
  stepper.begin_step(world);
  OneSphere r;
  const auto& pw = world.contacts.wall_pairs;
  for (std::size_t c = 0; c < pw.size(); ++c)
    if (pw.history[c].touching) r.touching_walls.push_back(pw.wall[c]);
  r.force = world.particles.force[0];
  return r;
}

}  // namespace

TEST(ShearBoxEdges, ASphereAtTheSideWallsSeamTouchesOneSurface) {
  // Against the front wall (y = 0), 0.1 mm above the shear plane: on the upper plate's face,
  // and 0.1 mm from the lower plate's top edge, which it overlaps by ~8.5 um too.
  const ShearBoxSpec box;
  const Vec3 x(box.length / 2, kR - kOverlap, box.shear_plane + 1e-4);
  const OneSphere per_wall = touch(x, BoxEdgeContacts::kPerWall);
  const OneSphere per_surface = touch(x, BoxEdgeContacts::kPerSurface);
  EXPECT_EQ(per_wall.touching_walls.size(), 2u);
  ASSERT_EQ(per_surface.touching_walls.size(), 1u);
  // One surface: F = Kn un along +y, exactly. Per wall the lower plate's top edge (the line
  // y = 0, z = shear_plane) adds Kn u_e along its normal: the centre is sqrt((R - un)^2 + h^2)
  // from the edge (h = 0.1 mm), so u_e = R - that = 8.457 um with n_y = (R - un) / that:
  // F_y = Kn (un + u_e n_y) = 1.845 Kn un.
  EXPECT_NEAR(per_surface.force.y(), kWallKn * kOverlap, 1e-9);
  const double to_edge = std::hypot(kR - kOverlap, 1e-4);
  EXPECT_NEAR(per_wall.force.y(), kWallKn * (kOverlap + (kR - to_edge) * (kR - kOverlap) / to_edge), 1e-9);
}

TEST(ShearBoxEdges, ASphereAtARimsConvexCornerTouchesOneEdge) {
  // Lower half moved by 5 mm: its trailing wall's top edge (x = 5 mm, z = sp) and the lower
  // rim's end meet there. A sphere in the open quadrant, on the diagonal, touches that line.
  const ShearBoxSpec box;
  const double s = 5e-3, d = (kR - kOverlap) / std::sqrt(2.0);
  const Vec3 x(s + d, box.width / 2, box.shear_plane + d);
  const OneSphere per_wall = touch(x, BoxEdgeContacts::kPerWall, s);
  const OneSphere per_surface = touch(x, BoxEdgeContacts::kPerSurface, s);
  EXPECT_EQ(per_wall.touching_walls.size(), 2u);
  ASSERT_EQ(per_surface.touching_walls.size(), 1u);
  const double expected = kWallKn * kOverlap;  // along (1, 0, 1)/sqrt(2)
  EXPECT_NEAR(per_surface.force.norm(), expected, 1e-9);
  EXPECT_NEAR(per_surface.force.x(), per_surface.force.z(), 1e-12);
  EXPECT_NEAR(per_wall.force.norm(), 2.0 * expected, 1e-9);
}

TEST(ShearBoxEdges, ASphereOnARimNextToItsCornerTouchesTheRimOnly) {
  // Lower half moved by 5 mm; a sphere on the lower rim 0.1 mm short of its end (x = 5 mm),
  // behind the trailing wall's plane: the rim's face holds it. The trailing wall's top edge,
  // 0.1 mm away too, touches only spheres in front of that wall (per_surface); per wall it
  // adds an edge contact from behind, nearly doubling the force.
  const ShearBoxSpec box;
  const double s = 5e-3;
  const Vec3 x(s - 1e-4, box.width / 2, box.shear_plane + kR - kOverlap);
  const OneSphere per_wall = touch(x, BoxEdgeContacts::kPerWall, s);
  const OneSphere per_surface = touch(x, BoxEdgeContacts::kPerSurface, s);
  EXPECT_EQ(per_wall.touching_walls.size(), 2u);
  ASSERT_EQ(per_surface.touching_walls.size(), 1u);
  EXPECT_NEAR(per_surface.force.z(), kWallKn * kOverlap, 1e-9);
  EXPECT_NEAR(per_surface.force.x(), 0.0, 1e-12);
  // The same under the upper rim, just beyond its end at the upper leading wall (x = L).
  const Vec3 y(box.length + 1e-4, box.width / 2, box.shear_plane - kR + kOverlap);
  EXPECT_EQ(touch(y, BoxEdgeContacts::kPerWall, s).touching_walls.size(), 2u);
  const OneSphere under = touch(y, BoxEdgeContacts::kPerSurface, s);
  ASSERT_EQ(under.touching_walls.size(), 1u);
  EXPECT_NEAR(under.force.z(), -kWallKn * kOverlap, 1e-9);
}

TEST(ShearBoxEdges, AlignedTrailingSeamTouchesOneSurfaceUntilTheHalvesMove) {
  // Before shearing the trailing walls are coplanar (x = 0): a sphere 0.1 mm above the shear
  // plane touches the upper plate's face only; per wall, also the lower plate's top edge and
  // the lower rim's end, which lie on the same line. Once the lower half has moved, its
  // trailing wall's top edge is a real step and touches the sphere too (here by 0.1 mm of
  // shear); the rim's end still hands its edge to that wall.
  const ShearBoxSpec box;
  const Vec3 x(kR - kOverlap, box.width / 2, box.shear_plane + 1e-4);
  EXPECT_EQ(touch(x, BoxEdgeContacts::kPerSurface).touching_walls.size(), 1u);
  EXPECT_EQ(touch(x, BoxEdgeContacts::kPerWall).touching_walls.size(), 3u);
  EXPECT_EQ(touch(x, BoxEdgeContacts::kPerSurface, 1e-4).touching_walls.size(), 2u);
}
