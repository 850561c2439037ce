// Steps 1-6 of the contact law (physics.md section 2) for one SIMD lane of a batched kernel:
// a contact that was touching at the start of the step, given its geometry this step. The
// particle-pair kernel (engine/pair_batch.hpp) and the wall-pair kernel
// (engine/wall_batch.hpp) compute their own geometry and call this inside their
// `#pragma omp simd` loops (it is always inlined, so it vectorises with them).
//
// Every line is the scalar reference's expression (contact/contact_law.hpp evaluate_contact
// with LinearNormal and CoulombTangential), with the same IEEE operations in the same order
// and no FMA contraction (-ffp-contract=off), so each lane gives the scalar law's bits.
#pragma once
#include <algorithm>
#include <cmath>

namespace colza::detail {

// A lane's geometry this step and its history. Body 1 -> body 2 normal n (unit), overlap
// un (m), shear displacement increment dus (m), twist angle about the previous normal
// (rad), previous normal h and stored shear force fs (N).
struct LaneContact {
  double nx, ny, nz, overlap;
  double sx, sy, sz, twist;
  double hx, hy, hz;
  double fsx, fsy, fsz;
  bool bonded;  // an intact bond joins the pair (always false without bonds)
};

// What the law gives the lane: force on body 2 F = Fn n + Fs (N), the new shear force Fs
// (N), Fn (N, compression positive), slip energy (J), and whether the contact changes state
// this step (falls back to the scalar law from its untouched history).
struct LaneForce {
  double Fx, Fy, Fz;
  double fsx, fsy, fsz;
  double fn, slip;
  bool falls_back;
  double trial_x, trial_y, trial_z;  // Fs before the Coulomb cap (N): the cap slid it where they differ
};

// kn, ks (N/m), mu: the pair's parameters; cn, cs (N): bond strengths (unused without bonds).
// kSlip: compute the slip energy (false when no energy ledger is kept: slip is then 0 and its
// division is skipped; nothing else changes).
// lane_law_of_force: the same with step 1's normal force fn (N) given (a normal law of the
// lanes other than the linear spring).
template <bool kBonds, bool kSlip>
[[gnu::always_inline]] inline LaneForce lane_law_of_force(const LaneContact& c, double fn, double ks, double mu,
                                                          double cn, double cs);
template <bool kBonds, bool kSlip>
[[gnu::always_inline]] inline LaneForce lane_law(const LaneContact& c, double kn, double ks, double mu, double cn,
                                                 double cs) {
  // Step 1: Fn = Kn un (N).
  return lane_law_of_force<kBonds, kSlip>(c, kn * c.overlap, ks, mu, cn, cs);
}
template <bool kBonds, bool kSlip>
[[gnu::always_inline]] inline LaneForce lane_law_of_force(const LaneContact& c, double fn, double ks, double mu,
                                                          double cn, double cs) {
  // Step 2: rotate the stored shear force into the new tangent plane:
  //   Fs -= Fs x (n_old x n);  Fs -= Fs x (twist n_old).
  const double rx = c.hy * c.nz - c.hz * c.ny, ry = c.hz * c.nx - c.hx * c.nz, rz = c.hx * c.ny - c.hy * c.nx;
  double fx = c.fsx, fy = c.fsy, fz = c.fsz;
  {
    const double cx = fy * rz - fz * ry, cy = fz * rx - fx * rz, cz = fx * ry - fy * rx;
    fx -= cx;
    fy -= cy;
    fz -= cz;
  }
  {
    const double tx = c.twist * c.hx, ty = c.twist * c.hy, tz = c.twist * c.hz;
    const double cx = fy * tz - fz * ty, cy = fz * tx - fx * tz, cz = fx * ty - fy * tx;
    fx -= cx;
    fy -= cy;
    fz -= cz;
  }
  // Step 3: trial shear force Fs -= Ks dus (N).
  fx -= ks * c.sx;
  fy -= ks * c.sy;
  fz -= ks * c.sz;
  const double fs2 = (fx * fx + fy * fy) + fz * fz;
  // Steps 4-5: an intact bond holds unless -Fn > Cn or |Fs| > Cs (those lanes fall back);
  // an unbonded contact that lost its overlap falls back (it is removed); otherwise the
  // Coulomb cap |Fs| <= mu max(Fn, 0) with slip energy (F_trial - F).F / Ks (J).
  // (Bitwise & and | instead of && and ||: no branches, so the loop vectorises.)
  const bool bonded = kBonds & c.bonded;
  const bool bond_breaks = (-fn > cn) | (fs2 > cs * cs);
  LaneForce out;
  out.falls_back = (bonded & bond_breaks) | (!bonded & (c.overlap < 0.0));
  const double max_fs = mu * std::max(fn, 0.0);
  const bool slides = !bonded & (fs2 > max_fs * max_fs);
  const double scale = max_fs / std::sqrt(fs2);
  const double cx = slides ? fx * scale : fx, cy = slides ? fy * scale : fy, cz = slides ? fz * scale : fz;
  out.trial_x = fx;
  out.trial_y = fy;
  out.trial_z = fz;
  if constexpr (kSlip)
    out.slip = slides ? (((fx - cx) * cx + (fy - cy) * cy) + (fz - cz) * cz) / ks : 0.0;
  else
    out.slip = 0.0;
  // Step 6: force on body 2, F = Fn n + Fs.
  out.Fx = fn * c.nx + cx;
  out.Fy = fn * c.ny + cy;
  out.Fz = fn * c.nz + cz;
  out.fsx = cx;
  out.fsy = cy;
  out.fsz = cz;
  out.fn = fn;
  return out;
}

}  // namespace colza::detail
