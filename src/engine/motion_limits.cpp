#include "engine/motion_limits.hpp"

#include <algorithm>

#include "contact/slots.hpp"

namespace colza {

DeepestOverlap deepest_overlap(const ParticleArrays& p, const std::vector<Wall>& walls, const ContactStore& contacts,
                               const PairTable& pairs) {
  static_assert(kNormalLawIsLinear, "the overlap is read back from the normal force as un = Fn / Kn");
  DeepestOverlap deepest;
  const auto consider = [&](double normal_force, double kn, double radius, bool with_wall, std::size_t a,
                            std::size_t b) {
    if (!(normal_force > 0.0)) return;
    const double overlap = normal_force / kn, ratio = overlap / radius;
    if (ratio > deepest.ratio) deepest = {ratio, overlap, with_wall, a, b};
  };
  const ParticlePairList& pp = contacts.particle_pairs;
  for (std::size_t c = 0; c < pp.size(); ++c) {
    const ContactHistory& h = pp.history[c];
    if (!h.touching) continue;
    const Index i = pp.first[c], j = pp.second[c];
    consider(h.normal_force, pairs.particle_particle(p.material[i], p.material[j]).kn,
             std::min(p.radius[i], p.radius[j]), false, i, j);
  }
  const WallPairList& pw = contacts.wall_pairs;
  for (std::size_t c = 0; c < pw.size(); ++c) {
    const ContactHistory& h = pw.history[c];
    if (!h.touching) continue;
    const Index i = pw.particle[c], w = pw.wall[c];
    consider(h.normal_force, pairs.particle_wall(p.material[i], walls[w].material).kn, p.radius[i], true, i, w);
  }
  return deepest;
}

FastestParticle fastest_particle(const ParticleArrays& p, const ContactStore& contacts, double dt,
                                 double free_flight_speed) {
  const std::vector<std::uint8_t> has_candidate = contacts.particles_in_pairs(p.size(), /*touching_only=*/false);
  FastestParticle fastest;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double speed = p.velocity[i].norm(), ratio = speed * dt / p.radius[i];
    if (!has_candidate[i] && !(speed > free_flight_speed)) continue;
    if (ratio > fastest.ratio) fastest = {ratio, speed, i};
  }
  return fastest;
}

}  // namespace colza
