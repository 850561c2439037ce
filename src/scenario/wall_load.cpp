#include "scenario/wall_load.hpp"

namespace colza {

double wall_normal_force_sum(const ContactStore& contacts, Index wall) {
  const WallPairList& pairs = contacts.wall_pairs;
  double sum = 0.0;
  for (std::size_t k = 0; k < pairs.size(); ++k)
    if (pairs.wall[k] == wall && pairs.history[k].touching) sum += pairs.history[k].normal_force;
  return sum;
}

}  // namespace colza
