// Per-contact state carried from step to step, kept by pair (not on particles).
#pragma once
#include "core/types.hpp"

namespace colza {

struct ContactHistory {
  Vec3 shear_force = Vec3::Zero();  // Fs on body 2, carried in the tangent plane (N)
  Vec3 normal = Vec3::Zero();       // unit normal of the previous step (small-rotation update)
  double normal_force = 0.0;        // Fn of the last step, compression positive (N) (for output/energy)
  std::uint8_t touching = 0;        // 1 while the contact exists and carries force
  std::uint8_t bonded = 0;          // 1 while an intact contact bond joins the pair

  void reset() { *this = ContactHistory{}; }
};

}  // namespace colza
