// Batched particle-pair kernel: the contact law of physics.md section 2 for contacts that
// persist through the step, computed lane by lane over small structure-of-arrays batches
// (`#pragma omp simd`: one contact per SIMD lane; with AVX-512, eight at once).
//
// Why: the scalar loop is latency-bound (sqrt, three divisions, the tangent-plane rotation and
// the Coulomb cap form one long dependency chain per contact); lanes run those chains side by
// side. The lane arithmetic is the scalar reference (engine/pair_force.hpp) expression for
// expression, with the same IEEE operations in the same order and no contraction into FMA
// (-ffp-contract=off, see CMakeLists.txt), so every lane gives the bits the scalar function
// gives. Lanes take the contacts that were touching at the start of the step; a candidate
// pair that was not (it becomes a new contact if the spheres overlap now) and any contact
// that changes state this step (a separation, a bond break) go through the scalar function
// from their untouched history. Results are consumed in pair order, so the per-particle
// sums are those of the reference loop.
//
// Most chunks of pairs are quiet: no lane changes state and no candidate that was apart at
// the start of the step overlaps now. Their lanes are then consumed straight in lane order, which is their
// pair order, and the other candidates carry no force (the scalar function would return at
// its first test). Filling the chunk and testing it are branch-free; the pair-by-pair merge
// of lanes and scalar pairs (its branches follow the contact pattern and mispredict) is left
// to the chunks that are not quiet.
//
// Used for the built-in slot combination (LinearNormal, CoulombTangential, NoBond or
// ContactBond) with one particle material, and for that combination with one mechanism of the
// generic tier, the elastic-plastic rolling moment or viscous dashpots (engine/rolling_lanes.hpp,
// engine/viscous_lanes.hpp; the generic law for the pairs that are not steady lanes); anything
// else takes the scalar loop.
#pragma once
#include <cmath>
#include <type_traits>
#include "engine/batch_driver.hpp"
#include "engine/lane_law.hpp"
#include "engine/lane_transpose.hpp"
#include "engine/pair_force.hpp"

