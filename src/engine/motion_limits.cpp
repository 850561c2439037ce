#include "engine/motion_limits.hpp"

#include <algorithm>
#include <variant>

#include "contact/slots.hpp"

namespace colza {

DeepestOverlap deepest_overlap(const ParticleArrays& p, const std::vector<Wall>& walls, const ContactStore& contacts,
                               const PairTable& pairs, const ContactModel& model) {
  const bool linear = std::holds_alternative<LinearNormal>(model.normal);
  const SlotStateLayout& layout = contacts.slot_state_layout();
  DeepestOverlap deepest;
  // The overlap of a contact whose normal force is fn (N): Fn / Kn for the linear law, the
  // normal slot's own reading otherwise.
  const auto consider = [&](double normal_force, const PairContext& c, const double* state, double radius,
                            bool with_wall, std::size_t a, std::size_t b) {
    if (!(normal_force > 0.0)) return;
    const double overlap =
        linear ? normal_force / c.q.kn
               : std::visit([&](const auto& n) { return n.overlap(c, normal_force, state + layout.normal); },
                            model.normal);
    const double ratio = overlap / radius;
    if (ratio > deepest.ratio) deepest = {ratio, overlap, with_wall, a, b};
  };
  const auto state_of = [&](const std::vector<double>& rows, std::size_t c) -> const double* {
    return layout.stride == 0 ? nullptr : rows.data() + c * layout.stride;
  };
  const ParticlePairList& pp = contacts.particle_pairs;
  for (std::size_t c = 0; c < pp.size(); ++c) {
    const ContactHistory& h = pp.history[c];
    if (!h.touching) continue;
    const Index i = pp.first[c], j = pp.second[c];
    const double ri = p.radius[i], rj = p.radius[j];
    const PairContext ctx{pairs.particle_particle(p.material[i], p.material[j]), ri, rj, ri * rj / (ri + rj), 0.0,
                          0.0, false};
    consider(h.normal_force, ctx, state_of(pp.slot_state, c), std::min(ri, rj), false, i, j);
  }
  const WallPairList& pw = contacts.wall_pairs;
  for (std::size_t c = 0; c < pw.size(); ++c) {
    const ContactHistory& h = pw.history[c];
    if (!h.touching) continue;
    const Index i = pw.particle[c], w = pw.wall[c];
    const double r = p.radius[i];
    const PairContext ctx{pairs.particle_wall(p.material[i], walls[w].material), r, r, r, 0.0, 0.0, true};
    consider(h.normal_force, ctx, state_of(pw.slot_state, c), r, true, i, w);
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
