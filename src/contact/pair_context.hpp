// What every contact-law slot may read about a pair besides its own state: the pair's
// parameters and bodies (PairContext) and the step's contact kinematics (ContactKinematics).
// Geometry is computed once per contact by the caller (engine/pair_force.hpp,
// engine/wall_pair_force.hpp, engine/generic_pair_force.hpp), as in YADE's geometry ->
// physics -> law pipeline.
#pragma once
#include "core/materials.hpp"
#include "core/particles.hpp"
#include "core/types.hpp"

namespace colza {

// The pair, for the slots of the generic law (contact/generic_law.hpp). Sphere-wall: the
// wall is body 1 and both radii are the sphere's, R* = R and m* = m (physics.md section 7).
struct PairContext {
  const PairParameters& q;  // Kn, Ks (N/m), mu (-), E*, G* (Pa)
  double radius_1 = 0.0;    // R1 (m)
  double radius_2 = 0.0;    // R2 (m)
  double effective_radius = 0.0;  // R* = R1 R2 / (R1 + R2) (m)
  double effective_mass = 0.0;    // m* = m1 m2 / (m1 + m2) (kg)
  double dt = 0.0;                // s
  bool with_wall = false;
  // I_r = [1/(I1 + m1 R1^2) + 1/(I2 + m2 R2^2)]^-1 (kg m^2): the pair's inertia for rolling
  // about the contact (Ai et al. 2011, eq. 16); sphere-wall I + m R^2.
  double rolling_inertia = 0.0;
};

// I + m R^2 (kg m^2) of one body rolling about its contact point.
inline double inertia_about_contact(double inertia, double mass, double radius) {
  return inertia + mass * radius * radius;
}
// I_r of two bodies' (kg m^2), a b / (a + b).
inline double pair_rolling_inertia(double about_contact_1, double about_contact_2) {
  return about_contact_1 * about_contact_2 / (about_contact_1 + about_contact_2);
}

// The context of particle pair (i, j): R* = R1 R2 / (R1 + R2), m* = m1 m2 / (m1 + m2), I_r; for
// a particle with itself (the time step's contact of a body that has none) R / 2 and m / 2.
inline PairContext particle_pair_context(const ParticleArrays& p, const PairTable& pairs, Index i, Index j,
                                         double dt) {
  const double ri = p.radius[i], rj = p.radius[j], mi = p.mass[i], mj = p.mass[j];
  return {pairs.particle_particle(p.material[i], p.material[j]),
          ri,
          rj,
          ri * rj / (ri + rj),
          mi * mj / (mi + mj),
          dt,
          false,
          pair_rolling_inertia(inertia_about_contact(p.inertia[i], mi, ri), inertia_about_contact(p.inertia[j], mj, rj))};
}
// The context of particle i against a wall of material `wall_material`: R1 = R2 = R* = R, m* = m,
// I_r = I + m R^2.
inline PairContext wall_pair_context(const ParticleArrays& p, const PairTable& pairs, Index i,
                                     std::size_t wall_material, double dt) {
  const double r = p.radius[i];
  return {pairs.particle_wall(p.material[i], wall_material), r, r, r, p.mass[i], dt, true,
          inertia_about_contact(p.inertia[i], p.mass[i], r)};
}

struct ContactKinematics {
  Vec3 normal;           // unit normal n from body 1 to body 2
  double overlap;        // un = R1 + R2 - |x2 - x1| (sphere-wall: R - distance), > 0 touching (m)
  Vec3 shear_increment;  // dus = (vr - (vr.n) n) dt, vr = velocity of 2 relative to 1 at c (m)
  double twist_angle;    // dt/2 (w1 + w2) . n_old (rad): spin of the pair about the PREVIOUS normal
                         // (YADE ScGeom::precompute computes it before updating the normal)
  // Read by the generic law's slots only (the baseline's paths leave them zero):
  double normal_velocity = 0.0;       // vn = vr . n (m/s), approach negative
  Vec3 rotation_increment = Vec3::Zero();  // (w2 - w1) dt (rad), relative rotation of the step
};

}  // namespace colza
