// Servo control of a loading plate's normal force (PFC-style wall servo).
// Each step the plate velocity along its normal is set so that a fraction `relaxation` of
// the force error would be removed in one step if the plate's contacts alone deformed:
//   v = relaxation (F_target - F) / (k_plate dt),   k_plate = sum of Kn over its contacts,
// clamped to |v| <= max_speed. The bulk behind the contacts is softer than k_plate, so the
// correction is an underestimate and the loop is stable for relaxation <= 1.
#pragma once
#include "core/types.hpp"

namespace colza {

struct PlateServo {
  double target_force = 0.0;  // N, compression positive (force of the particles on the plate)
  double relaxation = 0.5;    // -
  double max_speed = 0.05;    // m/s
  // Speed of the plate towards the particles (m/s; positive = advancing, compressing).
  double advance_speed(double force, double contact_stiffness, double dt) const;
};

}  // namespace colza
