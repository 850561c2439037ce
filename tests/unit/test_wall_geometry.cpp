// Sphere-wall contact geometry (physics.md section 2 and walls/wall.hpp): the wall is body 1,
// n points from the wall into the sphere, un = R - distance(centre, wall surface), and the
// contact point is the middle of the overlap, c = x - (R - un/2) n.
#include <gtest/gtest.h>

#include <cmath>

#include "walls/wall.hpp"

using namespace colza;

namespace {

constexpr double kTol = 1e-14;

void expect_vec(const Vec3& got, const Vec3& expected, const char* what) {
  EXPECT_NEAR((got - expected).norm(), 0.0, kTol) << what << ": got (" << got.transpose() << "), expected ("
                                                  << expected.transpose() << ")";
}

// Checks overlap, normal, and that the point is x - (R - un/2) n.
void expect_geometry(const WallContactGeometry& g, const Vec3& x, double R, double overlap, const Vec3& normal,
                     const Vec3& point) {
  ASSERT_TRUE(g.in_range);
  EXPECT_NEAR(g.overlap, overlap, kTol);
  expect_vec(g.normal, normal, "normal");
  EXPECT_NEAR(g.normal.norm(), 1.0, kTol);
  expect_vec(g.point, point, "contact point");
  expect_vec(g.point, x - (R - 0.5 * g.overlap) * g.normal, "c = x - (R - un/2) n");
}

}  // namespace

TEST(WallGeometry, Plane) {
  // Plane z = 1, normal given unnormalised (0, 0, 2). Sphere R = 0.5 at z = 1.4: distance 0.4,
  // un = 0.1, n = +z; overlap spans z in [0.9, 1.0], its middle 0.95 = c_z.
  const Wall w = Wall::plane("p", Vec3(0, 0, 1), Vec3(0, 0, 2));
  const Vec3 x(3, 4, 1.4);
  expect_geometry(wall_sphere_geometry(w, x, 0.5), x, 0.5, 0.1, Vec3::UnitZ(), Vec3(3, 4, 0.95));
  // Separated sphere: negative overlap R - distance = 0.5 - 0.7 = -0.2.
  EXPECT_NEAR(wall_sphere_geometry(w, Vec3(0, 0, 1.7), 0.5).overlap, -0.2, kTol);
}

TEST(WallGeometry, TiltedPlane) {
  // Plane through the origin with normal (1, 1, 0)/sqrt2. Centre (0.3, 0.3, 7): distance
  // 0.6/sqrt2 = 0.3 sqrt2; R = 0.5 -> un = 0.5 - 0.3 sqrt2.
  const Vec3 n = Vec3(1, 1, 0) / std::sqrt(2.0);
  const Wall w = Wall::plane("p", Vec3::Zero(), Vec3(1, 1, 0));
  const Vec3 x(0.3, 0.3, 7.0);
  const double un = 0.5 - 0.3 * std::sqrt(2.0);
  expect_geometry(wall_sphere_geometry(w, x, 0.5), x, 0.5, un, n, x - (0.5 - un / 2) * n);
}

