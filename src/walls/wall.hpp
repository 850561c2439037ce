// Kinematic walls (physics.md section 1): never integrated; they translate with a
// prescribed velocity (or one set each step by a servo). Three shapes:
//   plane     - infinite, one-sided: `normal` points into the particle side;
//   cylinder  - inner surface of a circular cylinder (oedometer envelope), finite along its axis;
//   rectangle - finite, two-sided plate (shear-box faces, rims, plates); its edges and
//               corners are part of the surface, so spheres can touch them, from both
//               sides unless the edge is restricted (RectangleEdges, below).
#pragma once
#include <string>
#include <vector>
#include "core/types.hpp"

namespace colza {

enum class WallShape { kPlane, kCylinder, kRectangle };
const char* to_string(WallShape shape);

// What a rectangle's edge gives a sphere whose projection on the plate's plane lies beyond
// that edge (a corner: beyond two edges, and either may refuse). Without a restriction a
// sphere touching a seam or corner that two plates share gets one contact from each, up to
// twice the force of one surface.
enum class EdgeContact : std::uint8_t {
  kBothSides,  // the edge or corner touches it from either side of the plate (a free edge)
  kFrontOnly,  // only on the normal's side (h > 0): the edge of a convex corner whose back is
               // covered by the plate meeting it there (a shear box's side wall under its rim)
  kNone,       // nothing: another surface takes the contact there (a coplanar neighbour's
               // face at a seam, the side wall at a rim's end)
};

// Whether an edge in state `e` refuses a sphere whose projection lies beyond it; `behind`:
// the sphere is not on the plate's normal side (h <= 0). Shared by the scalar geometry and
// the lanes (engine/wall_batch.hpp), bitwise so that the lanes stay branch-free.
inline bool edge_refuses(EdgeContact e, bool behind) {
  return (e == EdgeContact::kNone) | ((e == EdgeContact::kFrontOnly) & behind);
}

struct RectangleEdges {
  EdgeContact u_min = EdgeContact::kBothSides, u_max = EdgeContact::kBothSides;  // s_u = -half_u, +half_u
  EdgeContact v_min = EdgeContact::kBothSides, v_max = EdgeContact::kBothSides;  // s_v = -half_v, +half_v
};

struct Wall {
  std::string name;
  WallShape shape = WallShape::kPlane;
  Vec3 origin = Vec3::Zero();   // plane: a point on it; cylinder: a point on the axis; rectangle: centre
  Vec3 normal = Vec3::UnitZ();  // plane/rectangle: unit normal; cylinder: unit axis direction
  Vec3 axis_u = Vec3::UnitX();  // rectangle: unit in-plane axes (orthogonal to normal)
  Vec3 axis_v = Vec3::UnitY();
  double half_u = 0.0, half_v = 0.0;          // rectangle half extents (m)
  RectangleEdges edges;                        // rectangle: what each edge gives beyond it
  double radius = 0.0;                         // cylinder inner radius (m)
  double axial_min = 0.0, axial_max = 0.0;     // cylinder extent along its axis from origin (m)
  Vec3 velocity = Vec3::Zero();                // m/s
  std::uint16_t material = 0;                  // index into the wall material table
  // false: fixed spheres get no contact with this wall (a base glued to the plate, which the
  // repose cylinder passes through as it is lifted); free spheres always do.
  bool meets_fixed_spheres = true;

  // Filled by the force computation each step: total contact force exerted BY the
  // particles ON this wall (N), and its contact count.
  Vec3 force = Vec3::Zero();
  Index contact_count = 0;

  static Wall plane(std::string name, const Vec3& point, const Vec3& normal);
  static Wall cylinder(std::string name, const Vec3& axis_point, const Vec3& axis, double radius,
                       double axial_min, double axial_max);
  // Rectangle with centre, unit normal, in-plane axis u (v = normal x u) and half extents.
  static Wall rectangle(std::string name, const Vec3& centre, const Vec3& normal, const Vec3& axis_u,
                        double half_u, double half_v);
};

// Geometry of a sphere touching a wall. The wall is body 1: `normal` points from the
// wall into the sphere, overlap = R - distance(centre, wall surface), and the contact
// point is the middle of the overlap: c = x - (R - overlap/2) normal.
struct WallContactGeometry {
  bool in_range = false;  // false: the sphere cannot touch this wall (e.g. beyond a cylinder's ends)
  double overlap = 0.0;
  Vec3 normal = Vec3::UnitZ();
  Vec3 point = Vec3::Zero();
};

WallContactGeometry wall_sphere_geometry(const Wall& wall, const Vec3& centre, double radius);

// Sets what the edge of rectangle `wall` that passes through `point_on_edge` (a point of the
// edge's line, e.g. its middle; within 1e-9 m) gives beyond it. Throws std::invalid_argument
// when no edge passes there or the wall is not a rectangle.
void set_edge_contact(Wall& wall, const Vec3& point_on_edge, EdgeContact contact);

}  // namespace colza
