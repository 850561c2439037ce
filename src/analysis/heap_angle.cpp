#include "analysis/heap_angle.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "core/types.hpp"

namespace colza {

namespace {
constexpr double kMinHeapBins = 3.0;
constexpr std::size_t kMinFitPoints = 5;
}  // namespace

HeapAngle fit_heap_angle(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                         const std::vector<double>& radius, const HeapFitSettings& s) {
  const std::size_t n = x.size();
  if (y.size() != n || z.size() != n || radius.size() != n)
    throw std::invalid_argument("x, y, z and radius must have the same length");
  if (s.sectors == 0 || !(s.inner >= 0.0 && s.inner < s.outer && s.outer <= 1.0))
    throw std::invalid_argument("need sectors > 0 and 0 <= inner < outer <= 1");
  HeapAngle h;
  if (n == 0) return h;
  double mean_d = 0.0;
  for (double r : radius) mean_d += 2.0 * r;
  mean_d /= static_cast<double>(n);
  const double bin = s.bin_width > 0.0 ? s.bin_width : mean_d;
  const double toe = s.toe_height > 0.0 ? s.toe_height : 2.0 * mean_d;  // above the base

  // The surface sphere of each (sector, radial bin): its highest top, with that sphere's rho
  // and index.
  struct SurfaceSphere {
    double top, rho;
    std::size_t index;
  };
  std::map<std::pair<std::size_t, long>, SurfaceSphere> surface;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = x[i] - s.centre_x, dy = y[i] - s.centre_y;
    const double rho = std::hypot(dx, dy), top = z[i] + radius[i] - s.base_height;  // above the base
    h.height = std::max(h.height, top);
    const double turn = (std::atan2(dy, dx) + kPi) / (2.0 * kPi);  // 0..1
    const std::size_t sector = std::min(s.sectors - 1, static_cast<std::size_t>(turn * static_cast<double>(s.sectors)));
    const auto key = std::make_pair(sector, static_cast<long>(std::floor(rho / bin)));
    auto it = surface.find(key);
    if (it == surface.end() || top > it->second.top) surface[key] = {top, rho, i};
  }
  h.surface_spheres = surface.size();
  for (const auto& [key, cell] : surface)
    if (cell.top >= toe) h.radius = std::max(h.radius, cell.rho);
  h.fit_rho_min = s.inner * h.radius;
  h.fit_rho_max = s.outer * h.radius;
  double sr = 0.0, st = 0.0;
  std::vector<std::pair<double, double>> pts;  // (rho, top)
  for (const auto& [key, cell] : surface)
    if (cell.rho >= h.fit_rho_min && cell.rho <= h.fit_rho_max) {
      pts.emplace_back(cell.rho, cell.top);
      h.fit_spheres.push_back(cell.index);
      sr += cell.rho;
      st += cell.top;
    }
  std::sort(h.fit_spheres.begin(), h.fit_spheres.end());
  h.points = pts.size();
  // A heap narrower than three bins (a sphere or two stacked on a spread layer) or a fit
  // through fewer than 5 surface spheres has no slope worth a number.
  if (h.radius < kMinHeapBins * bin || h.points < kMinFitPoints) return h;
  const double m = static_cast<double>(h.points);
  sr /= m;
  st /= m;
  double srr = 0.0, srt = 0.0, stt = 0.0;
  for (const auto& [rho, top] : pts) {
    srr += (rho - sr) * (rho - sr);
    srt += (rho - sr) * (top - st);
    stt += (top - st) * (top - st);
  }
  if (!(srr > 0.0)) return h;
  const double slope = srt / srr;  // d top / d rho, negative on a heap
  h.tan_angle = -slope;
  h.intercept = st - slope * sr;
  const double ss_res = std::max(0.0, stt - slope * srt);
  h.r2 = stt > 0.0 ? 1.0 - ss_res / stt : 1.0;
  const double se = std::sqrt(ss_res / (m - 2.0) / srr);
  h.angle_deg = std::atan(h.tan_angle) * 180.0 / kPi;
  h.angle_error_deg = se / (1.0 + h.tan_angle * h.tan_angle) * 180.0 / kPi;
  h.valid = true;
  return h;
}

}  // namespace colza
