// Damping slot: viscous contact damping (physics.md section 7.3). Local (Cundall) damping
// acts on bodies, not contacts, and lives in integrate/integrator.cpp.
#pragma once
#include <cmath>
#include "contact/pair_context.hpp"

namespace colza {

struct NoDamping {
  static constexpr const char* kName = "none";
};

// Normal and tangential dashpots by critical damping ratio (Cundall & Strack 1979; LIGGGHTS
// and LAMMPS GRANULAR `viscoelastic` damping with a damping ratio):
//   cn = 2 zeta_n sqrt(m* kn),  ct = 2 zeta_t sqrt(m* kt)   (N s/m),
// kn, kt the normal and tangential laws' tangent stiffnesses at this overlap. On body 2:
// normal -cn vn n (vn = vr . n, approach negative), tangential -ct vt (vt = dus / dt), the
// latter only while the contact sticks. The damped normal force of an unbonded contact is
// never attractive (clamped at 0). For the linear law the head-on restitution is
// e = exp(-pi zeta_n / sqrt(1 - zeta_n^2)).
struct ViscousDamping {
  static constexpr const char* kName = "viscous";
  double normal_ratio = 0.0;      // zeta_n (-)
  double tangential_ratio = 0.0;  // zeta_t (-)
  double normal_coefficient(const PairContext& c, double kn) const {
    return 2.0 * normal_ratio * std::sqrt(c.effective_mass * kn);
  }
  double tangential_coefficient(const PairContext& c, double kt) const {
    return 2.0 * tangential_ratio * std::sqrt(c.effective_mass * kt);
  }
};

}  // namespace colza
