#include "scenario/bonds.hpp"

#include <sstream>
#include <stdexcept>

namespace colza {

std::size_t install_bonds(World& world, Stepper& stepper, double gap) {
  if (!(gap < stepper.physics().skin)) {
    std::ostringstream why;
    why.precision(15);  // as the config check's message: a gap a hair above the skin must not print as it
    why << "bond gap " << gap << " m is not below the Verlet skin " << stepper.physics().skin << " m";
    throw std::invalid_argument(why.str());
  }
  // A pair that was not a candidate at the last build may have closed by up to the skin since
  // (each sphere moves at most skin/2 between builds): only a fresh list holds every pair
  // whose gap is below the skin.
  stepper.rebuild_neighbours(world);
  const ParticleArrays& p = world.particles;
  auto& pairs = world.contacts.particle_pairs;
  std::size_t installed = 0, new_contacts = 0;
  for (std::size_t c = 0; c < pairs.size(); ++c) {
    const Index i = pairs.first[c], j = pairs.second[c];
    const Vec3 d = p.position[j] - p.position[i];
    const double dist = d.norm();
    const double overlap = p.radius[i] + p.radius[j] - dist;
    if (overlap < -gap) continue;
    ContactHistory& h = pairs.history[c];
    if (!h.touching) {  // a pair within the gap tolerance becomes a (bonded) contact now
      h.reset();
      h.touching = 1;
      h.normal = d / dist;
      ++new_contacts;
    }
    if (!h.bonded) {
      h.bonded = 1;
      ++installed;
    }
  }
  // New contacts stiffen their spheres (k_i grows by kn + ks each), so the critical time step
  // may have dropped: evaluate it now rather than at the next recompute_interval. Overlaps
  // count too: right after prepare() (a packing read from a file) no force pass has flagged
  // the wall contacts, which the flags alone would leave out.
  if (new_contacts > 0) stepper.update_time_step(world, CountedContacts::kTouchingOrOverlapping);
  return installed;
}

}  // namespace colza
