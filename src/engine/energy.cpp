#include "engine/energy.hpp"

#include <variant>

#include "contact/generic_law.hpp"

namespace colza {

bool model_has(const ContactModel& model, ChannelOwner owner) {
  switch (owner) {
    case ChannelOwner::kAlways: return true;
    case ChannelOwner::kRolling: return std::holds_alternative<ElasticPlasticRolling>(model.rolling);
    case ChannelOwner::kViscous: return std::holds_alternative<ViscousDamping>(model.damping);
    case ChannelOwner::kPlastic: return std::holds_alternative<WaltonBraunNormal>(model.normal);
    case ChannelOwner::kMindlin: return std::holds_alternative<MindlinTangential>(model.tangential);
  }
  return false;
}

std::vector<std::string> energy_columns(const ContactModel& model) {
  std::vector<std::string> names;
  for (const StoredChannel& c : kStoredChannels)
    if (model_has(model, c.owner)) names.emplace_back(c.column);
  for (const LedgerChannel& c : kLedgerChannels)
    if (model_has(model, c.owner)) names.emplace_back(c.column);
  return names;
}

std::vector<double> energy_values(const ContactModel& model, const EnergySnapshot& e, const EnergyLedger& l) {
  std::vector<double> values;
  for (const StoredChannel& c : kStoredChannels)
    if (model_has(model, c.owner)) values.push_back(e.*c.value);
  for (const LedgerChannel& c : kLedgerChannels)
    if (model_has(model, c.owner)) values.push_back(l.*c.value);
  return values;
}

double energy_balance(const EnergySnapshot& e, const EnergyLedger& l) {
  double total = e.total_stored();
  for (const LedgerChannel& c : kLedgerChannels) total += c.sign * (l.*c.value);
  return total;
}

namespace {

// The springs' stored energy, each slot stating its own (contact/generic_law.hpp): for the
// paper's law 1/2 Fn^2 / Kn and 1/2 |Fs|^2 / Ks per contact.
void add_slot_springs(const World& world, const ContactModel& model, const PairTable& pairs, EnergySnapshot& e) {
  const ParticleArrays& p = world.particles;
  const SlotStateLayout& layout = world.contacts.slot_state_layout();
  const auto add = [&](const ContactEnergy& c) {
    e.elastic_normal += c.normal;
    e.elastic_shear += c.shear;
    e.elastic_rolling += c.rolling;
  };
  const auto& pp = world.contacts.particle_pairs;
  for (std::size_t c = 0; c < pp.size(); ++c) {
    if (!pp.history[c].touching) continue;
    const PairContext ctx = particle_pair_context(p, pairs, pp.first[c], pp.second[c], 0.0);
    add(stored_contact_energy(model, layout, ctx, pp.history[c], world.contacts.particle_pair_state(c)));
  }
  const auto& pw = world.contacts.wall_pairs;
  for (std::size_t c = 0; c < pw.size(); ++c) {
    if (!pw.history[c].touching) continue;
    const PairContext ctx = wall_pair_context(p, pairs, pw.particle[c], world.walls[pw.wall[c]].material, 0.0);
    add(stored_contact_energy(model, layout, ctx, pw.history[c], world.contacts.wall_pair_state(c)));
  }
}

}  // namespace

EnergySnapshot measure_energy(const World& world, const PhysicsSettings& physics, const PairTable& pairs) {
  EnergySnapshot e;
  const ParticleArrays& p = world.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    e.kinetic += 0.5 * p.mass[i] * p.velocity[i].squaredNorm() +
                 0.5 * p.inertia[i] * p.angular_velocity[i].squaredNorm();
    e.gravitational -= p.mass[i] * physics.integrator.gravity.dot(p.position[i]);
  }
  add_slot_springs(world, physics.model, pairs, e);
  return e;
}

}  // namespace colza
