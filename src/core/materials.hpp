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
  double young_modulus = 0.0;  // E (Pa), for the Hertz-Mindlin slots; 0 when not given
  double poisson_ratio = 0.0;  // nu (-), for the Hertz-Mindlin slots
};

struct WallMaterial {
  std::string name;
  double kn = 0.0;        // N/m
  double ks = 0.0;        // N/m
  double friction = 0.0;  // particle-wall friction coefficient mu_pw (-), see WallFrictionRule
  double young_modulus = 0.0;  // E (Pa), for the Hertz-Mindlin slots; 0 when not given
  double poisson_ratio = 0.0;  // nu (-)
};

// Everything the contact law needs to know about one pair of entities.
struct PairParameters {
  double kn = 0.0;        // contact normal stiffness Kn (N/m)
  double ks = 0.0;        // contact shear stiffness Ks (N/m)
  double friction = 0.0;  // Coulomb coefficient mu
  // Hertz-Mindlin moduli of the pair (physics.md section 7.2), 0 when a material has no E:
  //   1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,  1/G* = 2(2 - nu1)(1 + nu1)/E1 + 2(2 - nu2)(1 + nu2)/E2 (Pa).
  double effective_young = 0.0;  // E* (Pa)
  double effective_shear = 0.0;  // G* (Pa)
};

// E* and G* of two materials (Pa), as PairParameters states; both 0 unless both E > 0.
struct HertzModuli {
  double effective_young = 0.0, effective_shear = 0.0;
};
HertzModuli hertz_moduli(double young_1, double poisson_1, double young_2, double poisson_2);

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
