// Walls as quadrilaterals, for pictures (result.xmf): a rectangle is its one quad; a
// cylinder's inner surface kCylinderSegments quads around its axis between axial_min and
// axial_max (clamped to the particles' extent when a bound is beyond it); an infinite plane
// a square patch centred on the projection of the particles' bounding-box centre, its half
// side the box's half diagonal, padded (it covers every sphere's shadow on the plane).
#pragma once
#include <array>
#include <vector>
#include "core/types.hpp"
#include "walls/wall.hpp"

namespace colza {

inline constexpr int kCylinderSegments = 48;

struct WallMesh {
  std::vector<Vec3> points;
  std::vector<std::array<int, 4>> quads;  // indices into points, in order around each quad
};

// `lo`, `hi`: the particles' bounding box (m), sphere surfaces included; `pad`: how far the
// patch of a plane and a clamped cylinder reach beyond it (m).
WallMesh wall_mesh(const Wall& wall, const Vec3& lo, const Vec3& hi, double pad);

}  // namespace colza
