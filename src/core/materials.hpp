// Entity properties and how they combine into contact parameters (physics.md section 2).
#pragma once
#include <cassert>
#include <string>
#include <vector>
#include "core/types.hpp"

namespace colza {

// How entity stiffnesses become contact stiffnesses.
enum class StiffnessRule {
  kSeries,   // Kn = kn1 kn2 / (kn1 + kn2), same for Ks (PFC3D 4 linear model)
  kContact,  // the entity numbers are the contact stiffnesses: particle-wall contacts take the
             // wall's numbers; two particle materials with different numbers take the smaller
};
const char* to_string(StiffnessRule rule);

// The friction coefficient of a particle-wall contact (physics.md section 2, "Friction").
enum class WallFrictionRule {
  kOwn,      // the wall's mu_pw, as physics.md states (the paper lists mu_pw as a parameter)
  kMinimum,  // min(mu_pp, mu_pw): PFC3D 4's rule at every contact, walls included; with Table 1
             // (0.20, 0.23) the paper's own PFC runs would have had 0.20 at the walls
};
const char* to_string(WallFrictionRule rule);

struct ParticleMaterial {
  std::string name;
  double density = 0.0;   // kg/m^3
  double kn = 0.0;        // normal stiffness of the entity (N/m)
  double ks = 0.0;        // shear stiffness of the entity (N/m)
  double friction = 0.0;  // particle-particle friction coefficient mu_pp (-)
};

struct WallMaterial {
  std::string name;
  double kn = 0.0;        // N/m
  double ks = 0.0;        // N/m
  double friction = 0.0;  // particle-wall friction coefficient mu_pw (-), see WallFrictionRule
};

// Everything the contact law needs to know about one pair of entities.
struct PairParameters {
  double kn = 0.0;        // contact normal stiffness Kn (N/m)
  double ks = 0.0;        // contact shear stiffness Ks (N/m)
  double friction = 0.0;  // Coulomb coefficient mu
};

double combine_stiffness(double k1, double k2, StiffnessRule rule);

// Particle-particle: stiffness by the rule, friction = min(mu1, mu2) (PFC's rule; equal for
// one seed material). Particle-wall: stiffness by the rule, friction by `friction_rule` (the
// wall's mu_pw, or min(mu_pp, mu_pw)).
PairParameters particle_pair(const ParticleMaterial& a, const ParticleMaterial& b, StiffnessRule rule);
PairParameters particle_wall_pair(const ParticleMaterial& p, const WallMaterial& w, StiffnessRule rule,
                                  WallFrictionRule friction_rule = WallFrictionRule::kOwn);

// Precomputed table of pair parameters, indexed by material indices.
class PairTable {
 public:
  PairTable() = default;
  PairTable(const std::vector<ParticleMaterial>& particles, const std::vector<WallMaterial>& walls,
            StiffnessRule rule, WallFrictionRule wall_friction = WallFrictionRule::kOwn);
  // Arguments are MATERIAL indices (ParticleArrays::material, Wall::material), not body indices.
  const PairParameters& particle_particle(std::size_t a, std::size_t b) const {
    assert(a < n_particle_ && b < n_particle_);
    return pp_[a * n_particle_ + b];
  }
  const PairParameters& particle_wall(std::size_t p, std::size_t w) const {
    assert(p < n_particle_ && w < n_wall_);
    return pw_[p * n_wall_ + w];
  }
  std::size_t particle_material_count() const { return n_particle_; }
  StiffnessRule rule() const { return rule_; }

 private:
  std::size_t n_particle_ = 0, n_wall_ = 0;
  std::vector<PairParameters> pp_, pw_;
  StiffnessRule rule_ = StiffnessRule::kSeries;
};

}  // namespace colza
