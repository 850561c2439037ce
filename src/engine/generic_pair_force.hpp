// Geometry and generic contact law of one particle pair or sphere-wall pair (the generic
// tier, contact/generic_law.hpp). The geometry is the baseline's (engine/pair_force.hpp,
// engine/wall_pair_force.hpp), expression for expression, plus what the mechanisms read:
// the normal relative velocity vn = vr . n (m/s), the relative rotation (w2 - w1) dt (rad),
// and the pair's radii, R* and m*.
#pragma once
#include "contact/generic_law.hpp"
#include "engine/pair_force.hpp"
#include "engine/wall_pair_force.hpp"
#include "walls/wall.hpp"

namespace colza::detail {

// A contact's history and slot-state row as they were before the law ran.
struct SlotRow {
  ContactHistory history;
  double state[kMaxSlotStride] = {};
};
inline SlotRow save_row(const ContactHistory& h, const double* state, std::size_t stride) {
  SlotRow r;
  r.history = h;
  for (std::size_t d = 0; d < stride; ++d) r.state[d] = state[d];
  return r;
}

// The stored energy of a contact that vanished, from its saved row (J): rare, so kept out of
// the force loop's code (it inlines everything else).
[[gnu::noinline, gnu::cold]] inline ContactEnergy vanished_energy(const ContactModel& model,
                                                                  const SlotStateLayout& layout, const PairContext& c,
                                                                  const SlotRow& saved) {
  return stored_contact_energy(model, layout, c, saved.history, saved.state);
}

// The generic law's dissipation channels of one outcome go to the sink.
template <class Sink>
inline void book_mechanisms(const ContactOutcome& out, Sink& sink) {
  sink.rolling(out.rolling_dissipation);
  sink.viscous(out.viscous_dissipation);
  sink.plastic(out.plastic_dissipation);
  sink.stiffness_change(out.stiffness_change);
}

// Particle pair (i < j) with slot-state row `state`. Returns false when the pair carries no
// force; otherwise f = force on body 2 (j) and t_i, t_j the torques as the outputs take them
// (body 1 gets -t_i): the lever arms' moments plus the rolling moment on body 2.
template <class Sink>
inline bool generic_particle_pair_force(const ContactModel& model, const SlotStateLayout& layout,
                                        bool bond_new_contacts, const ParticleArrays& p, const PairTable& pairs,
                                        double dt, double half_dt, Index i, Index j, ContactHistory& h,
                                        double* state, V3& f, V3& t_i, V3& t_j, Sink& sink) {
  const PairGap gap = pair_gap(p, i, j);
  if (!h.touching && gap.apart()) return false;  // candidate, not in contact
  const PairGeometry g = pair_geometry(p, i, j, gap);
  ContactKinematics k = pair_kinematics(g, dt, half_dt, h.normal);
  k.normal_velocity = dot(g.rel_vel, g.n);
  k.rotation_increment = vec((g.wj - g.wi) * dt);
  const PairContext c = particle_pair_context(p, pairs, i, j, dt);
  // The state before the law runs: its stored energy is lost if the contact vanishes this
  // step (evaluated only then).
  const bool was_touching = h.touching != 0;
  SlotRow saved;
  if (was_touching) saved = save_row(h, state, layout.stride);
  const ContactOutcome out = evaluate_contact_generic(model, layout, c, k, h, state, bond_new_contacts);
  if (!out.carries_force) {
    if (was_touching) {
      const ContactEnergy e = vanished_energy(model, layout, c, saved);
      sink.broken(e.normal + e.shear + e.rolling);
    }
    sink.event(out.event);
    return false;
  }
  book_outcome(out, sink);
  book_mechanisms(out, sink);
  f = v3(out.force_on_2);
  t_i = cross(g.arm_i, f);
  t_j = cross(g.arm_j, f);
  if (out.has_moment) {
    t_i = t_i + v3(out.moment_on_2);
    t_j = t_j + v3(out.moment_on_2);
  }
  return true;
}

// Sphere-wall pair (the wall is body 1), as wall_pair_force (engine/wall_pair_force.hpp) with
// the generic law; `torque` includes the rolling moment on the sphere.
template <class Sink>
inline bool generic_wall_pair_force(const ContactModel& model, const SlotStateLayout& layout,
                                    const ParticleArrays& p, const Wall& wall, const PairTable& pairs, double dt,
                                    double half_dt, Index i, ContactHistory& h, double* state, Vec3& force,
                                    Vec3& torque, Sink& sink) {
  const PairContext c = wall_pair_context(p, pairs, i, wall.material, dt);
  const WallContactGeometry g = wall_sphere_geometry(wall, p.position[i], c.radius_2);
  if (!g.in_range || (!h.touching && g.overlap < 0.0)) {
    if (h.touching) {
      const bool handed_on = wall.shape == WallShape::kRectangle;
      const ContactEnergy e = stored_contact_energy(model, layout, c, h, state);
      sink.broken((handed_on ? 0.0 : e.normal) + e.shear + e.rolling);
      h.reset();
      clear_slot_state(state, layout.stride);
    }
    return false;
  }
  Vec3 arm, rel_vel;
  ContactKinematics k = wall_kinematics(p, wall, g, i, dt, half_dt, h.normal, arm, rel_vel);
  k.normal_velocity = rel_vel.dot(k.normal);
  k.rotation_increment = p.angular_velocity[i] * dt;
  // A separation from a wall books nothing for linear springs (their last energy is
  // O((w dt)^2) and went into the motion); the Mindlin spring's |Fs|^2 / (2 kt), kt vanishing
  // with the overlap, is not small: it leaves with the contact (stiffness-change channel).
  const bool mindlin = std::holds_alternative<MindlinTangential>(model.tangential) && h.touching;
  SlotRow saved;
  if (mindlin) saved = save_row(h, state, layout.stride);
  const ContactOutcome out = evaluate_contact_generic(model, layout, c, k, h, state, false);
  if (!out.carries_force) {
    if (mindlin) sink.stiffness_change(vanished_energy(model, layout, c, saved).shear);
    return false;
  }
  sink.slip(out.slip_dissipation);
  book_mechanisms(out, sink);
  force = out.force_on_2;
  torque = arm.cross(force);
  if (out.has_moment) torque += out.moment_on_2;
  return true;
}

}  // namespace colza::detail
