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

// Springs of the baseline: 1/2 Fn^2 / Kn and 1/2 |Fs|^2 / Ks per contact.
void add_baseline_springs(const World& world, const PairTable& pairs, EnergySnapshot& e) {
  const ParticleArrays& p = world.particles;
  const LinearNormal normal;
  const CoulombTangential tangential;
  const auto& pp = world.contacts.particle_pairs;
  for (std::size_t c = 0; c < pp.size(); ++c) {
    const ContactHistory& h = pp.history[c];
    if (!h.touching) continue;
    const PairParameters& q = pairs.particle_particle(p.material[pp.first[c]], p.material[pp.second[c]]);
    e.elastic_normal += normal.energy(q, h.normal_force);
    e.elastic_shear += tangential.energy(q, h.shear_force);
  }
  const auto& pw = world.contacts.wall_pairs;
  for (std::size_t c = 0; c < pw.size(); ++c) {
    const ContactHistory& h = pw.history[c];
    if (!h.touching) continue;
    const PairParameters& q = pairs.particle_wall(p.material[pw.particle[c]], world.walls[pw.wall[c]].material);
    e.elastic_normal += normal.energy(q, h.normal_force);
    e.elastic_shear += tangential.energy(q, h.shear_force);
  }
}

// Springs of any model, each slot stating its own (contact/generic_law.hpp).
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
    const Index i = pp.first[c], j = pp.second[c];
    const double ri = p.radius[i], rj = p.radius[j], mi = p.mass[i], mj = p.mass[j];
    const PairContext ctx{pairs.particle_particle(p.material[i], p.material[j]), ri, rj, ri * rj / (ri + rj),
                          mi * mj / (mi + mj), 0.0, false};
    add(stored_contact_energy(model, layout, ctx, pp.history[c], pp.slot_state.data() + c * layout.stride));
  }
  const auto& pw = world.contacts.wall_pairs;
  for (std::size_t c = 0; c < pw.size(); ++c) {
    if (!pw.history[c].touching) continue;
    const Index i = pw.particle[c];
    const double r = p.radius[i];
    const PairContext ctx{pairs.particle_wall(p.material[i], world.walls[pw.wall[c]].material), r, r, r, p.mass[i],
                          0.0, true};
    add(stored_contact_energy(model, layout, ctx, pw.history[c], pw.slot_state.data() + c * layout.stride));
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
  if (is_baseline(physics.model)) add_baseline_springs(world, pairs, e);
  else add_slot_springs(world, physics.model, pairs, e);
  return e;
}

}  // namespace colza
