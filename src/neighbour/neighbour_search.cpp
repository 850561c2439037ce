#include "neighbour/neighbour_search.hpp"

#include <algorithm>
#include <cmath>

#include "core/unstable_motion.hpp"

namespace colza {

namespace {

// The wall as the candidate test sees it. A finite cylinder reaches one skin beyond each of
// its ends: between two builds the sphere and the wall each move at most skin/2, so the
// sphere's axial coordinate (measured from the wall's origin) changes by at most a skin,
// and a sphere just beyond an end at the build may be within the range, and touching,
// before the next build. Planes and rectangles need no widening: their gap is a distance to
// the whole surface, edges and corners included, so it closes by at most a skin. A
// rectangle's restricted edges count in full for the test: a sphere beyond one at the
// build may move back over the plate, or in front of it, before the next.
Wall candidate_reach(const Wall& wall, double skin) {
  Wall reach = wall;
  reach.edges = RectangleEdges{};
  if (reach.shape == WallShape::kCylinder) {
    reach.axial_min -= skin;
    reach.axial_max += skin;
  }
  return reach;
}

}  // namespace

bool NeighbourSearch::needs_rebuild(const ParticleArrays& particles, const std::vector<Wall>& walls) const {
  if (!valid_ || position_at_build_.size() != particles.size() || wall_origin_at_build_.size() != walls.size())
    return true;
  const double limit2 = 0.25 * skin_ * skin_;
  for (std::size_t w = 0; w < walls.size(); ++w)
    if ((walls[w].origin - wall_origin_at_build_[w]).squaredNorm() > limit2) return true;
  // A particle moved more than skin/2 since the build: |x - x_build|^2 > skin^2 / 4. This
  // runs every step, so each block of particles first goes through a filter that vectorises
  // over the flat coordinates: no coordinate moved by more than d_max, and
  // 4 d_max^2 <= skin^2 / 4 mean that every particle of the block moved less than
  // 2 d_max <= skin/2 (|d|^2 <= 3 d_max^2; the factor 4/3 covers the rounding). Blocks
  // that fail the filter take the exact test, particle by particle: the decision is the
  // exact test's (a scalar loop over all particles cost ~2 us per step on 2300 spheres).
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "positions are read as packed xyz triples");
  constexpr std::size_t kBlock = 64;
  const std::size_t n = particles.size();
  const double* x = particles.position.data()->data();
  const double* x0 = position_at_build_.data()->data();
  for (std::size_t begin = 0; begin < n; begin += kBlock) {
    const std::size_t end = std::min(n, begin + kBlock);
    double largest2 = 0.0;
#pragma omp simd reduction(max : largest2)
    for (std::size_t k = 3 * begin; k < 3 * end; ++k) {
      const double d = x[k] - x0[k];
      largest2 = std::max(largest2, d * d);
    }
    if (4.0 * largest2 <= limit2) continue;
    for (std::size_t i = begin; i < end; ++i)
      if ((particles.position[i] - position_at_build_[i]).squaredNorm() > limit2) return true;
  }
  return false;
}

