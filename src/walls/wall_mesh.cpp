#include "walls/wall_mesh.hpp"

#include <algorithm>
#include <cmath>

namespace colza {

namespace {

// Two unit vectors spanning the plane normal to `n` (n unit).
void tangent_frame(const Vec3& n, Vec3& u, Vec3& v) {
  const Vec3 helper = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  u = (helper - helper.dot(n) * n).normalized();
  v = n.cross(u);
}

WallMesh quad(const Vec3& centre, const Vec3& u, const Vec3& v, double half_u, double half_v) {
  WallMesh m;
  m.points = {centre - half_u * u - half_v * v, centre + half_u * u - half_v * v, centre + half_u * u + half_v * v,
              centre - half_u * u + half_v * v};
  m.quads = {{0, 1, 2, 3}};
  return m;
}

}  // namespace

WallMesh wall_mesh(const Wall& w, const Vec3& lo, const Vec3& hi, double pad) {
  const Vec3 mid = 0.5 * (lo + hi);
  const double half_diagonal = 0.5 * (hi - lo).norm() + pad;
  switch (w.shape) {
    case WallShape::kRectangle:
      return quad(w.origin, w.axis_u, w.axis_v, w.half_u, w.half_v);
    case WallShape::kPlane: {
      Vec3 u, v;
      tangent_frame(w.normal, u, v);
      const Vec3 centre = mid - (mid - w.origin).dot(w.normal) * w.normal;
      return quad(centre, u, v, half_diagonal, half_diagonal);
    }
    case WallShape::kCylinder: {
      // Axial range: the wall's, clamped to the particles' extent along the axis (+- pad).
      const double at_mid = (mid - w.origin).dot(w.normal);
      const double a0 = std::max(w.axial_min, at_mid - half_diagonal);
      const double a1 = std::min(w.axial_max, at_mid + half_diagonal);
      Vec3 u, v;
      tangent_frame(w.normal, u, v);
      WallMesh m;
      for (int k = 0; k < kCylinderSegments; ++k) {
        const double phi = 2.0 * kPi * k / kCylinderSegments;
        const Vec3 radial = w.radius * (std::cos(phi) * u + std::sin(phi) * v);
        m.points.push_back(w.origin + a0 * w.normal + radial);
        m.points.push_back(w.origin + a1 * w.normal + radial);
      }
      for (int k = 0; k < kCylinderSegments; ++k) {
        const int next = (k + 1) % kCylinderSegments;
        m.quads.push_back({2 * k, 2 * next, 2 * next + 1, 2 * k + 1});
      }
      return m;
    }
  }
  return {};
}

}  // namespace colza