TEST(WallGeometry, CylinderInnerSurface) {
  // Axis z through (1, 2, 0), radius 1, extent z in [0, 2] from the origin point.
  const Wall w = Wall::cylinder("c", Vec3(1, 2, 0), Vec3(0, 0, 3), 1.0, 0.0, 2.0);
  // Sphere R = 0.3 at radial offset 0.8 along +x: wall at distance 1 - 0.8 = 0.2, un = 0.1,
  // n = -x (from the wall inwards, into the sphere); the sphere surface reaches radial offset
  // 0.8 + 0.3 = 1.1, beyond the wall at 1.0: the overlap spans [1.0, 1.1], its middle is 1.05.
  const Vec3 x(1.8, 2.0, 1.0);
  expect_geometry(wall_sphere_geometry(w, x, 0.3), x, 0.3, 0.1, -Vec3::UnitX(), Vec3(2.05, 2.0, 1.0));
  // Oblique radial direction (0.6, 0.8) at offset rho = 0.5: un = 0.3 - 0.5 = -0.2 (not touching);
  // normal -(0.6, 0.8, 0).
  const Vec3 y(1.0 + 0.3, 2.0 + 0.4, 0.5);
  const WallContactGeometry g = wall_sphere_geometry(w, y, 0.3);
  ASSERT_TRUE(g.in_range);
  EXPECT_NEAR(g.overlap, -0.2, kTol);
  expect_vec(g.normal, Vec3(-0.6, -0.8, 0), "oblique normal");
  // Beyond the axial extent, or exactly on the axis: cannot touch.
  EXPECT_FALSE(wall_sphere_geometry(w, Vec3(1.8, 2.0, 2.5), 0.3).in_range);
  EXPECT_FALSE(wall_sphere_geometry(w, Vec3(1.8, 2.0, -0.1), 0.3).in_range);
  EXPECT_FALSE(wall_sphere_geometry(w, Vec3(1.0, 2.0, 1.0), 0.3).in_range);
}

TEST(WallGeometry, RectangleFaceBothSides) {
  // Centre origin, normal +z, u = +x, half extents 1 (u) and 0.5 (v = n x u = +y).
  const Wall w = Wall::rectangle("r", Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), 1.0, 0.5);
  expect_vec(w.axis_v, Vec3::UnitY(), "v = n x u");
  // Above the face: distance 0.4, un = 0.1, n = +z, c = x - 0.45 z.
  const Vec3 a(0.3, 0.2, 0.4);
  expect_geometry(wall_sphere_geometry(w, a, 0.5), a, 0.5, 0.1, Vec3::UnitZ(), Vec3(0.3, 0.2, -0.05));
  // Below: a two-sided plate, n = -z.
  const Vec3 b(0.3, 0.2, -0.4);
  expect_geometry(wall_sphere_geometry(w, b, 0.5), b, 0.5, 0.1, -Vec3::UnitZ(), Vec3(0.3, 0.2, 0.05));
}

TEST(WallGeometry, RectangleEdge) {
  const Wall w = Wall::rectangle("r", Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), 1.0, 0.5);
  // In the plane, beyond the edge x = 1: closest point (1, 0.2, 0), distance 0.3, un = 0.2,
  // n = +x, overlap spans x in [0.8, 1.0], middle 0.9.
  const Vec3 a(1.3, 0.2, 0.0);
  expect_geometry(wall_sphere_geometry(w, a, 0.5), a, 0.5, 0.2, Vec3::UnitX(), Vec3(0.9, 0.2, 0.0));
  // Above and beyond the edge: d = (0.24, 0, 0.32), |d| = 0.4, un = 0.1, n = (0.6, 0, 0.8).
  const Vec3 b(1.24, 0.2, 0.32);
  const Vec3 n(0.6, 0.0, 0.8);
  expect_geometry(wall_sphere_geometry(w, b, 0.5), b, 0.5, 0.1, n, b - 0.45 * n);
}

TEST(WallGeometry, RectangleCorner) {
  const Wall w = Wall::rectangle("r", Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), 1.0, 0.5);
  // Corner (1, 0.5, 0); centre at corner + (0.2, 0.2, 0.1): |d| = 0.3, un = 0.5 - 0.3 = 0.2,
  // n = (2, 2, 1)/3, c = x - 0.4 n.
  const Vec3 x(1.2, 0.7, 0.1);
  const Vec3 n = Vec3(2, 2, 1) / 3.0;
  expect_geometry(wall_sphere_geometry(w, x, 0.5), x, 0.5, 0.2, n, x - 0.4 * n);
}

