#include "integrate/time_step.hpp"

#include <cmath>
#include <limits>

#include "contact/slots.hpp"

namespace colza {

namespace {

// Overlap now (un > 0, m), for pairs no force pass has flagged: two spheres, a sphere and a wall.
bool spheres_overlap(const ParticleArrays& p, Index i, Index j) {
  const double reach = p.radius[i] + p.radius[j];
  return (p.position[j] - p.position[i]).squaredNorm() < reach * reach;
}
bool sphere_overlaps_wall(const ParticleArrays& p, Index i, const Wall& wall) {
  const WallContactGeometry g = wall_sphere_geometry(wall, p.position[i], p.radius[i]);
  return g.in_range && g.overlap > 0.0;
}

}  // namespace

double critical_time_step(const ParticleArrays& p, const std::vector<Wall>& walls, const ContactStore& contacts,
                          const PairTable& pairs, CountedContacts counted) {
  static_assert(kNormalLawIsLinear, "a contact's translational stiffness is taken as Kn + Ks (linear springs)");
  const bool overlaps_count = counted == CountedContacts::kTouchingOrOverlapping;
  const std::size_t n = p.size();
  std::vector<double> k_trans(n, 0.0), k_shear(n, 0.0);
  const auto& pp = contacts.particle_pairs;
  for (std::size_t c = 0; c < pp.size(); ++c) {
    const Index i = pp.first[c], j = pp.second[c];
    if (!pp.history[c].touching && !(overlaps_count && spheres_overlap(p, i, j))) continue;
    const PairParameters& q = pairs.particle_particle(p.material[i], p.material[j]);
    k_trans[i] += q.kn + q.ks;
    k_trans[j] += q.kn + q.ks;
    k_shear[i] += q.ks;
    k_shear[j] += q.ks;
  }
  const auto& pw = contacts.wall_pairs;
  for (std::size_t c = 0; c < pw.size(); ++c) {
    const Index i = pw.particle[c];
    if (!pw.history[c].touching && !(overlaps_count && sphere_overlaps_wall(p, i, walls[pw.wall[c]]))) continue;
    const PairParameters& q = pairs.particle_wall(p.material[i], walls[pw.wall[c]].material);
    k_trans[i] += q.kn + q.ks;
    k_shear[i] += q.ks;
  }
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    if (k_trans[i] == 0.0) {
      const PairParameters& q = pairs.particle_particle(p.material[i], p.material[i]);
      k_trans[i] = q.kn + q.ks;
      k_shear[i] = q.ks;
    }
    const double r = p.radius[i];
    dt = std::min(dt, std::sqrt(p.mass[i] / k_trans[i]));
    if (k_shear[i] > 0.0) dt = std::min(dt, std::sqrt(p.inertia[i] / (k_shear[i] * r * r)));
  }
  return dt;
}

}  // namespace colza
