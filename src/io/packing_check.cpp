#include "io/packing_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "config/config_error.hpp"
#include "io/format_number.hpp"

namespace colza {

namespace {

std::string describe(const PackedSphere& s) {
  return "line " + std::to_string(s.line) + ": the sphere at (" + format_significant(s.position[0], 6) + ", " +
         format_significant(s.position[1], 6) + ", " + format_significant(s.position[2], 6) + ") m, radius " +
         format_significant(s.radius, 6) + " m,";
}

// How far (m) sphere s reaches beyond the bounds of its container (<= 0: inside), and which.
struct Excess {
  double by = 0.0;
  const char* where = "";
};

// `excess(s)` gives sphere s's Excess over the container described by `container`.
template <class ExcessOf>
void check_each(const std::vector<PackedSphere>& spheres, const std::string& file, const std::string& key,
                const std::string& container, ExcessOf&& excess) {
  for (const PackedSphere& s : spheres) {
    const Excess e = excess(s);
    if (e.by > kMaxSettledOverlapFraction * s.radius)
      throw ConfigError(file, key,
                        describe(s) + " lies " + format_significant(e.by * 1e3, 3) + " mm beyond " + e.where +
                            " of " + container + ": the packing does not fit this container (a packing for "
                            "another geometry, or other units than metres?)");
  }
}

// A settled packing rests against its container's walls: its outermost sphere surfaces lie
// close to each. One that stops short of the container's `extent` (m) by more than `tolerance`
// (m; `reach`: how far it gets) was made in a narrower container and would load as a loose
// heap.
void check_fills(double reach, double extent, double tolerance, const std::string& file, const std::string& key,
                 const std::string& what) {
  if (reach >= extent - tolerance) return;
  throw ConfigError(file, key,
                    "the spheres reach only " + format_significant(reach * 1e3, 4) + " mm of the " +
                        format_significant(extent * 1e3, 4) + " mm " + what +
                        ": the packing does not fill this container (a packing made in a narrower one?)");
}

double largest_diameter(const std::vector<PackedSphere>& spheres) {
  double d = 0.0;
  for (const PackedSphere& s : spheres) d = std::max(d, 2.0 * s.radius);
  return d;
}

}  // namespace

void check_packing_in_cylinder(const std::vector<PackedSphere>& spheres, double radius, const std::string& file,
                               const std::string& key) {
  check_each(spheres, file, key,
             "the cylinder (radius " + format_significant(radius * 1e3, 6) + " mm, floor at z = 0)",
             [&](const PackedSphere& s) {
               const double wall = std::hypot(s.position[0], s.position[1]) + s.radius - radius;
               const double floor = s.radius - s.position[2];
               return wall >= floor ? Excess{wall, "the wall"} : Excess{floor, "the floor"};
             });
  double reach = 0.0;  // from the axis
  for (const PackedSphere& s : spheres) reach = std::max(reach, std::hypot(s.position[0], s.position[1]) + s.radius);
  if (!spheres.empty()) check_fills(reach, radius, largest_diameter(spheres), file, key, "radius from the axis");
}

void check_packing_in_box(const std::vector<PackedSphere>& spheres, double length, double width,
                          const std::string& file, const std::string& key) {
  check_each(spheres, file, key,
             "the box (" + format_significant(length * 1e3, 6) + " x " + format_significant(width * 1e3, 6) +
                 " mm, floor at z = 0)",
             [&](const PackedSphere& s) {
               const Excess candidates[5] = {{s.radius - s.position[0], "the wall x = 0"},
                                             {s.position[0] + s.radius - length, "the wall x = length"},
                                             {s.radius - s.position[1], "the wall y = 0"},
                                             {s.position[1] + s.radius - width, "the wall y = width"},
                                             {s.radius - s.position[2], "the floor"}};
               return *std::max_element(std::begin(candidates), std::end(candidates),
                                        [](const Excess& a, const Excess& c) { return a.by < c.by; });
             });
  if (spheres.empty()) return;
  const double fill_tolerance = 2.0 * largest_diameter(spheres);
  const double extent[2] = {length, width};
  const char* axis[2] = {"length (x)", "width (y)"};
  for (int d = 0; d < 2; ++d) {
    double lo = extent[d], hi = 0.0;
    for (const PackedSphere& s : spheres) {
      lo = std::min(lo, s.position[d] - s.radius);
      hi = std::max(hi, s.position[d] + s.radius);
    }
    check_fills(hi - lo, extent[d], fill_tolerance, file, key, axis[d]);
  }
}

void check_packing_overlaps(const std::vector<PackedSphere>& spheres, const std::string& file,
                            const std::string& key) {
  if (spheres.empty()) return;
  // Linked cells of edge 2 r_max: overlapping spheres lie in the same or adjacent cells.
  const double cell = largest_diameter(spheres);
  const auto cell_of = [&](const Vec3& x, int d) { return static_cast<std::int64_t>(std::floor(x[d] / cell)); };
  const auto key_of = [](std::int64_t i, std::int64_t j, std::int64_t k) {
    return (static_cast<std::uint64_t>(i & 0x1fffff) << 42) | (static_cast<std::uint64_t>(j & 0x1fffff) << 21) |
           static_cast<std::uint64_t>(k & 0x1fffff);
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells;
  for (std::size_t n = 0; n < spheres.size(); ++n) {
    const Vec3& x = spheres[n].position;
    cells[key_of(cell_of(x, 0), cell_of(x, 1), cell_of(x, 2))].push_back(n);
  }
  for (std::size_t a = 0; a < spheres.size(); ++a) {
    const PackedSphere& s = spheres[a];
    const std::int64_t ci = cell_of(s.position, 0), cj = cell_of(s.position, 1), ck = cell_of(s.position, 2);
    for (std::int64_t di = -1; di <= 1; ++di)
      for (std::int64_t dj = -1; dj <= 1; ++dj)
        for (std::int64_t dk = -1; dk <= 1; ++dk) {
          const auto found = cells.find(key_of(ci + di, cj + dj, ck + dk));
          if (found == cells.end()) continue;
          for (std::size_t b : found->second) {
            if (b <= a) continue;
            const PackedSphere& t = spheres[b];
            const double overlap = s.radius + t.radius - (t.position - s.position).norm();
            if (overlap > kMaxSettledOverlapFraction * std::min(s.radius, t.radius))
              throw ConfigError(file, key,
                                "lines " + std::to_string(s.line) + " and " + std::to_string(t.line) +
                                    ": two spheres overlap by " + format_significant(overlap * 1e3, 3) +
                                    " mm, more than " + format_significant(100 * kMaxSettledOverlapFraction, 3) +
                                    " % of the smaller radius: not a settled packing");
          }
        }
  }
}

}  // namespace colza
