// Energy bookkeeping: stored energies are evaluated from the state on demand, dissipated
// energies and boundary work are accumulated step by step by the Stepper.
#pragma once
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
};

struct EnergySnapshot {
  double kinetic = 0.0;        // 1/2 m v^2 + 1/2 I w^2 (J); velocities are mid-step values
  double gravitational = 0.0;  // -m g . x (J)
  double elastic_normal = 0.0; // sum of 1/2 Fn^2 / Kn (J)
  double elastic_shear = 0.0;  // sum of 1/2 |Fs|^2 / Ks (J)
  double total_stored() const { return kinetic + gravitational + elastic_normal + elastic_shear; }
};

EnergySnapshot measure_energy(const World& world, const PhysicsSettings& physics, const PairTable& pairs);

}  // namespace colza