void NeighbourSearch::build_particle_pairs(const ParticleArrays& particles, int threads, std::vector<Index>& first,
                                           std::vector<Index>& second) {
  const std::size_t n = particles.size();
  if (n < 2) return;
  // Grid over the particles' bounding box; a cell is at least one interaction range wide,
  // so all partners of a particle are in its own or the 26 surrounding cells.
  Vec3 lo = particles.position[0], hi = lo;
  double r_max = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    lo = lo.cwiseMin(particles.position[i]);
    hi = hi.cwiseMax(particles.position[i]);
    r_max = std::max(r_max, particles.radius[i]);
  }
  // At most ~8 cells per particle: particles spread far apart (a few escaped from a box, or
  // a motion blowing up through huge coordinates) would otherwise ask for more cells than
  // memory holds. Wider cells give the same list (partners are sorted), only a longer search.
  const double extent = (hi - lo).maxCoeff();
  if (!std::isfinite(extent))
    throw UnstableMotion("the particles' positions span more than the largest double: the motion became unstable");
  const double max_cells = 8.0 * static_cast<double>(n) + 4096.0;
  auto cells_per_axis = [&](double c, int d) { return std::floor((hi[d] - lo[d]) / c) + 1.0; };
  double cell = 2.0 * r_max + skin_;
  while (cells_per_axis(cell, 0) * cells_per_axis(cell, 1) * cells_per_axis(cell, 2) > max_cells) cell *= 2.0;
  int dims[3];
  for (int d = 0; d < 3; ++d) dims[d] = static_cast<int>(cells_per_axis(cell, d));
  const std::size_t n_cells = static_cast<std::size_t>(dims[0]) * dims[1] * dims[2];
  auto cell_coord = [&](const Vec3& x, int d) {
    return std::min(dims[d] - 1, static_cast<int>((x[d] - lo[d]) / cell));
  };
  // Counting sort of particles into cells (order within a cell: increasing index), with a
  // copy of positions and radii in that order: the three cells x-1..x+1 of a row are
  // consecutive cells, so a particle's 27 neighbour cells are 9 contiguous runs of memory.
  particle_cell_.resize(n);
  cell_start_.assign(n_cells + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = particles.position[i];
    const std::size_t c = (static_cast<std::size_t>(cell_coord(x, 2)) * dims[1] + cell_coord(x, 1)) * dims[0] +
                          cell_coord(x, 0);
    particle_cell_[i] = static_cast<Index>(c);
    ++cell_start_[c + 1];
  }
  for (std::size_t c = 0; c < n_cells; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_particles_.resize(n);
  {
    std::vector<Index> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (std::size_t i = 0; i < n; ++i) cell_particles_[fill[particle_cell_[i]]++] = static_cast<Index>(i);
  }
  sorted_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Index i = cell_particles_[k];
    sorted_[k] = {particles.position[i].x(), particles.position[i].y(), particles.position[i].z(),
                  particles.radius[i], static_cast<double>(particles.fixed[i] == kAnchored)};
  }
  // Partners j > i of particles [begin, end), appended in (i, j) order.
  auto search = [&](std::size_t begin, std::size_t end, std::vector<Index>& f, std::vector<Index>& s) {
    std::vector<Index> partners;
    for (std::size_t i = begin; i < end; ++i) {
      const Vec3& xi = particles.position[i];
      const double ri = particles.radius[i];
      const double anchored_i = particles.fixed[i] == kAnchored ? 1.0 : 0.0;
      const int cx = cell_coord(xi, 0), cy = cell_coord(xi, 1), cz = cell_coord(xi, 2);
      const int x_lo = std::max(0, cx - 1), x_hi = std::min(dims[0] - 1, cx + 1);
      const int z_lo = std::max(0, cz - 1), z_hi = std::min(dims[2] - 1, cz + 1);
      const int y_lo = std::max(0, cy - 1), y_hi = std::min(dims[1] - 1, cy + 1);
      std::size_t runs = 0;  // room for every particle of the 9 runs
      for (int z = z_lo; z <= z_hi; ++z)
        for (int y = y_lo; y <= y_hi; ++y) {
          const std::size_t row = (static_cast<std::size_t>(z) * dims[1] + y) * dims[0];
          runs += cell_start_[row + x_hi + 1] - cell_start_[row + x_lo];
        }
      partners.resize(runs);
      std::size_t found = 0;
      for (int z = z_lo; z <= z_hi; ++z)
        for (int y = y_lo; y <= y_hi; ++y) {
          const std::size_t row = (static_cast<std::size_t>(z) * dims[1] + y) * dims[0];
          // Branch-free: every particle is written, the count advances for partners only
          // (half of the tests fail on j > i and the rest at random: branches mispredict).
          // Two anchored spheres are never partners: neither ever moves, so a force between
          // them would do nothing (a glued base's ~2000 spheres would otherwise bring ~2
          // candidate pairs each, every step). Spheres with a prescribed motion are, as a
          // micro test measures the force between two of them.
          for (Index k = cell_start_[row + x_lo]; k < cell_start_[row + x_hi + 1]; ++k) {
            const Index j = cell_particles_[k];
            const SortedSphere& q = sorted_[k];
            const double reach = ri + q.r + skin_;
            const double dx = q.x - xi.x(), dy = q.y - xi.y(), dz = q.z - xi.z();
            partners[found] = j;
            found += static_cast<std::size_t>((j > i) & ((dx * dx + dy * dy) + dz * dz < reach * reach) &
                                              (anchored_i * q.anchored == 0.0));
          }
        }
      std::sort(partners.begin(), partners.begin() + static_cast<std::ptrdiff_t>(found));
      for (std::size_t m = 0; m < found; ++m) {
        f.push_back(static_cast<Index>(i));
        s.push_back(partners[m]);
      }
    }
  };
  // Threads take contiguous particle ranges; their lists are concatenated in range order,
  // so the result does not depend on the thread count.
  const std::size_t T = std::max<std::size_t>(1, std::min<std::size_t>(static_cast<std::size_t>(threads), n / 512));
  if (T == 1) {
    search(0, n, first, second);
    return;
  }
  range_first_.resize(T);
  range_second_.resize(T);
#pragma omp parallel for num_threads(static_cast<int>(T)) schedule(static, 1)
  for (std::size_t t = 0; t < T; ++t) {
    range_first_[t].clear();
    range_second_[t].clear();
    search(n * t / T, n * (t + 1) / T, range_first_[t], range_second_[t]);
  }
  for (std::size_t t = 0; t < T; ++t) {
    first.insert(first.end(), range_first_[t].begin(), range_first_[t].end());
    second.insert(second.end(), range_second_[t].begin(), range_second_[t].end());
  }
}

void NeighbourSearch::rebuild(const ParticleArrays& particles, const std::vector<Wall>& walls,
                              ContactStore& contacts, int threads) {
  std::vector<Index> first, second;
  first.reserve(contacts.particle_pairs.size() + 16);
  second.reserve(contacts.particle_pairs.size() + 16);
  build_particle_pairs(particles, threads, first, second);
  contacts.adopt_particle_pairs(std::move(first), std::move(second));

  std::vector<Index> wall_ids, wall_partners;
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const Wall reach = candidate_reach(walls[w], skin_);
    for (std::size_t i = 0; i < particles.size(); ++i) {
      if (particles.fixed[i] && !walls[w].meets_fixed_spheres) continue;
      const WallContactGeometry g = wall_sphere_geometry(reach, particles.position[i], particles.radius[i]);
      if (g.in_range && g.overlap > -skin_) {
        wall_ids.push_back(static_cast<Index>(w));
        wall_partners.push_back(static_cast<Index>(i));
      }
    }
  }
  contacts.adopt_wall_pairs(std::move(wall_ids), std::move(wall_partners));

  position_at_build_ = particles.position;
  wall_origin_at_build_.resize(walls.size());
  for (std::size_t w = 0; w < walls.size(); ++w) wall_origin_at_build_[w] = walls[w].origin;
  valid_ = true;
  ++rebuilds_;
}

}  // namespace colza
