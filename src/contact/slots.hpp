// Contact-law slots (physics.md section 2). A contact model is one implementation per slot:
//   normal     - force from the overlap;
//   tangential - incremental shear spring and its sliding limit;
//   bond       - contact bond (tension allowed, breaks at Cn / Cs) or none.
// Each slot implementation is a small struct of typed parameters with pure functions; a new
// mechanism is one struct here (or in its own header), one alternative in the slot's
// variant and one row in slot_registry.cpp. Slots are resolved with std::visit outside the
// contact loop, so the loop itself is compiled for the concrete combination.
#pragma once
#include <cmath>
#include <type_traits>
#include <variant>
#include "core/materials.hpp"
#include "core/types.hpp"

namespace colza {

// ---- normal slot --------------------------------------------------------------------

// Linear spring on the total overlap: Fn = Kn un (N), compression positive.
struct LinearNormal {
  static constexpr const char* kName = "linear";
  double force(const PairParameters& p, double overlap) const { return p.kn * overlap; }
  // Stored elastic energy 1/2 Fn^2 / Kn (J).
  double energy(const PairParameters& p, double fn) const { return 0.5 * fn * fn / p.kn; }
};

using NormalSlot = std::variant<LinearNormal>;

// Code outside the contact loop that reads the normal law as the linear spring Fn = Kn un:
// the overlap guard's un = Fn / Kn (engine/motion_limits.cpp), the critical time step's
// translational stiffness Kn + Ks (integrate/time_step.cpp) and the shear-box servo's plate
// stiffness Kn per contact (scenario/shear_box.cpp). Each static_asserts this, so a new
// normal alternative (Hertz, say) fails to compile there until those places take the slot's
// own overlap and tangent stiffness, instead of silently misjudging them.
inline constexpr bool kNormalLawIsLinear =
    std::variant_size_v<NormalSlot> == 1 && std::is_same_v<std::variant_alternative_t<0, NormalSlot>, LinearNormal>;

// ---- tangential slot ----------------------------------------------------------------

// Incremental linear shear spring, Fs <- Fs - Ks dus, capped at the Coulomb limit
// |Fs| <= mu max(Fn, 0) (Cundall & Strack 1979; PFC3D linear model; YADE CundallStrack).
struct CoulombTangential {
  static constexpr const char* kName = "coulomb";
  void increment(const PairParameters& p, Vec3& fs, const Vec3& shear_increment) const {
    fs -= p.ks * shear_increment;
  }
  // Scales fs onto the Coulomb limit if it exceeds it. Returns the energy dissipated by
  // the slip, (F_trial - F_capped) . F_capped / Ks (J) (same bookkeeping as YADE).
  double limit(const PairParameters& p, double fn, Vec3& fs) const {
    const double max_fs = p.friction * std::max(fn, 0.0);
    const double fs2 = fs.squaredNorm();
    if (fs2 <= max_fs * max_fs) return 0.0;
    const Vec3 trial = fs;
    fs *= max_fs / std::sqrt(fs2);
    return (trial - fs).dot(fs) / p.ks;
  }
  double energy(const PairParameters& p, const Vec3& fs) const { return 0.5 * fs.squaredNorm() / p.ks; }
  // Energy that leaves the shear spring in a step whose force goes from `carried` (the
  // previous force, carried into the new tangent plane) through `trial` to `capped` (J):
  //   D = (F_carried + F_capped) . (F_trial - F_capped) / (2 Ks).
  // It is the work of the applied forces over the step (trapezoid, as leapfrog integrates
  // it) minus the change of stored energy; in steady sliding it equals F delta. Used for the
  // drop of a shear bond break, where Fs falls from about Cs to mu Fn in one step.
  double released(const PairParameters& p, const Vec3& carried, const Vec3& trial, const Vec3& capped) const {
    return (carried + capped).dot(trial - capped) / (2.0 * p.ks);
  }
};

using TangentialSlot = std::variant<CoulombTangential>;

// ---- bond slot ----------------------------------------------------------------------

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
};

// PFC contact bond: while intact, tension is allowed (Fn = Kn un also for un < 0) and the
// shear force has no friction limit, only the bond's shear strength.
//   tension break: -Fn > Cn  -> bond and contact removed, no force this step;
//   shear break:   |Fs| > Cs -> bond removed, Fs capped at mu max(Fn, 0) in the same step.
struct ContactBond {
  static constexpr const char* kName = "contact_bond";
  double normal_strength = 0.0;  // Cn (N)
  double shear_strength = 0.0;   // Cs (N)
};

using BondSlot = std::variant<NoBond, ContactBond>;

struct ContactModel {
  NormalSlot normal;
  TangentialSlot tangential;
  BondSlot bond;
  BondInstallMoment bond_install = BondInstallMoment::kNever;
  double bond_gap = 0.0;  // bonds also join pairs whose gap (-un) is at most this (m)
};

}  // namespace colza
