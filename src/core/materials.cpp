#include "core/materials.hpp"

#include <algorithm>

namespace colza {

const char* to_string(StiffnessRule rule) {
  return rule == StiffnessRule::kSeries ? "series" : "contact";
}

const char* to_string(WallFrictionRule rule) { return rule == WallFrictionRule::kOwn ? "own" : "min"; }

double combine_stiffness(double k1, double k2, StiffnessRule rule) {
  if (rule == StiffnessRule::kSeries) return k1 * k2 / (k1 + k2);
  // "contact": the configured numbers already are contact stiffnesses. Two entities
  // with different numbers: use the smaller (the softer entity dominates a contact).
  return std::min(k1, k2);
}

PairParameters particle_pair(const ParticleMaterial& a, const ParticleMaterial& b, StiffnessRule rule) {
  return {combine_stiffness(a.kn, b.kn, rule), combine_stiffness(a.ks, b.ks, rule),
          std::min(a.friction, b.friction)};
}

PairParameters particle_wall_pair(const ParticleMaterial& p, const WallMaterial& w, StiffnessRule rule,
                                  WallFrictionRule friction_rule) {
  const double mu = friction_rule == WallFrictionRule::kOwn ? w.friction : std::min(p.friction, w.friction);
  if (rule == StiffnessRule::kContact) return {w.kn, w.ks, mu};  // wall numbers are the contact's
  return {combine_stiffness(p.kn, w.kn, rule), combine_stiffness(p.ks, w.ks, rule), mu};
}

PairTable::PairTable(const std::vector<ParticleMaterial>& particles,
                     const std::vector<WallMaterial>& walls, StiffnessRule rule, WallFrictionRule wall_friction)
    : n_particle_(particles.size()), n_wall_(walls.size()), rule_(rule) {
  pp_.resize(n_particle_ * n_particle_);
  for (std::size_t a = 0; a < n_particle_; ++a)
    for (std::size_t b = 0; b < n_particle_; ++b)
      pp_[a * n_particle_ + b] = particle_pair(particles[a], particles[b], rule);
  pw_.resize(n_particle_ * n_wall_);
  for (std::size_t p = 0; p < n_particle_; ++p)
    for (std::size_t w = 0; w < n_wall_; ++w)
      pw_[p * n_wall_ + w] = particle_wall_pair(particles[p], walls[w], rule, wall_friction);
}

}  // namespace colza
