// The simulated state: bodies, their interactions and the clock. Plain data; the
// Stepper advances it, scenarios build and drive it.
#pragma once
#include <vector>
#include "contact/contact_store.hpp"
#include "contact/slot_state.hpp"
#include "contact/slots.hpp"
#include "core/materials.hpp"
#include "core/particles.hpp"
#include "integrate/integrator.hpp"
#include "integrate/time_step.hpp"
#include "walls/wall.hpp"

namespace colza {

struct World {
  ParticleArrays particles;
  std::vector<Wall> walls;
  ContactStore contacts;
  double time = 0.0;        // s
  std::uint64_t step = 0;
  double dt = 0.0;          // current time step (s)
};

// Everything that defines the physics of a run (materials, contact model, integration).
struct PhysicsSettings {
  std::vector<ParticleMaterial> particle_materials;
  std::vector<WallMaterial> wall_materials;
  StiffnessRule stiffness_rule = StiffnessRule::kSeries;
  WallFrictionRule wall_friction = WallFrictionRule::kOwn;
  ContactModel model;
  IntegratorSettings integrator;
  TimeStepSettings time_step;
  double skin = 0.0;  // Verlet skin (m)
  // Run the generic tier even for the baseline model (tests compare the two tiers' bits;
  // benchmarks measure the generic tier's cost).
  bool generic_tier_only = false;
};

}  // namespace colza
