#include "scenario/glued_layer.hpp"

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_real_distribution.hpp>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace colza {

namespace {

// Mixed into the run's seed: the layer's draws form another stream than the sample's.
constexpr std::uint64_t kGluedLayerStream = 0x676c7565645f6c79ULL;  // "glued_ly"

// Spheres resting on the plate, (x, y, r), on a square grid of cells of d_max over [-R, R]^2:
// an overlap is found in the 9 cells about a new sphere's centre.
class DiscGrid {
 public:
  DiscGrid(double half_width, double cell) : lo_(-half_width), cell_(cell) {
    dims_ = std::max(1, static_cast<int>(std::ceil(2.0 * half_width / cell)));
    cells_.resize(static_cast<std::size_t>(dims_) * dims_);
  }
  bool free(double x, double y, double r) const {
    const int cx = coord(x), cy = coord(y);
    for (int j = std::max(0, cy - 1); j <= std::min(dims_ - 1, cy + 1); ++j)
      for (int i = std::max(0, cx - 1); i <= std::min(dims_ - 1, cx + 1); ++i)
        for (std::size_t k : cells_[static_cast<std::size_t>(j) * dims_ + i]) {
          // Two spheres resting on the plate, centres at heights r and r_k: overlap when
          // dx^2 + dy^2 + (r - r_k)^2 < (r + r_k)^2, i.e. dx^2 + dy^2 < 4 r r_k.
          const double dx = x - discs_[k].x, dy = y - discs_[k].y;
          if (dx * dx + dy * dy < 4.0 * r * discs_[k].r) return false;
        }
    return true;
  }
  void add(double x, double y, double r) {
    cells_[static_cast<std::size_t>(coord(y)) * dims_ + coord(x)].push_back(discs_.size());
    discs_.push_back({x, y, r});
  }
  struct Disc {
    double x, y, r;
  };
  const std::vector<Disc>& discs() const { return discs_; }

 private:
  int coord(double v) const { return std::clamp(static_cast<int>((v - lo_) / cell_), 0, dims_ - 1); }
  double lo_, cell_;
  int dims_;
  std::vector<std::vector<std::size_t>> cells_;
  std::vector<Disc> discs_;
};

}  // namespace

ParticleArrays glued_layer(const GluedLayerRequest& q) {
  if (!(q.disc_radius > 0.0) || !(q.diameter_min > 0.0) || !(q.diameter_min <= q.diameter_max) ||
      !(q.density > 0.0))
    throw std::invalid_argument("glued_layer: need disc_radius > 0, 0 < diameter_min <= diameter_max, density > 0");
  DiscGrid grid(q.disc_radius + q.diameter_max, q.diameter_max);
  // A sphere of radius r resting on the plate at (x, y) may be glued there: centre in the
  // disc, not overlapping a glued one.
  const auto fits = [&](double x, double y, double r) {
    return std::hypot(x, y) <= q.disc_radius && grid.free(x, y, r);
  };

  boost::random::mt19937_64 engine(q.seed ^ kGluedLayerStream);
  boost::random::uniform_real_distribution<double> unit(0.0, 1.0);
  const double mean_r = 0.25 * (q.diameter_min + q.diameter_max);
  const double spheres_in_disc = (q.disc_radius * q.disc_radius) / (mean_r * mean_r);
  const auto attempts = static_cast<std::uint64_t>(q.random_attempts_per_sphere * spheres_in_disc);
  for (std::uint64_t a = 0; a < attempts; ++a) {
    const double r = 0.5 * (q.diameter_min + (q.diameter_max - q.diameter_min) * unit(engine));
    const double x = q.disc_radius * (2.0 * unit(engine) - 1.0);
    const double y = q.disc_radius * (2.0 * unit(engine) - 1.0);
    if (fits(x, y, r)) grid.add(x, y, r);
  }
  // The fill (header): s = r_min / 8, r_fill = a^2 r_min, a the larger root of
  // a (1 - a) = s / (2 sqrt(2) r_min).
  const double r_min = 0.5 * q.diameter_min, spacing = r_min / 8.0;
  const double c = spacing / (2.0 * std::sqrt(2.0) * r_min);
  const double a = 0.5 * (1.0 + std::sqrt(1.0 - 4.0 * c)), r_fill = a * a * r_min;
  const int nodes = static_cast<int>(std::floor(q.disc_radius / spacing));
  for (int j = -nodes; j <= nodes; ++j)
    for (int i = -nodes; i <= nodes; ++i)
      if (fits(i * spacing, j * spacing, r_fill)) grid.add(i * spacing, j * spacing, r_fill);

  ParticleArrays layer;
  for (const DiscGrid::Disc& d : grid.discs()) {
    layer.add(Vec3(d.x, d.y, d.r), d.r, q.density);
    layer.fixed.back() = kAnchored;
  }
  return layer;
}

}  // namespace colza
