#include "engine/motion_limits.hpp"

#include <algorithm>
#include <variant>

#include "contact/slots.hpp"

namespace colza {

DeepestOverlap deepest_overlap(const ParticleArrays& p, const std::vector<Wall>& walls, const ContactStore& contacts,
                               const PairTable& pairs, const ContactModel& model) {
  const SlotStateLayout& layout = contacts.slot_state_layout();
  DeepestOverlap deepest;
  // The overlap of a contact whose normal force is fn (N), as its normal law reads it (Fn / Kn
  // for the linear law).
  const auto consider = [&](double normal_force, const PairContext& c, const double* state, double radius,
                            bool with_wall, std::size_t a, std::size_t b) {
    if (!(normal_force > 0.0)) return;
    const double overlap =
        std::visit([&](const auto& n) { return n.overlap(c, normal_force, state + layout.normal); }, model.normal);
    const double ratio = overlap / radius;
    if (ratio > deepest.ratio) deepest = {ratio, overlap, with_wall, a, b};
  };
  const ParticlePairList& pp = contacts.particle_pairs;
  for (std::size_t c = 0; c < pp.size(); ++c) {
    const ContactHistory& h = pp.history[c];
    if (!h.touching) continue;
    const Index i = pp.first[c], j = pp.second[c];
    const PairContext ctx = particle_pair_context(p, pairs, i, j, 0.0);
    consider(h.normal_force, ctx, contacts.particle_pair_state(c), std::min(ctx.radius_1, ctx.radius_2), false, i, j);
  }
  const WallPairList& pw = contacts.wall_pairs;
  for (std::size_t c = 0; c < pw.size(); ++c) {
    const ContactHistory& h = pw.history[c];
    if (!h.touching) continue;
    const Index i = pw.particle[c], w = pw.wall[c];
    const PairContext ctx = wall_pair_context(p, pairs, i, walls[w].material, 0.0);
    consider(h.normal_force, ctx, contacts.wall_pair_state(c), ctx.radius_2, true, i, w);
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
