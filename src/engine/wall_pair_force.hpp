// The contact law of one sphere-wall pair (internal to the stepper).
//
// Same law as a particle pair (contact/contact_law.hpp) with the wall as body 1: contact
// point, normal and overlap from walls/wall.hpp; relative velocity at the contact point
// v_rel = v_i + omega_i x arm - v_wall (m/s); shear increment (v_rel - (v_rel . n) n) dt;
// twist angle dt/2 omega_i . n_old (rad). No bond between a sphere and a wall.
#pragma once
#include "contact/contact_law.hpp"
#include "core/materials.hpp"
#include "core/particles.hpp"
#include "walls/wall.hpp"

namespace colza::detail {

// Evaluates wall pair (wall, particle i, history h). Returns true when the pair carries a
// force this step; then `force` is the force on the particle (N) and `torque` its moment
// about the particle's centre (N m). Slip dissipation (J) goes to sink.slip. A pair that
// left the wall's range, or separated, resets its history. A contact that leaves the range
// while touching vanishes with its springs loaded, and sink.broken (the ledger's
// bond_break_lost) gets what is lost: beyond a cylinder's end both springs' energy; beyond a
// rectangle's restricted edge only the shear spring's, since there another surface takes
// the sphere at the same overlap (a coplanar neighbour's face, the edge of a convex corner:
// walls/wall.hpp) and its normal spring carries that energy on. A separation books nothing:
// the overlap closes within a step, and its spring's last O((omega dt)^2) energy went into
// the motion (the energy tests' tolerance).
// The kinematics of sphere i touching a wall at geometry g: normal, overlap, shear
// increment of the sphere's contact point against the wall's velocity, twist about the
// previous normal; `arm` is the lever arm from the sphere's centre to the contact point (m).
[[gnu::always_inline]] inline ContactKinematics wall_kinematics(const ParticleArrays& p, const Wall& wall,
                                                                const WallContactGeometry& g, Index i, double dt,
                                                                double half_dt, const Vec3& previous_normal,
                                                                Vec3& arm, Vec3& rel_vel) {
  ContactKinematics k;
  k.normal = g.normal;
  k.overlap = g.overlap;
  arm = g.point - p.position[i];
  rel_vel = (p.velocity[i] + p.angular_velocity[i].cross(arm)) - wall.velocity;
  k.shear_increment = (rel_vel - rel_vel.dot(k.normal) * k.normal) * dt;
  k.twist_angle = half_dt * p.angular_velocity[i].dot(previous_normal);
  return k;
}

template <class Normal, class Tangential, class Sink>
[[gnu::always_inline]] inline bool wall_pair_force(const Normal& normal_law, const Tangential& tangential_law,
                                                   const ParticleArrays& p, const Wall& wall, const PairTable& pairs,
                                                   double dt, double half_dt, Index i, ContactHistory& h,
                                                   Vec3& force, Vec3& torque, Sink& sink) {
  const WallContactGeometry g = wall_sphere_geometry(wall, p.position[i], p.radius[i]);
  if (!g.in_range || (!h.touching && g.overlap < 0.0)) {
    if (h.touching) {
      const PairParameters& q = pairs.particle_wall(p.material[i], wall.material);
      const bool handed_on = wall.shape == WallShape::kRectangle;
      sink.broken((handed_on ? 0.0 : normal_law.energy(q, h.normal_force)) + tangential_law.energy(q, h.shear_force));
      h.reset();
    }
    return false;
  }
  Vec3 arm, rel_vel;
  const ContactKinematics k = wall_kinematics(p, wall, g, i, dt, half_dt, h.normal, arm, rel_vel);
  const PairParameters& q = pairs.particle_wall(p.material[i], wall.material);
  const ContactOutcome out = evaluate_contact(normal_law, tangential_law, NoBond{}, q, k, h, false);
  if (!out.carries_force) return false;  // separated: its springs' last energy went into the motion
  sink.slip(out.slip_dissipation);
  force = out.force_on_2;
  torque = arm.cross(force);
  return true;
}

}  // namespace colza::detail
