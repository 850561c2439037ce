#include "engine/energy.hpp"

#include <variant>

namespace colza {

EnergySnapshot measure_energy(const World& world, const PhysicsSettings& physics, const PairTable& pairs) {
  EnergySnapshot e;
  const ParticleArrays& p = world.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    e.kinetic += 0.5 * p.mass[i] * p.velocity[i].squaredNorm() +
                 0.5 * p.inertia[i] * p.angular_velocity[i].squaredNorm();
    e.gravitational -= p.mass[i] * physics.integrator.gravity.dot(p.position[i]);
  }
  std::visit(
      [&](const auto& normal, const auto& tangential) {
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
      },
      physics.model.normal, physics.model.tangential);
  return e;
}

}  // namespace colza
