// Energy bookkeeping: stored energies are evaluated from the state on demand, dissipated
// energies and boundary work are accumulated step by step by the Stepper. The channels are
// listed once (kStoredChannels, kLedgerChannels, each with the slot that owns it); the
// scene's energy columns, the balance and the energy tests are made from these lists.
#pragma once
#include <string>
#include <vector>
#include "contact/slots.hpp"
#include "engine/world.hpp"

namespace colza {

struct EnergyLedger {
  double slip_dissipated = 0.0;     // Coulomb sliding (J), cumulative
  double damping_dissipated = 0.0;  // local damping (J), cumulative
  double bond_break_lost = 0.0;     // stored energy of contacts that vanished (J): tension break, separation
                                    // of a particle pair, a wall contact leaving its wall's range (wall_pair_force.hpp)
  double shear_break_released = 0.0;  // shear-spring energy released when bonds break in shear (J)
  double wall_work = 0.0;           // work done by moving walls on the particles (J), cumulative
  double rolling_dissipated = 0.0;  // rolling resistance cap (J), cumulative
  double viscous_dissipated = 0.0;  // contact dashpots (J), cumulative
  double plastic_dissipated = 0.0;  // elasto-plastic normal law (J), cumulative
  double shear_stiffness_change = 0.0;  // what the Mindlin spring's energy 1/2 |Fs|^2 / kt lost as kt
                                        // changed at a fixed force (J), cumulative (generic_law.hpp)
};

struct EnergySnapshot {
  double kinetic = 0.0;        // 1/2 m v^2 + 1/2 I w^2 (J); velocities are mid-step values
  double gravitational = 0.0;  // -m g . x (J)
  double elastic_normal = 0.0; // normal springs (J): 1/2 Fn^2 / Kn for the linear law
  double elastic_shear = 0.0;  // shear springs, 1/2 |Fs|^2 / kt (J)
  double elastic_rolling = 0.0;  // rolling springs, 1/2 |Mr|^2 / kr (J)
  double total_stored() const { return kinetic + gravitational + elastic_normal + elastic_shear + elastic_rolling; }
};

// Which model has a channel: every model, or only one with that slot's mechanism.
enum class ChannelOwner { kAlways, kRolling, kViscous, kPlastic, kMindlin };
bool model_has(const ContactModel& model, ChannelOwner owner);

struct StoredChannel {
  const char* column;  // the scene's column (J)
  double EnergySnapshot::*value;
  ChannelOwner owner;
};
// The ledger's terms: energy that left the system (+1) or work done on it (-1, wall_work).
struct LedgerChannel {
  const char* column;
  double EnergyLedger::*value;
  double sign;
  ChannelOwner owner;
};
inline constexpr StoredChannel kStoredChannels[] = {
    {"kinetic_energy", &EnergySnapshot::kinetic, ChannelOwner::kAlways},
    {"gravitational_energy", &EnergySnapshot::gravitational, ChannelOwner::kAlways},
    {"elastic_normal_energy", &EnergySnapshot::elastic_normal, ChannelOwner::kAlways},
    {"elastic_shear_energy", &EnergySnapshot::elastic_shear, ChannelOwner::kAlways},
    {"elastic_rolling_energy", &EnergySnapshot::elastic_rolling, ChannelOwner::kRolling},
};
inline constexpr LedgerChannel kLedgerChannels[] = {
    {"slip_dissipated", &EnergyLedger::slip_dissipated, 1.0, ChannelOwner::kAlways},
    {"damping_dissipated", &EnergyLedger::damping_dissipated, 1.0, ChannelOwner::kAlways},
    {"bond_break_lost", &EnergyLedger::bond_break_lost, 1.0, ChannelOwner::kAlways},
    {"shear_break_released", &EnergyLedger::shear_break_released, 1.0, ChannelOwner::kAlways},
    {"wall_work", &EnergyLedger::wall_work, -1.0, ChannelOwner::kAlways},
    {"rolling_dissipated", &EnergyLedger::rolling_dissipated, 1.0, ChannelOwner::kRolling},
    {"viscous_dissipated", &EnergyLedger::viscous_dissipated, 1.0, ChannelOwner::kViscous},
    {"plastic_dissipated", &EnergyLedger::plastic_dissipated, 1.0, ChannelOwner::kPlastic},
    {"shear_stiffness_change", &EnergyLedger::shear_stiffness_change, 1.0, ChannelOwner::kMindlin},
};

// The energy columns of a model, stored first then the ledger's, in the tables' order.
std::vector<std::string> energy_columns(const ContactModel& model);
// Their values, in the same order.
std::vector<double> energy_values(const ContactModel& model, const EnergySnapshot& e, const EnergyLedger& l);
// Stored energy plus what left minus the walls' work (J): constant when the bookkeeping is complete.
double energy_balance(const EnergySnapshot& e, const EnergyLedger& l);

EnergySnapshot measure_energy(const World& world, const PhysicsSettings& physics, const PairTable& pairs);

}  // namespace colza
