#include "scenario/generation.hpp"

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_real_distribution.hpp>
#include <algorithm>
#include <cmath>

namespace colza {

GenerationRegion GenerationRegion::box(const Vec3& lo, const Vec3& hi) {
  GenerationRegion r;
  r.shape = Shape::kBox;
  r.lo = lo;
  r.hi = hi;
  return r;
}

GenerationRegion GenerationRegion::vertical_cylinder(const Vec3& base_centre, double radius, double height) {
  GenerationRegion r;
  r.shape = Shape::kCylinder;
  r.axis_point = base_centre;
  r.radius = radius;
  r.lo = base_centre - Vec3(radius, radius, 0.0);
  r.hi = base_centre + Vec3(radius, radius, height);
  return r;
}

bool GenerationRegion::contains(const Vec3& x, double r) const {
  if (x.z() - r < lo.z() || x.z() + r > hi.z()) return false;
  if (shape == Shape::kBox)
    return x.x() - r >= lo.x() && x.x() + r <= hi.x() && x.y() - r >= lo.y() && x.y() + r <= hi.y();
  const double dx = x.x() - axis_point.x(), dy = x.y() - axis_point.y();
  return radius >= r && dx * dx + dy * dy <= (radius - r) * (radius - r);
}

std::vector<PackedSphere> generate_spheres(const GenerationRequest& req) {
  boost::random::mt19937_64 engine(req.seed);
  boost::random::uniform_real_distribution<double> unit(0.0, 1.0);
  const Vec3 lo = req.region.lo, span = req.region.hi - req.region.lo;
  // No packing of spheres of diameter >= d_min fills more than pi / sqrt(18) (~74 %, Kepler)
  // of the region, so no more than `most` can ever be placed: a larger count is placed up to
  // the first failures and reported by the caller, never allocated (nor more than 2^20 in
  // advance, for a tiny d_min).
  const double region_volume = req.region.shape == GenerationRegion::Shape::kBox
                                   ? span.x() * span.y() * span.z()
                                   : kPi * req.region.radius * req.region.radius * span.z();
  const double smallest_sphere = kPi / 6.0 * std::pow(std::max(req.diameter_min, 1e-12), 3);
  const double most = kPi / std::sqrt(18.0) * region_volume / smallest_sphere + 1.0;
  // Hash grid of placed spheres, cell >= d_max, so overlaps are found in the 27 neighbouring
  // cells. Cells of d_max, unless that makes more than kCellsPerSphere per sphere asked for
  // (or that could fit; a region in mm typed for m made a grid of 14286 x 14286 x 29 cells:
  // std::bad_alloc): then larger cells, which find the same overlaps, so the same packing. The paper's
  // cylinder has 2.5 cells per sphere, its shear box 1.9.
  constexpr double kCellsPerSphere = 8.0, kCellsAtLeast = 4096.0;
  const double most_cells = std::max(kCellsAtLeast, kCellsPerSphere * std::min(static_cast<double>(req.count), most));
  double cell = std::max(req.diameter_max, 1e-12);
  const auto cells_along = [&](int d) { return std::max(1.0, std::ceil(span[d] / cell)); };
  while (cells_along(0) * cells_along(1) * cells_along(2) > most_cells) cell *= 1.25;
  int dims[3];
  for (int d = 0; d < 3; ++d) dims[d] = static_cast<int>(cells_along(d));
  std::vector<std::vector<std::uint32_t>> grid(static_cast<std::size_t>(dims[0]) * dims[1] * dims[2]);
  auto coord = [&](const Vec3& x, int d) { return std::clamp(static_cast<int>((x[d] - lo[d]) / cell), 0, dims[d] - 1); };

  std::vector<PackedSphere> placed;
  constexpr double kReserveAtMost = 1 << 20;  // beyond it the vector grows as spheres are placed
  placed.reserve(static_cast<std::size_t>(std::min({static_cast<double>(req.count), most, kReserveAtMost})));
  std::uint64_t failures = 0;
  while (placed.size() < req.count && failures < req.max_attempts) {
    const double d = req.diameter_min + (req.diameter_max - req.diameter_min) * unit(engine);
    const double r = 0.5 * d;
    bool ok = false;
    Vec3 x;
    while (!ok && failures < req.max_attempts) {
      // Named draws, in a fixed order: the arguments of one call are evaluated in an order the
      // language leaves open (GCC 12 took them right to left, clang left to right), which
      // would make the packing depend on the compiler. z, y, x is the order colza's packings
      // have always had (tests/unit/generation_reference.py regenerates them independently).
      const double u_z = unit(engine);
      const double u_y = unit(engine);
      const double u_x = unit(engine);
      x = Vec3(lo.x() + span.x() * u_x, lo.y() + span.y() * u_y, lo.z() + span.z() * u_z);
      ok = req.region.contains(x, r);
      const int cx = coord(x, 0), cy = coord(x, 1), cz = coord(x, 2);
      for (int z = std::max(0, cz - 1); ok && z <= std::min(dims[2] - 1, cz + 1); ++z)
        for (int y = std::max(0, cy - 1); ok && y <= std::min(dims[1] - 1, cy + 1); ++y)
          for (int xx = std::max(0, cx - 1); ok && xx <= std::min(dims[0] - 1, cx + 1); ++xx)
            for (std::uint32_t k : grid[(static_cast<std::size_t>(z) * dims[1] + y) * dims[0] + xx]) {
              const double reach = r + placed[k].radius;
              if ((placed[k].position - x).squaredNorm() < reach * reach) { ok = false; break; }
            }
      if (!ok) ++failures;
    }
    if (!ok) break;
    grid[(static_cast<std::size_t>(coord(x, 2)) * dims[1] + coord(x, 1)) * dims[0] + coord(x, 0)].push_back(
        static_cast<std::uint32_t>(placed.size()));
    placed.push_back({x, r});
  }
  return placed;
}

}  // namespace colza
