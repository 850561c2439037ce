// The elastic-plastic rolling moment (physics.md section 7.1; contact/rolling_laws.hpp
// ElasticPlasticRolling) for the SIMD lanes of the batched particle-pair kernel
// (engine/pair_batch.hpp): the moment Mr on body 2 of a contact that was touching at the
// start of the step, carried into the new contact frame like the shear force, incremented
// by the bending rotation and capped.
//
// Every line is the generic law's expression (contact/generic_law.hpp with
// ElasticPlasticRolling::update), with the same IEEE operations in the same order and no
// FMA contraction (-ffp-contract=off), so each lane gives the generic tier's bits.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include "contact/rolling_laws.hpp"

namespace colza::detail {

// One lane's inputs: new normal n, previous normal h, twist angle about h (rad), relative
// rotation of the step (w2 - w1) dt (rad), stored moment Mr (N m), rolling stiffness kr
// (N m/rad), moment limit M_max (N m) and the dashpot's Cr / dt (N m/rad; 0 without one).
struct LaneRollingContact {
  double nx, ny, nz;
  double hx, hy, hz, twist;
  double rx, ry, rz;
  double mx, my, mz;
  double kr, limit;
  double dashpot_per_step;
};

// A moment on body 2 (N m) and the energy dissipated making it (J).
struct LaneMoment {
  double mx, my, mz;
  double dissipated;
};
// The spring's new moment (stored), the moment applied (the spring's plus the dashpot's) and
// the energy the cap or the dashpot dissipated (J).
struct LaneRollingStep {
  double mx, my, mz;  // spring, N m
  LaneMoment applied;
};

// kDissipation: compute the cap's energy (false when no energy ledger is kept; it is then 0).
template <bool kDissipation>
[[gnu::always_inline]] inline LaneRollingStep lane_rolling_moment(const LaneRollingContact& c) {
  double mx = c.mx, my = c.my, mz = c.mz;
  // Carried into the new frame: Mr -= Mr x (n_old x n);  Mr -= Mr x (twist n_old).
  {
    const double tx = c.hy * c.nz - c.hz * c.ny, ty = c.hz * c.nx - c.hx * c.nz, tz = c.hx * c.ny - c.hy * c.nx;
    const double cx = my * tz - mz * ty, cy = mz * tx - mx * tz, cz = mx * ty - my * tx;
    mx -= cx;
    my -= cy;
    mz -= cz;
  }
  {
    const double sx = c.twist * c.hx, sy = c.twist * c.hy, sz = c.twist * c.hz;
    const double cx = my * sz - mz * sy, cy = mz * sx - mx * sz, cz = mx * sy - my * sx;
    mx -= cx;
    my -= cy;
    mz -= cz;
  }
  // Mr -= kr dtheta_b, dtheta_b = dtheta - (dtheta . n) n (rad).
  const double along = (c.rx * c.nx + c.ry * c.ny) + c.rz * c.nz;
  const double bx = c.rx - along * c.nx, by = c.ry - along * c.ny, bz = c.rz - along * c.nz;
  mx -= c.kr * bx;
  my -= c.kr * by;
  mz -= c.kr * bz;
  // The cap |Mr| <= M_max, dissipating (Mr_trial - Mr_capped) . Mr_capped / kr (J).
  const double m2 = (mx * mx + my * my) + mz * mz;
  const bool caps = m2 > c.limit * c.limit;
  const double scale = c.limit / std::sqrt(m2);
  LaneRollingStep out;
  out.mx = caps ? mx * scale : mx;
  out.my = caps ? my * scale : my;
  out.mz = caps ? mz * scale : mz;
  // The dashpot while the spring holds: Md = -(Cr / dt) dtheta_b, dissipating
  // (Cr / dt) dtheta_b . dtheta_b (J).
  const bool damps = !caps & (c.dashpot_per_step > 0.0);
  const double dx = c.dashpot_per_step * bx, dy = c.dashpot_per_step * by, dz = c.dashpot_per_step * bz;
  out.applied.mx = damps ? out.mx + -dx : out.mx;
  out.applied.my = damps ? out.my + -dy : out.my;
  out.applied.mz = damps ? out.mz + -dz : out.mz;
  if constexpr (kDissipation) {
    const double capped = (((mx - out.mx) * out.mx + (my - out.my) * out.my) + (mz - out.mz) * out.mz) / c.kr;
    const double damped = (dx * bx + dy * by) + dz * bz;
    out.applied.dissipated = caps ? capped : (damps ? damped : 0.0);
  } else {
    out.applied.dissipated = 0.0;
  }
  return out;
}

// ElasticPlasticRolling's parameters as the lanes take them: beta (-), mu_r (-), 1 when
// the spring has YADE's form, 0 for PFC's (a double: a select on a bool the loop does not
// compute does not vectorise), and eta_r (-).
struct LaneRollingLaw {
  double stiffness_factor, friction;
  double yade_form;
  double damping_ratio;
};
// The dashpot's Cr / dt (N m/rad) at kr (N m/rad), I_r (kg m^2) and dt (s), as
// ElasticPlasticRolling::dashpot_coefficient states Cr.
[[gnu::always_inline]] inline double lane_rolling_dashpot_per_step(const LaneRollingLaw& law, double kr,
                                                                   double rolling_inertia, double dt) {
  return 2.0 * law.damping_ratio * std::sqrt(rolling_inertia * kr) / dt;
}

// kr (N m/rad) and M_max / max(Fn, 0) (m) of a particle pair of radii ri, rj (m) and shear
// stiffness ks (N/m), as ElasticPlasticRolling::stiffness and moment_limit state them.
struct LaneRollingSpring {
  double kr, limit_per_force;
};
[[gnu::always_inline]] inline LaneRollingSpring lane_rolling_spring(const LaneRollingLaw& law, double ks, double ri,
                                                                    double rj) {
  const double effective_radius = ri * rj / (ri + rj);
  const double factor = law.stiffness_factor * ks;
  const bool yade = law.yade_form != 0.0;
  const double kr = yade ? factor * ri * rj : factor * effective_radius * effective_radius;
  const double smaller = rj < ri ? rj : ri;  // std::min(ri, rj)
  const double arm = yade ? smaller : effective_radius;
  return {kr, law.friction * arm};
}

}  // namespace colza::detail