TEST(WallGeometry, RotatedRectangle) {
  // Vertical plate: centre (0, 1, 0), normal +y, u given as (1, 1, 0) -> orthonormalised to +x,
  // v = n x u = y x x = -z. Half extents u 0.5, v 2.
  const Wall w = Wall::rectangle("r", Vec3(0, 1, 0), Vec3::UnitY(), Vec3(1, 1, 0), 0.5, 2.0);
  expect_vec(w.axis_u, Vec3::UnitX(), "u");
  expect_vec(w.axis_v, -Vec3::UnitZ(), "v");
  // Sphere R = 0.25 at (0.1, 0.8, -1.5): face side -y, distance 0.2, un = 0.05, n = -y; the
  // sphere reaches y = 1.05 beyond the plate at y = 1, so c_y = 1.025.
  const Vec3 x(0.1, 0.8, -1.5);
  expect_geometry(wall_sphere_geometry(w, x, 0.25), x, 0.25, 0.05, -Vec3::UnitY(), Vec3(0.1, 1.025, -1.5));
  // Beyond the v extent (z < -2): edge z = -2, d = (0, -0.2, -0.15), |d| = 0.25, un = 0.
  const Vec3 y(0.1, 0.8, -2.15);
  const WallContactGeometry g = wall_sphere_geometry(w, y, 0.25);
  ASSERT_TRUE(g.in_range);
  EXPECT_NEAR(g.overlap, 0.0, kTol);
  expect_vec(g.normal, Vec3(0, -0.8, -0.6), "edge normal");
}

TEST(WallGeometry, RectangleEdgeRestrictions) {
  Wall w = Wall::rectangle("r", Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), 1.0, 0.5);
  set_edge_contact(w, Vec3(1.0, 0.0, 0.0), EdgeContact::kNone);  // the edge x = +1 (u_max)
  EXPECT_EQ(w.edges.u_max, EdgeContact::kNone);
  EXPECT_EQ(w.edges.u_min, EdgeContact::kBothSides);
  // kNone: beyond it no contact (RectangleEdge's sphere a), nor at the corner beyond it.
  EXPECT_FALSE(wall_sphere_geometry(w, Vec3(1.3, 0.2, 0.0), 0.5).in_range);
  EXPECT_FALSE(wall_sphere_geometry(w, Vec3(1.2, 0.7, 0.1), 0.5).in_range);
  // On the face up to the edge, and beyond the unrestricted edges, as before.
  const Vec3 on_face(0.99, 0.2, 0.3);
  expect_geometry(wall_sphere_geometry(w, on_face, 0.5), on_face, 0.5, 0.2, Vec3::UnitZ(), Vec3(0.99, 0.2, -0.1));
  const Vec3 beyond_free(-1.3, 0.2, 0.0);
  expect_geometry(wall_sphere_geometry(w, beyond_free, 0.5), beyond_free, 0.5, 0.2, -Vec3::UnitX(),
                  Vec3(-0.9, 0.2, 0.0));
  // kFrontOnly: beyond the edge, only spheres on the normal's side (h > 0; in the plane, none).
  set_edge_contact(w, Vec3(1.0, -0.3, 0.0), EdgeContact::kFrontOnly);  // any point of the edge's line names it
  const Vec3 in_front(1.24, 0.2, 0.32);  // RectangleEdge's sphere b: un = 0.1, n = (0.6, 0, 0.8)
  const Vec3 n(0.6, 0.0, 0.8);
  expect_geometry(wall_sphere_geometry(w, in_front, 0.5), in_front, 0.5, 0.1, n, in_front - 0.45 * n);
  EXPECT_FALSE(wall_sphere_geometry(w, Vec3(1.24, 0.2, -0.32), 0.5).in_range);  // behind
  EXPECT_FALSE(wall_sphere_geometry(w, Vec3(1.3, 0.2, 0.0), 0.5).in_range);     // in the plane
  EXPECT_TRUE(wall_sphere_geometry(w, Vec3(0.9, 0.2, -0.3), 0.5).in_range);     // the face, from behind
  set_edge_contact(w, Vec3(1.0, 0.0, 0.0), EdgeContact::kBothSides);
  EXPECT_TRUE(wall_sphere_geometry(w, Vec3(1.3, 0.2, 0.0), 0.5).in_range);
  EXPECT_THROW(set_edge_contact(w, Vec3(0.5, 0.0, 0.0), EdgeContact::kNone), std::invalid_argument);  // no edge there
}
