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

HertzModuli hertz_moduli(double young_1, double poisson_1, double young_2, double poisson_2) {
  if (!(young_1 > 0.0) || !(young_2 > 0.0)) return {};
  const double inv_e = (1.0 - poisson_1 * poisson_1) / young_1 + (1.0 - poisson_2 * poisson_2) / young_2;
  const double inv_g = 2.0 * (2.0 - poisson_1) * (1.0 + poisson_1) / young_1 +
                       2.0 * (2.0 - poisson_2) * (1.0 + poisson_2) / young_2;
  return {1.0 / inv_e, 1.0 / inv_g};
}

PairParameters particle_pair(const ParticleMaterial& a, const ParticleMaterial& b, StiffnessRule rule) {
  const HertzModuli h = hertz_moduli(a.young_modulus, a.poisson_ratio, b.young_modulus, b.poisson_ratio);
  return {combine_stiffness(a.kn, b.kn, rule), combine_stiffness(a.ks, b.ks, rule),
          std::min(a.friction, b.friction), h.effective_young, h.effective_shear};
}

PairParameters particle_wall_pair(const ParticleMaterial& p, const WallMaterial& w, StiffnessRule rule,
                                  WallFrictionRule friction_rule) {
  const double mu = friction_rule == WallFrictionRule::kOwn ? w.friction : std::min(p.friction, w.friction);
  const HertzModuli h = hertz_moduli(p.young_modulus, p.poisson_ratio, w.young_modulus, w.poisson_ratio);
  if (rule == StiffnessRule::kContact)  // wall numbers are the contact's
    return {w.kn, w.ks, mu, h.effective_young, h.effective_shear};
  return {combine_stiffness(p.kn, w.kn, rule), combine_stiffness(p.ks, w.ks, rule), mu, h.effective_young,
          h.effective_shear};
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
