// Geometry and contact law of one particle pair, scalar reference (physics.md section 2).
// The batched kernel (engine/pair_batch.hpp) computes the same expressions lane by lane and
// falls back to this function for every contact that changes state in the step.
#pragma once
#include <cmath>
#include "contact/contact_law.hpp"
#include "core/materials.hpp"
#include "core/particles.hpp"

namespace colza::detail {

// Plain three-component arithmetic for the pair geometry. Every component is computed with
// the same IEEE operations in the same order as the Eigen expressions of the reference loop
// (element-wise ops; dot = (x0 y0 + x1 y1) + x2 y2; cross as Eigen's OrthoMethods), so the
// results are the same bits; it only avoids Eigen's packet shuffles on 3-vectors under SSE2.
struct V3 {
  double x, y, z;
};
inline V3 v3(const Vec3& v) { return {v[0], v[1], v[2]}; }
inline Vec3 vec(const V3& v) { return Vec3(v.x, v.y, v.z); }
inline V3 operator+(const V3& a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator*(double s, const V3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline V3 operator*(const V3& a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline V3 operator/(const V3& a, double s) { return {a.x / s, a.y / s, a.z / s}; }
inline double dot(const V3& a, const V3& b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }
inline V3 cross(const V3& a, const V3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline void add_to(Vec3& acc, const V3& a) {
  acc[0] += a.x;
  acc[1] += a.y;
  acc[2] += a.z;
}
inline void sub_from(Vec3& acc, const V3& a) {
  acc[0] -= a.x;
  acc[1] -= a.y;
  acc[2] -= a.z;
}

// The centre distance of particle pair (i, j) against its reach: d = x_j - x_i (m),
// dist2 = |d|^2, reach = r_i + r_j (m). The spheres do not overlap when dist2 >= reach^2.
// The one test of "not in contact" for a pair that was not touching: particle_pair_force
// and the batched kernel's quiet chunks (engine/pair_batch.hpp) must agree on it bit for bit.
struct PairGap {
  V3 d;
  double dist2, reach;
  bool apart() const { return dist2 >= reach * reach; }
};
inline PairGap pair_gap(const ParticleArrays& p, Index i, Index j) {
  const V3 d = v3(p.position[j]) - v3(p.position[i]);
  return {d, dot(d, d), p.radius[i] + p.radius[j]};
}

// The contact geometry of particle pair (i < j) found not apart (or touching): normal n from
// i to j, overlap un (m), lever arms from each centre to the contact point (middle of the
// overlap, m), the relative velocity of j against i at that point (m/s) and both spins.
struct PairGeometry {
  V3 n;
  double overlap;
  V3 arm_i, arm_j, rel_vel, wi, wj;
};
[[gnu::always_inline]] inline PairGeometry pair_geometry(const ParticleArrays& p, Index i, Index j,
                                                         const PairGap& gap) {
  PairGeometry g;
  const V3 xi = v3(p.position[i]), xj = v3(p.position[j]);
  const double dist = std::sqrt(gap.dist2);
  g.n = gap.d / dist;
  g.overlap = gap.reach - dist;
  const V3 point = xi + (p.radius[i] - 0.5 * g.overlap) * g.n;  // middle of the overlap
  g.arm_i = point - xi;
  g.arm_j = point - xj;
  g.wi = v3(p.angular_velocity[i]);
  g.wj = v3(p.angular_velocity[j]);
  g.rel_vel = (v3(p.velocity[j]) + cross(g.wj, g.arm_j)) - (v3(p.velocity[i]) + cross(g.wi, g.arm_i));
  return g;
}
// The baseline law's kinematics of that geometry: shear increment (vr - (vr.n) n) dt and the
// twist dt/2 (w1 + w2) . n_old about the previous normal (zero for a new contact).
[[gnu::always_inline]] inline ContactKinematics pair_kinematics(const PairGeometry& g, double dt, double half_dt,
                                                                const Vec3& previous_normal) {
  ContactKinematics k;
  k.normal = vec(g.n);
  k.overlap = g.overlap;
  k.shear_increment = vec((g.rel_vel - dot(g.rel_vel, g.n) * g.n) * dt);
  k.twist_angle = half_dt * dot(g.wi + g.wj, v3(previous_normal));
  return k;
}

// What a pair's outcome books besides its force: the event, the slip, the shear-spring energy
// a bond break released and the normal spring's energy lost with it, in this order.
template <class Sink>
[[gnu::always_inline]] inline void book_outcome(const ContactOutcome& out, Sink& sink) {
  sink.event(out.event);
  sink.slip(out.slip_dissipation);
  sink.released(out.bond_break_energy);
  sink.broken(out.normal_energy_lost);
}

// Geometry and contact law of one particle pair (i < j): the arithmetic of the reference
// force loop, expression for expression. Returns false when the pair carries no force;
// otherwise f = force on body 2 (j), and arm_i, arm_j the lever arms.
template <class Normal, class Tangential, class Bond, class Sink>
[[gnu::always_inline]] inline bool particle_pair_force(const Normal& normal_law, const Tangential& tangential_law,
                                                       const Bond& bond_law, bool bond_new_contacts,
                                                       const ParticleArrays& p, const PairTable& pairs, double dt,
                                                       double half_dt, Index i, Index j, ContactHistory& h, V3& f,
                                                       V3& arm_i, V3& arm_j, Sink& sink) {
  const PairGap gap = pair_gap(p, i, j);
  if (!h.touching && gap.apart()) return false;  // candidate, not in contact
  const PairGeometry g = pair_geometry(p, i, j, gap);
  arm_i = g.arm_i;
  arm_j = g.arm_j;
  const ContactKinematics k = pair_kinematics(g, dt, half_dt, h.normal);
  const PairParameters& q = pairs.particle_particle(p.material[i], p.material[j]);
  // State before the law runs: its stored energy is lost if the contact vanishes this step
  // (evaluated only then; same expression as evaluating it up front).
  const bool was_touching = h.touching != 0;
  const double fn_before = h.normal_force;
  const Vec3 fs_before = h.shear_force;
  const ContactOutcome out = evaluate_contact(normal_law, tangential_law, bond_law, q, k, h, bond_new_contacts);
  if (!out.carries_force) {
    if (was_touching) sink.broken(normal_law.energy(q, fn_before) + tangential_law.energy(q, fs_before));
    sink.event(out.event);
    return false;
  }
  book_outcome(out, sink);
  f = v3(out.force_on_2);
  return true;
}

}  // namespace colza::detail