namespace colza::detail {

// The slot combinations the lanes compute (lane_law.hpp hard-codes the linear spring, the
// Coulomb cap and the contact bond's rule: an intact bond has no friction cap and breaks at Cn
// or Cs). A new alternative in any slot is false here and takes the scalar loop until it gets
// lanes of its own; ForcePaths compares the two bit for bit.
template <class Normal, class Tangential, class Bond = NoBond>
inline constexpr bool kHasBatchedKernel =
    std::is_same_v<Normal, LinearNormal> && std::is_same_v<Tangential, CoulombTangential> &&
    (std::is_same_v<Bond, NoBond> || std::is_same_v<Bond, ContactBond>);

// Inputs and outputs of up to kLanes contacts (pairs touching at the start of the step), one
// array per component, and up to kLanes candidates of the same chunk whose spheres were
// apart. `note_lane` records a contact's pair, bodies, radii and bond flag; `fill_lanes`
// then copies the bodies' states and the histories of all the batch's lanes
// (engine/lane_transpose.hpp).
struct PairBatch {
  static constexpr int kLanes = 32;
  int count = 0;                         // lanes
  std::size_t pair[kLanes];              // candidate-pair index of each lane, increasing
  Index body_i[kLanes], body_j[kLanes];  // its bodies 1 and 2
  int apart = 0;                         // candidates apart at the start of the step
  std::size_t apart_pair[kLanes];        // their pair indices, increasing
  Index apart_i[kLanes], apart_j[kLanes];
  // inputs: body states and history (previous shear force and normal)
  alignas(64) double xi[3][kLanes], xj[3][kLanes], vi[3][kLanes], vj[3][kLanes], wi[3][kLanes], wj[3][kLanes];
  alignas(64) double ri[kLanes], rj[kLanes], bonded[kLanes];
  alignas(64) double fs[3][kLanes], prev_normal[3][kLanes];
  // outputs: new normal, Fn, new shear force, force on body 2, torques, slip energy
  alignas(64) double normal[3][kLanes], fn[kLanes], fs_new[3][kLanes], f[3][kLanes];
  alignas(64) double torque_i[3][kLanes], torque_j[3][kLanes], slip[kLanes];
  alignas(64) double fallback[kLanes];  // 1: the contact changes state, recompute with the scalar law
};

// Records candidate pair c (bodies i, j) in lane l.
[[gnu::always_inline]] inline void note_lane(PairBatch& b, int l, const double* radius, std::size_t c, Index i,
                                             Index j, const ContactHistory& h) {
  b.pair[l] = c;
  b.body_i[l] = i;
  b.body_j[l] = j;
  b.ri[l] = radius[i];
  b.rj[l] = radius[j];
  b.bonded[l] = h.bonded ? 1.0 : 0.0;
}

// Notes the candidate pairs from c on, until the batch's lanes or its apart list are full
// (so a chunk has at most 2 kLanes - 1 pairs) or the range ends: a pair touching at the start
// of the step into the next lane, any other into the apart list. Branch-free: every pair is
// written to both next slots, and only the slot it belongs to advances. Returns the end of
// the chunk.
[[gnu::always_inline]] inline std::size_t note_chunk(PairBatch& b, const double* radius, const Index* first,
                                                     const Index* second, const ContactHistory* history,
                                                     std::size_t c, std::size_t end) {
  int count = 0, apart = 0;
  for (; c < end && count < PairBatch::kLanes && apart < PairBatch::kLanes; ++c) {
    const int touching = history[c].touching != 0;
    note_lane(b, count, radius, c, first[c], second[c], history[c]);
    b.apart_pair[apart] = c;
    b.apart_i[apart] = first[c];
    b.apart_j[apart] = second[c];
    count += touching;
    apart += 1 - touching;
  }
  b.count = count;
  b.apart = apart;
  return c;
}

// Whether the chunk is quiet: no lane changes state, and every candidate that was apart is
// still apart (the scalar function's own test, pair_gap in engine/pair_force.hpp).
inline bool quiet_chunk(const PairBatch& b, const ParticleArrays& p) {
  bool quiet = true;
  for (int l = 0; l < b.count; ++l) quiet &= b.fallback[l] == 0.0;
  for (int k = 0; k < b.apart; ++k) quiet &= pair_gap(p, b.apart_i[k], b.apart_j[k]).apart();
  return quiet;
}

// The noted lanes' body states (positions, velocities, angular velocities of bodies 1 and 2)
// and histories (stored shear force, previous normal), four lanes at a time.
inline void fill_lanes(PairBatch& b, const ParticleArrays& p, const ContactHistory* history) {
  pad_last_lane_group(b.count, b.pair, b.body_i, b.body_j);
  for (int l = 0; l < b.count; l += kLaneGroup) {
    bodies_to_lanes(p.position, b.body_i, b.xi, l);
    bodies_to_lanes(p.position, b.body_j, b.xj, l);
    bodies_to_lanes(p.velocity, b.body_i, b.vi, l);
    bodies_to_lanes(p.velocity, b.body_j, b.vj, l);
    bodies_to_lanes(p.angular_velocity, b.body_i, b.wi, l);
    bodies_to_lanes(p.angular_velocity, b.body_j, b.wj, l);
    histories_to_lanes(b, history, l);
  }
}

// What the lanes compute besides the paper's law: a mechanism of the generic tier computed lane
// by lane (RollingLanes, engine/rolling_lanes.hpp; ViscousLanes, engine/viscous_lanes.hpp), or
// nothing. A mechanism states kMoment (a moment on body 2 added to both torques: lane()),
// kDashpots (the force replaced by the damped one: damp()), kNormal (the normal force in
// place of the linear spring's: normal_force()) or kBondStrengths (each lane's bond strengths
// in place of the contact bond's, and whether its bond forms now, which makes it fall back:
// bond_strengths()), its invariant parameters `law`,
// and how it fills its columns (fill), keeps a steady lane's state (keep) and books its
// energy (book).
struct NoLaneMechanism {
  static constexpr bool kMoment = false;
  static constexpr bool kDashpots = false;
  static constexpr bool kNormal = false;
  static constexpr bool kBondStrengths = false;
  struct {
  } law;
  template <class Batch>
  void fill(const Batch&, const ParticleArrays&) {}
  void keep(std::size_t, int) {}
  template <class Sink>
  void book(Sink&, int) const {}
};

// The law for every lane (physics.md section 2, steps 1-6, for a contact that existed at the
// start of the step), with the pair parameters q of the one particle material: the pair
// geometry here, the law in lane_law.hpp, and the `mechanism`'s (NoLaneMechanism above). Each
// line is the scalar reference's expression; see pair_force.hpp, contact_law.hpp and
// generic_law.hpp for the physics.
template <class Bond, bool kSlip, class Mechanism>
inline void compute_lanes(PairBatch& b, const Bond& bond, const PairParameters& q, double dt, double half_dt,
                          Mechanism& mechanism) {
  static_assert(std::is_same_v<Bond, NoBond> || std::is_same_v<Bond, ContactBond>,
                "the lanes compute the contact bond's rule only (kHasBatchedKernel)");
  constexpr bool kBonds = std::is_same_v<Bond, ContactBond>;
  double cn = 0.0, cs = 0.0;
  if constexpr (kBonds) {
    cn = bond.normal_strength;
    cs = bond.shear_strength;
  }
  const double kn = q.kn, ks = q.ks, mu = q.friction;
  const int count = b.count;
  [[maybe_unused]] const auto mechanism_law = mechanism.law;
#pragma omp simd
  for (int l = 0; l < count; ++l) {
    // Geometry: normal n from 1 to 2, overlap un, contact point in the middle of the overlap.
    const double dx = b.xj[0][l] - b.xi[0][l], dy = b.xj[1][l] - b.xi[1][l], dz = b.xj[2][l] - b.xi[2][l];
    const double dist2 = (dx * dx + dy * dy) + dz * dz;
    const double dist = std::sqrt(dist2);
    const double nx = dx / dist, ny = dy / dist, nz = dz / dist;
    const double overlap = (b.ri[l] + b.rj[l]) - dist;
    const double centre_offset = b.ri[l] - 0.5 * overlap;
    const double px = b.xi[0][l] + centre_offset * nx, py = b.xi[1][l] + centre_offset * ny,
                 pz = b.xi[2][l] + centre_offset * nz;
    const double aix = px - b.xi[0][l], aiy = py - b.xi[1][l], aiz = pz - b.xi[2][l];  // arm of body 1
    const double ajx = px - b.xj[0][l], ajy = py - b.xj[1][l], ajz = pz - b.xj[2][l];  // arm of body 2
    // Relative velocity of 2 with respect to 1 at the contact point: (vj + wj x aj) - (vi + wi x ai).
    const double wix = b.wi[0][l], wiy = b.wi[1][l], wiz = b.wi[2][l];
    const double wjx = b.wj[0][l], wjy = b.wj[1][l], wjz = b.wj[2][l];
    const double rvx = (b.vj[0][l] + (wjy * ajz - wjz * ajy)) - (b.vi[0][l] + (wiy * aiz - wiz * aiy));
    const double rvy = (b.vj[1][l] + (wjz * ajx - wjx * ajz)) - (b.vi[1][l] + (wiz * aix - wix * aiz));
    const double rvz = (b.vj[2][l] + (wjx * ajy - wjy * ajx)) - (b.vi[2][l] + (wix * aiy - wiy * aix));
    // Shear displacement increment dus = (vr - (vr.n) n) dt (m).
    const double vn = (rvx * nx + rvy * ny) + rvz * nz;
    const double sx = (rvx - vn * nx) * dt, sy = (rvy - vn * ny) * dt, sz = (rvz - vn * nz) * dt;
    // Twist about the previous normal: dt/2 (w1 + w2) . n_old (rad).
    const double hx = b.prev_normal[0][l], hy = b.prev_normal[1][l], hz = b.prev_normal[2][l];
    const double twist = half_dt * (((wix + wjx) * hx + (wiy + wjy) * hy) + (wiz + wjz) * hz);
    const LaneContact contact{nx, ny, nz, overlap, sx, sy, sz, twist, hx, hy, hz,
                              b.fs[0][l], b.fs[1][l], b.fs[2][l], b.bonded[l] != 0.0};
    // Step 1's normal force: the linear spring Kn un, or the mechanism's normal law.
    double fn = kn * overlap;
    if constexpr (Mechanism::kNormal)
      fn = mechanism.normal_force(l, mechanism_law, overlap, kn, kBonds ? b.bonded[l] : 0.0);
    double lane_cn = cn, lane_cs = cs, bond_forms = 0.0;
    if constexpr (Mechanism::kBondStrengths) {
      const auto strengths = mechanism.bond_strengths(l, mechanism_law, fn);
      lane_cn = strengths.normal;
      lane_cs = strengths.shear;
      bond_forms = strengths.forms;
    }
    LaneForce r = lane_law_of_force<kBonds, kSlip>(contact, fn, ks, mu, lane_cn, lane_cs);
    b.slip[l] = r.slip;
    b.fallback[l] = r.falls_back ? 1.0 : bond_forms;
    if constexpr (Mechanism::kDashpots) {
      const auto d = mechanism.template damp<kSlip>(l, mechanism_law, nx, ny, nz, vn, sx, sy, sz, r.fn, r.trial_x,
                                                    r.trial_y, r.trial_z, r.fsx, r.fsy, r.fsz,
                                                    kBonds ? b.bonded[l] : 0.0, kn, ks, mu, dt);
      r.Fx = d.Fx;
      r.Fy = d.Fy;
      r.Fz = d.Fz;
    }
    // Torques arm x F of the force on body 2, plus the moment on body 2 (body 1 gets the
    // opposite of both).
    const double Fx = r.Fx, Fy = r.Fy, Fz = r.Fz;
    double tix = aiy * Fz - aiz * Fy, tiy = aiz * Fx - aix * Fz, tiz = aix * Fy - aiy * Fx;
    double tjx = ajy * Fz - ajz * Fy, tjy = ajz * Fx - ajx * Fz, tjz = ajx * Fy - ajy * Fx;
    if constexpr (Mechanism::kMoment) {
      // Relative rotation of the step (w2 - w1) dt (rad).
      const auto m = mechanism.template lane<kSlip>(l, mechanism_law, nx, ny, nz, hx, hy, hz, twist, (wjx - wix) * dt,
                                                        (wjy - wiy) * dt, (wjz - wiz) * dt, b.ri[l], b.rj[l], r.fn,
                                                        ks, dt);
      tix = tix + m.mx;
      tiy = tiy + m.my;
      tiz = tiz + m.mz;
      tjx = tjx + m.mx;
      tjy = tjy + m.my;
      tjz = tjz + m.mz;
    }
    b.torque_i[0][l] = tix;
    b.torque_i[1][l] = tiy;
    b.torque_i[2][l] = tiz;
    b.torque_j[0][l] = tjx;
    b.torque_j[1][l] = tjy;
    b.torque_j[2][l] = tjz;
    store_lane_force(b, l, r, nx, ny, nz);
  }
}
// The paper's law alone in the lanes.
template <class Bond, bool kSlip>
inline void compute_lanes(PairBatch& b, const Bond& bond, const PairParameters& q, double dt, double half_dt) {
  NoLaneMechanism none;
  compute_lanes<Bond, kSlip>(b, bond, q, dt, half_dt, none);
}

// Particle pairs [begin, end) through the batched kernel, with the lanes' `mechanism`
// (NoLaneMechanism, RollingLanes or ViscousLanes). `out.carries(c, i, j, f, t_i, t_j)`
// receives, in pair order, the force f on body 2 (body 1 gets -f) and the torques t_i, t_j
// (arm_i x f and arm_j x f plus the moment on body 2; body 1 gets -t_i); `out.none(c)` each
// pair without force (in a quiet chunk after the chunk's carrying pairs, so it must touch
// nothing that carries() adds to). A pair that is not a steady lane goes to
// `scalar_pair(c, f, t_i, t_j)`, the scalar law from its untouched history, which returns
// whether it carries force. Requires one particle material (the caller checks).
template <class Bond, class Mechanism, class ScalarPair, class Out, class Sink>
[[gnu::always_inline]] inline void particle_pairs_in_lanes(const Bond& bond_law, Mechanism& mechanism,
                                                           ScalarPair&& scalar_pair, const ParticleArrays& p,
                                                           const PairTable& pairs, double dt, double half_dt,
                                                           const Index* first, const Index* second,
                                                           ContactHistory* history, std::size_t begin,
                                                           std::size_t end, Out& out, Sink& sink) {
  const PairParameters& q = pairs.particle_particle(0, 0);
  PairBatch b;
  const auto steady = [&](std::size_t k, int l) {  // steady contact: the lane's result
    keep_lane_history(history[k], b, l);
    sink.slip(b.slip[l]);
    mechanism.keep(k, l);
    mechanism.book(sink, l);
    out.carries(k, first[k], second[k], V3{b.f[0][l], b.f[1][l], b.f[2][l]},
                V3{b.torque_i[0][l], b.torque_i[1][l], b.torque_i[2][l]},
                V3{b.torque_j[0][l], b.torque_j[1][l], b.torque_j[2][l]});
  };
  const auto scalar = [&](std::size_t k) {  // a new contact if the spheres overlap now, or a change of state
    V3 f, t_i, t_j;
    if (scalar_pair(k, f, t_i, t_j))
      out.carries(k, first[k], second[k], f, t_i, t_j);
    else
      out.none(k);
  };
  std::size_t c = begin;
  while (c < end) {
    const std::size_t chunk_begin = c;
    c = note_chunk(b, p.radius.data(), first, second, history, c, end);
    fill_lanes(b, p, history);
    mechanism.fill(b, p);
    compute_lanes<Bond, Sink::kKeepsSlip>(b, bond_law, q, dt, half_dt, mechanism);
    if (!quiet_chunk(b, p)) {
      consume_in_pair_order(b, chunk_begin, c, steady, scalar);
      continue;
    }
    for (int l = 0; l < b.count; ++l) steady(b.pair[l], l);
    for (int k = 0; k < b.apart; ++k) out.none(b.apart_pair[k]);
  }
}

// The paper's law (linear, Coulomb, `bond_law`) through the batched kernel; the scalar
// reference (particle_pair_force) for the pairs that are not steady lanes.
template <class Normal, class Tangential, class Bond, class Out, class Sink>
[[gnu::always_inline]] inline void particle_pairs_batched(const Normal& normal_law, const Tangential& tangential_law,
                                                          const Bond& bond_law, bool bond_new_contacts,
                                                          const ParticleArrays& p, const PairTable& pairs, double dt,
                                                          double half_dt, const Index* first, const Index* second,
                                                          ContactHistory* history, std::size_t begin, std::size_t end,
                                                          Out& out, Sink& sink) {
  NoLaneMechanism none;
  const auto scalar_pair = [&](std::size_t k, V3& f, V3& t_i, V3& t_j) {
    V3 arm_i, arm_j;
    if (!particle_pair_force(normal_law, tangential_law, bond_law, bond_new_contacts, p, pairs, dt, half_dt,
                             first[k], second[k], history[k], f, arm_i, arm_j, sink))
      return false;
    t_i = cross(arm_i, f);
    t_j = cross(arm_j, f);
    return true;
  };
  particle_pairs_in_lanes(bond_law, none, scalar_pair, p, pairs, dt, half_dt, first, second, history, begin, end,
                          out, sink);
}

}  // namespace colza::detail
