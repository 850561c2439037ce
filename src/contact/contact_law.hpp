// One step of the baseline contact law for one contact (physics.md section 2, steps 1-6).
// Geometry (normal, overlap, shear increment) is computed by the caller once per contact;
// the law only turns it into forces, as in YADE's geometry -> physics -> law pipeline.
#pragma once
#include <type_traits>
#include "contact/history.hpp"
#include "contact/pair_context.hpp"
#include "contact/slots.hpp"

namespace colza {

enum class ContactEvent : std::uint8_t {
  kNone,
  kCreated,
  kSeparated,          // unbonded contact lost its overlap and was removed
  kBondBrokeTension,   // -Fn > Cn: bond and contact removed
  kBondBrokeShear,     // |Fs| > Cs: bond removed, contact continues frictional
};

struct ContactOutcome {
  Vec3 force_on_2 = Vec3::Zero();  // Fn n + Fs (N); body 1 gets the opposite
  bool carries_force = false;
  ContactEvent event = ContactEvent::kNone;
  double slip_dissipation = 0.0;   // J, this step (Coulomb sliding)
  double bond_break_energy = 0.0;  // J, shear-spring energy released by a shear bond break this step
  double normal_energy_lost = 0.0;  // J, a shear break in tension: the stretched normal spring's energy,
                                    // gone with the contact (it carries no force from this step on)
  // The generic tier's mechanisms (contact/generic_law.hpp); zero on the baseline's paths:
  Vec3 moment_on_2 = Vec3::Zero();    // rolling moment on body 2 (N m); body 1 gets the opposite
  bool has_moment = false;            // a rolling slot acts on this contact
  double rolling_dissipation = 0.0;   // J, this step (rolling cap)
  double viscous_dissipation = 0.0;   // J, this step (dashpots)
  double plastic_dissipation = 0.0;   // J, this step (elasto-plastic normal law)
  double stiffness_change = 0.0;      // J, this step: the Mindlin spring's energy lost as kt changed
};

// Bond slot behaviour, one overload per bond implementation.
enum class BondState : std::uint8_t { kUnbonded, kHolds, kBrokeTension, kBrokeShear };

inline BondState apply_bond(const NoBond&, double, const Vec3&, ContactHistory&) {
  return BondState::kUnbonded;
}
inline BondState apply_bond(const ContactBond& bond, double fn, const Vec3& fs, ContactHistory& h) {
  if (!h.bonded) return BondState::kUnbonded;
  if (-fn > bond.normal_strength) return BondState::kBrokeTension;
  if (fs.squaredNorm() > bond.shear_strength * bond.shear_strength) {
    h.bonded = 0;
    return BondState::kBrokeShear;
  }
  return BondState::kHolds;
}

// bond_new_contacts: a contact created this step starts bonded (install moment "on_new_contacts").
template <class Normal, class Tangential, class Bond>
inline ContactOutcome evaluate_contact(const Normal& normal_law, const Tangential& tangential_law,
                                       const Bond& bond_law, const PairParameters& p,
                                       const ContactKinematics& k, ContactHistory& h,
                                       bool bond_new_contacts) {
  ContactOutcome out;
  bool fresh = false;
  if (!h.touching) {
    if (k.overlap < 0.0) return out;  // not in contact
    h.reset();
    h.touching = 1;
    h.normal = k.normal;
    if constexpr (!std::is_same_v<Bond, NoBond>) h.bonded = bond_new_contacts ? 1 : 0;
    fresh = true;
    out.event = ContactEvent::kCreated;
  }
  if (k.overlap < 0.0 && !h.bonded) {  // step 4: unbonded contact without overlap is removed
    h.reset();
    out.event = ContactEvent::kSeparated;
    return out;
  }
  // Step 1: normal force from the total overlap (also tension while bonded).
  const double fn = normal_law.force(p, k.overlap);
  // Step 2: carry the stored shear force into the current tangent plane (ScGeom::rotate).
  Vec3 fs = h.shear_force;
  if (!fresh) {
    fs -= fs.cross(h.normal.cross(k.normal));
    fs -= fs.cross(k.twist_angle * h.normal);  // twist about the previous normal, as YADE
  }
  const Vec3 fs_carried = fs;
  // Step 3: trial shear force from the shear displacement increment.
  tangential_law.increment(p, fs, k.shear_increment);
  // Steps 4-5: bond or friction limit.
  const BondState bond_state = apply_bond(bond_law, fn, fs, h);
  if (bond_state == BondState::kBrokeTension) {
    h.reset();
    out.event = ContactEvent::kBondBrokeTension;
    return out;
  }
  if (bond_state != BondState::kHolds) {
    const Vec3 fs_trial = fs;
    const double slip = tangential_law.limit(p, fn, fs);
    if (bond_state == BondState::kBrokeShear) out.bond_break_energy = tangential_law.released(p, fs_carried, fs_trial, fs);
    else out.slip_dissipation = slip;
  }
  // A bond broken in shear while in tension leaves an unbonded contact without overlap:
  // it carries no normal force (step 4) and is removed on the next step. YADE applies no
  // normal force in that step either; its older law erases the contact on the next step as
  // here, its newer checkPlasticity in the same step (which YADE 2023.02a has was not
  // checked), which differs only if the pair overlaps again in the next step.
  double fn_applied = fn;
  if (bond_state == BondState::kBrokeShear) {
    out.event = ContactEvent::kBondBrokeShear;
    if (fn < 0.0) {
      fn_applied = 0.0;
      out.normal_energy_lost = normal_law.energy(p, fn);
    }
  }
  h.shear_force = fs;
  h.normal = k.normal;
  h.normal_force = fn_applied;
  out.force_on_2 = fn_applied * k.normal + fs;  // step 6
  out.carries_force = true;
  return out;
}

}  // namespace colza
