#include "engine/wall_stiffness.hpp"

#include <algorithm>
#include <variant>

namespace colza {

double wall_normal_stiffness(const World& world, const PhysicsSettings& physics, const PairTable& pairs,
                             std::size_t wall_index) {
  const Wall& wall = world.walls[wall_index];
  const ContactModel& model = physics.model;
  if (std::holds_alternative<LinearNormal>(model.normal))
    return pairs.particle_wall(0, wall.material).kn * std::max<Index>(1, wall.contact_count);
  const ParticleArrays& p = world.particles;
  const WallPairList& pw = world.contacts.wall_pairs;
  const SlotStateLayout& layout = world.contacts.slot_state_layout();
  const auto tangent = [&](const PairContext& c, double overlap, const double* state) {
    return std::visit([&](const auto& n) { return n.tangent_stiffness(c, overlap, state); }, model.normal);
  };
  double k = 0.0;
  for (std::size_t c = 0; c < pw.size(); ++c) {
    if (pw.wall[c] != wall_index || !pw.history[c].touching) continue;
    const PairContext ctx = wall_pair_context(p, pairs, pw.particle[c], wall.material, 0.0);
    const double* state = world.contacts.wall_pair_state(c) + layout.normal;
    const double overlap =
        std::visit([&](const auto& n) { return n.overlap(ctx, pw.history[c].normal_force, state); }, model.normal);
    k += tangent(ctx, overlap, state);
  }
  if (k > 0.0 || p.size() == 0) return k;
  return tangent(wall_pair_context(p, pairs, 0, wall.material, 0.0), 0.01 * p.radius[0], kZeroSlotRow);
}

}  // namespace colza
