#include "walls/wall.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace colza {

const char* to_string(WallShape shape) {
  switch (shape) {
    case WallShape::kPlane: return "plane";
    case WallShape::kCylinder: return "cylinder";
    case WallShape::kRectangle: return "rectangle";
  }
  return "?";
}

Wall Wall::plane(std::string name, const Vec3& point, const Vec3& normal) {
  Wall w;
  w.name = std::move(name);
  w.shape = WallShape::kPlane;
  w.origin = point;
  w.normal = normal.normalized();
  return w;
}

Wall Wall::cylinder(std::string name, const Vec3& axis_point, const Vec3& axis, double radius,
                    double axial_min, double axial_max) {
  Wall w;
  w.name = std::move(name);
  w.shape = WallShape::kCylinder;
  w.origin = axis_point;
  w.normal = axis.normalized();
  w.radius = radius;
  w.axial_min = axial_min;
  w.axial_max = axial_max;
  return w;
}

Wall Wall::rectangle(std::string name, const Vec3& centre, const Vec3& normal, const Vec3& axis_u,
                     double half_u, double half_v) {
  Wall w;
  w.name = std::move(name);
  w.shape = WallShape::kRectangle;
  w.origin = centre;
  w.normal = normal.normalized();
  // Remove any normal component from u so the frame is orthonormal.
  w.axis_u = (axis_u - axis_u.dot(w.normal) * w.normal).normalized();
  w.axis_v = w.normal.cross(w.axis_u);
  w.half_u = half_u;
  w.half_v = half_v;
  return w;
}

namespace {

WallContactGeometry from_distance(const Vec3& centre, double radius, double distance, const Vec3& normal) {
  WallContactGeometry g;
  g.in_range = true;
  g.overlap = radius - distance;
  g.normal = normal;
  g.point = centre - (radius - 0.5 * g.overlap) * normal;
  return g;
}

WallContactGeometry plane_geometry(const Wall& w, const Vec3& x, double r) {
  const double distance = (x - w.origin).dot(w.normal);  // signed; negative = behind the plane
  return from_distance(x, r, distance, w.normal);
}

WallContactGeometry cylinder_geometry(const Wall& w, const Vec3& x, double r) {
  const Vec3 rel = x - w.origin;
  const double axial = rel.dot(w.normal);
  if (axial < w.axial_min || axial > w.axial_max) return {};
  const Vec3 radial = rel - axial * w.normal;
  const double rho = radial.norm();
  if (rho == 0.0) return {};  // on the axis: cannot touch a cylinder of radius > r
  // Inner surface: the wall lies at distance (Rc - rho) outward; the normal points inward.
  return from_distance(x, r, w.radius - rho, -radial / rho);
}

WallContactGeometry rectangle_geometry(const Wall& w, const Vec3& x, double r) {
  const Vec3 rel = x - w.origin;
  const double su = rel.dot(w.axis_u), sv = rel.dot(w.axis_v);
  const double h = rel.dot(w.normal);
  // Beyond a restricted edge: no contact there (kNone), or none behind the plate (kFrontOnly).
  const bool behind = !(h > 0.0);
  const RectangleEdges& edges = w.edges;
  if ((su < -w.half_u && edge_refuses(edges.u_min, behind)) || (su > w.half_u && edge_refuses(edges.u_max, behind)) ||
      (sv < -w.half_v && edge_refuses(edges.v_min, behind)) || (sv > w.half_v && edge_refuses(edges.v_max, behind)))
    return {};
  const double cu = std::clamp(su, -w.half_u, w.half_u), cv = std::clamp(sv, -w.half_v, w.half_v);
  if (cu == su && cv == sv) {  // projection on the face: plate seen from whichever side the sphere is
    const Vec3 n = (h >= 0.0) ? w.normal : Vec3(-w.normal);
    return from_distance(x, r, std::abs(h), n);
  }
  const Vec3 closest = w.origin + cu * w.axis_u + cv * w.axis_v;  // on an edge or corner
  const Vec3 d = x - closest;
  const double dist = d.norm();
  if (dist == 0.0) return {};
  return from_distance(x, r, dist, d / dist);
}

}  // namespace

void set_edge_contact(Wall& wall, const Vec3& point_on_edge, EdgeContact contact) {
  if (wall.shape != WallShape::kRectangle)
    throw std::invalid_argument("set_edge_contact: " + wall.name + " is not a rectangle");
  const Vec3 rel = point_on_edge - wall.origin;
  const double su = rel.dot(wall.axis_u), sv = rel.dot(wall.axis_v);
  constexpr double kTolerance = 1e-9;  // m
  if (std::abs(su + wall.half_u) < kTolerance) wall.edges.u_min = contact;
  else if (std::abs(su - wall.half_u) < kTolerance) wall.edges.u_max = contact;
  else if (std::abs(sv + wall.half_v) < kTolerance) wall.edges.v_min = contact;
  else if (std::abs(sv - wall.half_v) < kTolerance) wall.edges.v_max = contact;
  else throw std::invalid_argument("set_edge_contact: no edge of " + wall.name + " passes through the point");
}

WallContactGeometry wall_sphere_geometry(const Wall& wall, const Vec3& centre, double radius) {
  switch (wall.shape) {
    case WallShape::kPlane: return plane_geometry(wall, centre, radius);
    case WallShape::kCylinder: return cylinder_geometry(wall, centre, radius);
    case WallShape::kRectangle: return rectangle_geometry(wall, centre, radius);
  }
  return {};
}

}  // namespace colza
