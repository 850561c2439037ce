// Viscous contact damping (physics.md section 7.3; contact/damping_laws.hpp ViscousDamping) for
// the SIMD lanes of the batched particle-pair kernel (engine/pair_batch.hpp): the normal and
// tangential dashpots added to the paper's law's force of a contact that was touching at the
// start of the step and keeps its state.
//
// Every line is the generic law's expression (contact/generic_law.hpp, the dashpots after the
// Coulomb cap), with the same IEEE operations in the same order and no FMA contraction
// (-ffp-contract=off), so each lane gives the generic tier's bits.
#pragma once
#include <cmath>

namespace colza::detail {

// The dashpots' damping ratios zeta_n, zeta_t (-).
struct LaneViscousLaw {
  double normal_ratio, tangential_ratio;
};

// One lane: normal n (unit), normal relative velocity vn (m/s), shear increment dus (m), the
// law's elastic normal force Fn (N), its shear force before the Coulomb cap (trial) and after
// (Fs, N; the contact slides where they differ, the generic law's `sliding`), 1 if a bond
// holds else 0, the tangent stiffnesses kn, kt (N/m), m* (kg), mu (-), dt (s), dt > 0 (the
// generic law's tangential dashpot asks for it; the caller's lanes run only then).
struct LaneDashpotContact {
  double nx, ny, nz, vn;
  double sx, sy, sz;
  double fn, trial_x, trial_y, trial_z, fsx, fsy, fsz;
  double bonded;
  double kn, kt, mass, friction, dt;
};

// The force on body 2 with the dashpots, F = Fn_damped n + Fs_damped (N), and the energy
// they dissipated (J).
struct LaneDamped {
  double Fx, Fy, Fz;
  double dissipated;
};

// kDissipation: compute the dissipated energy (false when no energy ledger is kept; it is 0).
template <bool kDissipation>
[[gnu::always_inline]] inline LaneDamped lane_dashpots(const LaneViscousLaw& law, const LaneDashpotContact& c) {
  // Normal dashpot -cn vn, cn = 2 zeta_n sqrt(m* kn) (N s/m); never attractive unless bonded.
  // (std::max(a, 0.0) is (a < 0) ? 0 : a, written out by value: it vectorises.)
  const bool bonded = c.bonded != 0.0;
  const double cn = 2.0 * law.normal_ratio * std::sqrt(c.mass * c.kn);
  const double damped = c.fn - cn * c.vn;
  const bool clamps = !bonded & (damped < 0.0);
  const double fn_damped = clamps ? 0.0 : damped;
  const double normal_work = -(fn_damped - c.fn) * c.vn * c.dt;
  // Tangential dashpot -ct dus / dt, ct = 2 zeta_t sqrt(m* kt) (N s/m), only while the contact
  // sticks; unbonded, the total stays within the Coulomb limit mu max(Fn, 0).
  const double ct = 2.0 * law.tangential_ratio * std::sqrt(c.mass * c.kt);
  const double ax = c.fsx - ct * (c.sx / c.dt), ay = c.fsy - ct * (c.sy / c.dt), az = c.fsz - ct * (c.sz / c.dt);
  const double max_fs = c.friction * (c.fn < 0.0 ? 0.0 : c.fn);
  const double f2 = (ax * ax + ay * ay) + az * az;
  const bool caps = !bonded & (f2 > max_fs * max_fs);
  const double shrink = max_fs / std::sqrt(f2);
  const double cx = caps ? ax * shrink : ax, cy = caps ? ay * shrink : ay, cz = caps ? az * shrink : az;
  const bool sticks = (c.fsx == c.trial_x) & (c.fsy == c.trial_y) & (c.fsz == c.trial_z);
  const double fx = sticks ? cx : c.fsx, fy = sticks ? cy : c.fsy, fz = sticks ? cz : c.fsz;
  LaneDamped out;
  if constexpr (kDissipation) {
    const double tangential_work = ((cx - c.fsx) * c.sx + (cy - c.fsy) * c.sy) + (cz - c.fsz) * c.sz;
    out.dissipated = sticks ? normal_work - tangential_work : normal_work;
  } else {
    out.dissipated = 0.0;
  }
  // Step 6: F = Fn n + Fs with the damped forces.
  out.Fx = fn_damped * c.nx + fx;
  out.Fy = fn_damped * c.ny + fy;
  out.Fz = fn_damped * c.nz + fz;
  return out;
}

}  // namespace colza::detail
