// Bond slot: contact bonds (physics.md section 2 step 5) and load-induced cohesion (7.5).
#pragma once
#include <algorithm>
#include <cstdint>
#include <limits>

namespace colza {

// When bonds are put on particle-particle contacts (physics.md section 2).
enum class BondInstallMoment {
  kNever,
  kAfterSettling,   // on the contacts of the settled sample at rest, after discarding (oedometer, shear box)
  kBeforeLoading,   // on the contacts present when loading starts (oedometer piston / shearing)
  kOnNewContacts,   // every particle-particle contact is bonded the step it forms
};
const char* to_string(BondInstallMoment moment);
// Whether bonds are put on the contacts present at one moment (install_bonds,
// scenario/bonds.hpp), rather than never or as contacts form.
inline bool installs_bonds_at_a_moment(BondInstallMoment m) {
  return m == BondInstallMoment::kAfterSettling || m == BondInstallMoment::kBeforeLoading;
}

struct NoBond {
  static constexpr const char* kName = "none";
  static constexpr int kStateDoubles = 0;
};

// Strengths of an intact bond (N).
struct BondStrengths {
  double normal = 0.0;  // Cn
  double shear = 0.0;   // Cs
};

// PFC contact bond: while intact, tension is allowed (Fn = Kn un also for un < 0) and the
// shear force has no friction limit, only the bond's shear strength.
//   tension break: -Fn > Cn  -> bond and contact removed, no force this step;
//   shear break:   |Fs| > Cs -> bond removed, Fs capped at mu max(Fn, 0) in the same step.
struct ContactBond {
  static constexpr const char* kName = "contact_bond";
  static constexpr int kStateDoubles = 0;
  double normal_strength = 0.0;  // Cn (N)
  double shear_strength = 0.0;   // Cs (N)
};

// Load-induced cohesion (physics.md 7.5; the paper's oil pressed to the seed surface): a
// particle-particle contact is bonded the first time its normal force exceeds F_on, and the
// bond's strengths follow the largest normal force Fmax the contact has carried:
//   Cn = min(a_n Fmax, Cn_cap),  Cs = min(a_s Fmax, Cs_cap)  (N).
// Once bonded it behaves as the contact bond (tension allowed, no friction cap, breaks at Cn
// or Cs) and once broken it does not form again. State: Fmax (N) and whether the bond has
// formed (0 / 1), both unchanged when the pair's bodies swap.
struct LoadInducedBond {
  static constexpr const char* kName = "load_induced";
  static constexpr int kStateDoubles = 2;
  double onset_force = 0.0;            // F_on (N)
  double normal_strength_ratio = 0.0;  // a_n (-)
  double shear_strength_ratio = 0.0;   // a_s (-)
  double normal_strength_cap = std::numeric_limits<double>::infinity();  // N
  double shear_strength_cap = std::numeric_limits<double>::infinity();   // N

  // Notes the step's normal force; returns true when the bond forms in this step.
  bool note_normal_force(double fn, double* state) const {
    state[0] = std::max(state[0], fn);
    if (state[1] != 0.0 || !(fn > onset_force)) return false;
    state[1] = 1.0;
    return true;
  }
  BondStrengths strengths(const double* state) const {
    return {std::min(normal_strength_ratio * state[0], normal_strength_cap),
            std::min(shear_strength_ratio * state[0], shear_strength_cap)};
  }
};

}  // namespace colza
