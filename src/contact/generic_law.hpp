// One step of the contact law for one contact, any slot combination (the generic tier;
// physics.md section 2 steps 1-6 with the mechanisms of section 7). Each slot is chosen at
// run time per contact (visit_slot, contact/slots.hpp), so combinations add no compiled
// copies of the loops.
// With the baseline's slots it performs the baseline's IEEE operations in the baseline's
// order (contact/contact_law.hpp), so the two tiers give the same bits
// (ForcePaths.TheGenericTierGivesTheBaselineBits).
//
// Order within a step: the normal law (and the bond forming under load), the shear force
// carried into the new tangent plane and incremented, the rolling moment likewise, the
// bond's rule or the Coulomb cap, then the dashpots. The caps take the elastic normal force
// Fn, not the damped one, so a contact's strength does not depend on the speed.
#pragma once
#include <algorithm>
#include <type_traits>
#include <variant>
#include "contact/contact_law.hpp"
#include "contact/slot_state.hpp"

namespace colza {

// The state of a slot row: zero for a new or vanished contact.
inline void clear_slot_state(double* state, std::size_t stride) { std::fill(state, state + stride, 0.0); }

namespace detail {

inline BondState apply_generic_bond(const NoBond&, double, const Vec3&, ContactHistory&, const double*) {
  return BondState::kUnbonded;
}
inline BondState apply_generic_bond(const ContactBond& b, double fn, const Vec3& fs, ContactHistory& h,
                                    const double*) {
  return apply_bond(b, fn, fs, h);
}
inline BondState apply_generic_bond(const LoadInducedBond& b, double fn, const Vec3& fs, ContactHistory& h,
                                    const double* state) {
  const BondStrengths s = b.strengths(state);
  return apply_bond(ContactBond{s.normal, s.shear}, fn, fs, h);
}

}  // namespace detail

// Stored energy of a contact (J), spring by spring.
struct ContactEnergy {
  double normal = 0.0, shear = 0.0, rolling = 0.0;
};
inline ContactEnergy stored_contact_energy(const ContactModel& m, const SlotStateLayout& layout, const PairContext& c,
                                           const ContactHistory& h, const double* state) {
  const double fn = h.normal_force;
  ContactEnergy e;
  double overlap = 0.0;
  std::visit(
      [&](const auto& normal) {
        e.normal = normal.energy(c, fn, state + layout.normal);
        overlap = normal.overlap(c, fn, state + layout.normal);
      },
      m.normal);
  // Mindlin's spring: the kt of its last step (kept in its state), else the law's at the overlap.
  const double kept_kt = std::holds_alternative<MindlinTangential>(m.tangential) ? state[layout.tangential] : 0.0;
  const double kt =
      kept_kt > 0.0 ? kept_kt : visit_slot(m.tangential, [&](const auto& t) { return t.stiffness(c, overlap); });
  e.shear = shear_spring_energy(kt, h.shear_force);
  if (const auto* rolling = std::get_if<ElasticPlasticRolling>(&m.rolling); rolling && rolling->acts(c)) {
    const double* mr = state + layout.rolling;
    e.rolling = rolling->energy(c, Vec3(mr[0], mr[1], mr[2]));
  }
  return e;
}

// The generic law. `state` is the pair's slot-state row (layout.stride doubles);
// bond_new_contacts as in evaluate_contact.
inline ContactOutcome evaluate_contact_generic(const ContactModel& m, const SlotStateLayout& layout,
                                               const PairContext& c, const ContactKinematics& k,
                                               ContactHistory& h, double* state, bool bond_new_contacts) {
  ContactOutcome out;
  bool fresh = false;
  if (!h.touching) {
    if (k.overlap < 0.0) return out;  // not in contact
    h.reset();
    clear_slot_state(state, layout.stride);
    h.touching = 1;
    h.normal = k.normal;
    if (std::holds_alternative<ContactBond>(m.bond) && !c.with_wall) h.bonded = bond_new_contacts ? 1 : 0;
    fresh = true;
    out.event = ContactEvent::kCreated;
  }
  // The Mindlin spring's stiffness of the previous step (its state; the stiffness-change
  // channel below).
  const bool stiffness_varies = std::holds_alternative<MindlinTangential>(m.tangential);
  const double kt_previous = stiffness_varies ? state[layout.tangential] : 0.0;
  if (k.overlap < 0.0 && !h.bonded) {  // step 4: unbonded contact without overlap is removed
    h.reset();
    clear_slot_state(state, layout.stride);
    out.event = ContactEvent::kSeparated;
    return out;
  }
  // Step 1: normal force (also tension while bonded); a load-induced bond forms here.
  const NormalResult normal =
      visit_slot(m.normal, [&](const auto& n) { return n.force(c, k.overlap, state + layout.normal, h.bonded != 0); });
  const double fn = normal.force;
  out.plastic_dissipation = normal.dissipated;
  if (const auto* load_bond = std::get_if<LoadInducedBond>(&m.bond); load_bond && !c.with_wall)
    if (load_bond->note_normal_force(fn, state + layout.bond)) h.bonded = 1;
  // Step 2: carry the stored shear force (and the rolling moment) into the current tangent plane.
  Vec3 fs = h.shear_force;
  const Vec3 tilt = h.normal.cross(k.normal);
  const Vec3 spin = k.twist_angle * h.normal;
  if (!fresh) {
    fs -= fs.cross(tilt);
    fs -= fs.cross(spin);  // twist about the previous normal, as YADE
  }
  const Vec3 fs_carried = fs;
  // Step 3: trial shear force from the shear displacement increment.
  const double kt = visit_slot(m.tangential, [&](const auto& t) { return t.stiffness(c, k.overlap); });
  // Mindlin's incremental spring has no potential: at a fixed force its energy 1/2 |Fs|^2 / kt
  // changes with kt (the overlap), by 1/2 |Fs|^2 (1/kt - 1/kt_prev) (J), work no force did.
  // Booked (with the opposite sign) so that the balance states it.
  if (stiffness_varies) {
    if (!fresh) out.stiffness_change = -0.5 * fs_carried.squaredNorm() * (1.0 / kt - 1.0 / kt_previous);
    state[layout.tangential] = kt;
  }
  fs -= kt * k.shear_increment;
  // Rolling moment (physics.md 7.1): carried like Fs, incremented by the bending rotation, capped.
  const auto* rolling = std::get_if<ElasticPlasticRolling>(&m.rolling);
  if (rolling && rolling->acts(c)) {
    double* mr_state = state + layout.rolling;
    Vec3 mr(mr_state[0], mr_state[1], mr_state[2]);
    if (!fresh) {
      mr -= mr.cross(tilt);
      mr -= mr.cross(spin);
    }
    const RollingStep step = rolling->update(c, k.normal, k.rotation_increment, fn, mr);
    out.rolling_dissipation = step.dissipated;
    mr_state[0] = mr[0];
    mr_state[1] = mr[1];
    mr_state[2] = mr[2];
    out.moment_on_2 = rolling->damping_ratio > 0.0 ? Vec3(mr + step.dashpot_moment) : mr;
    out.has_moment = true;
  }
  // Steps 4-5: bond or friction limit.
  const BondState bond_state =
      visit_slot(m.bond, [&](const auto& b) { return detail::apply_generic_bond(b, fn, fs, h, state + layout.bond); });
  // A tension break removes the contact (section 2 step 5) when the spheres no longer
  // overlap, which for the linear and Hertz laws is the only case (tension means un < 0).
  // An elasto-plastic contact is in tension already below its plastic overlap d0 > 0: its
  // spheres still overlap, so the contact lives on unbonded (with its largest overlap
  // remembered) and the break is booked like a shear break.
  const bool broke_overlapping = bond_state == BondState::kBrokeTension && k.overlap >= 0.0;
  if (broke_overlapping) h.bonded = 0;
  if (bond_state == BondState::kBrokeTension && !broke_overlapping) {
    h.reset();
    clear_slot_state(state, layout.stride);
    out.event = ContactEvent::kBondBrokeTension;
    out.moment_on_2 = Vec3::Zero();
    out.has_moment = false;
    out.rolling_dissipation = 0.0;
    return out;
  }
  bool sliding = false;
  if (bond_state != BondState::kHolds) {
    const Vec3 fs_trial = fs;
    const double slip = coulomb_cap(c.q.friction, kt, fn, fs);
    sliding = slip != 0.0 || fs_trial != fs;
    if (bond_state == BondState::kBrokeShear || broke_overlapping)
      out.bond_break_energy = shear_spring_released(kt, fs_carried, fs_trial, fs);
    else
      out.slip_dissipation = slip;
  }
  double fn_applied = fn;
  if (bond_state == BondState::kBrokeShear || broke_overlapping) {
    out.event = broke_overlapping ? ContactEvent::kBondBrokeTension : ContactEvent::kBondBrokeShear;
    if (fn < 0.0) {
      fn_applied = 0.0;
      out.normal_energy_lost =
          visit_slot(m.normal, [&](const auto& n) { return n.energy(c, fn, state + layout.normal); });
    }
  }
  // Dashpots (physics.md 7.3): not stored in the history; their work is the viscous channel.
  Vec3 fs_applied = fs;
  if (const auto* viscous = std::get_if<ViscousDamping>(&m.damping)) {
    const double kn = visit_slot(m.normal, [&](const auto& n) { return n.tangent_stiffness(c, k.overlap, state + layout.normal); });
    const double damped = fn_applied - viscous->normal_coefficient(c, kn) * k.normal_velocity;
    const double fn_damped = h.bonded ? damped : std::max(damped, 0.0);
    const double dt = c.dt;
    out.viscous_dissipation = -(fn_damped - fn_applied) * k.normal_velocity * dt;
    fn_applied = fn_damped;
    if (!sliding && bond_state != BondState::kBrokeShear && !broke_overlapping && dt > 0.0) {
      fs_applied = fs - viscous->tangential_coefficient(c, kt) * (k.shear_increment / dt);
      if (!h.bonded) {  // the dashpot never takes the total past the Coulomb limit
        const double max_fs = c.q.friction * std::max(fn, 0.0);
        const double f2 = fs_applied.squaredNorm();
        if (f2 > max_fs * max_fs) fs_applied *= max_fs / std::sqrt(f2);
      }
      out.viscous_dissipation -= (fs_applied - fs).dot(k.shear_increment);
    }
  }
  h.shear_force = fs;
  h.normal = k.normal;
  h.normal_force = (bond_state == BondState::kBrokeShear || broke_overlapping) && fn < 0.0 ? 0.0 : fn;  // elastic
  out.force_on_2 = fn_applied * k.normal + fs_applied;  // step 6
  out.carries_force = true;
  return out;
}

}  // namespace colza
