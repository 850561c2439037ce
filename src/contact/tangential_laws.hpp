// Tangential slot: the incremental shear spring and its sliding limit (physics.md sections
// 2 and 7.2). Fs is the shear force on body 2, carried in the tangent plane by the caller.
#pragma once
#include <algorithm>
#include <cmath>
#include "contact/pair_context.hpp"

namespace colza {

// The Coulomb cap |Fs| <= mu max(Fn, 0) for a spring of stiffness kt (N/m): scales fs onto
// the limit if it exceeds it and returns the energy the slip dissipated,
// (F_trial - F_capped) . F_capped / kt (J) (YADE's bookkeeping).
inline double coulomb_cap(double friction, double kt, double fn, Vec3& fs) {
  const double max_fs = friction * std::max(fn, 0.0);
  const double fs2 = fs.squaredNorm();
  if (fs2 <= max_fs * max_fs) return 0.0;
  const Vec3 trial = fs;
  fs *= max_fs / std::sqrt(fs2);
  return (trial - fs).dot(fs) / kt;
}

// Incremental linear shear spring, Fs <- Fs - Ks dus, capped at the Coulomb limit
// |Fs| <= mu max(Fn, 0) (Cundall & Strack 1979; PFC3D linear model; YADE CundallStrack).
struct CoulombTangential {
  static constexpr const char* kName = "coulomb";
  static constexpr int kStateDoubles = 0;
  void increment(const PairParameters& p, Vec3& fs, const Vec3& shear_increment) const {
    fs -= p.ks * shear_increment;
  }
  // Scales fs onto the Coulomb limit if it exceeds it. Returns the energy dissipated by
  // the slip, (F_trial - F_capped) . F_capped / Ks (J) (same bookkeeping as YADE).
  double limit(const PairParameters& p, double fn, Vec3& fs) const {
    const double max_fs = p.friction * std::max(fn, 0.0);
    const double fs2 = fs.squaredNorm();
    if (fs2 <= max_fs * max_fs) return 0.0;
    const Vec3 trial = fs;
    fs *= max_fs / std::sqrt(fs2);
    return (trial - fs).dot(fs) / p.ks;
  }
  double energy(const PairParameters& p, const Vec3& fs) const { return 0.5 * fs.squaredNorm() / p.ks; }
  // Energy that leaves the shear spring in a step whose force goes from `carried` (the
  // previous force, carried into the new tangent plane) through `trial` to `capped` (J):
  //   D = (F_carried + F_capped) . (F_trial - F_capped) / (2 Ks).
  // It is the work of the applied forces over the step (trapezoid, as leapfrog integrates
  // it) minus the change of stored energy; in steady sliding it equals F delta. Used for the
  // drop of a shear bond break, where Fs falls from about Cs to mu Fn in one step.
  double released(const PairParameters& p, const Vec3& carried, const Vec3& trial, const Vec3& capped) const {
    return (carried + capped).dot(trial - capped) / (2.0 * p.ks);
  }

  // The generic law's interface: the spring's stiffness at this overlap (N/m).
  double stiffness(const PairContext& c, double) const { return c.q.ks; }
};

// No-slip Mindlin shear spring (Mindlin 1949; YADE Law2_ScGeom_MindlinPhys_Mindlin; LIGGGHTS
// tangential history with Hertz): kt = 8 G* sqrt(R* un) (N/m), incremental Fs <- Fs - kt dus
// with kt at this step's overlap, Coulomb cap as the linear law's (physics.md 7.2). Stored
// energy |Fs|^2 / (2 kt) (J). A bonded pair in tension (un <= 0) keeps the linear Ks. State:
// the last step's kt (N/m; unchanged when the bodies swap), for the energy and its change.
struct MindlinTangential {
  static constexpr const char* kName = "mindlin";
  static constexpr int kStateDoubles = 1;
  double stiffness(const PairContext& c, double overlap) const {
    if (overlap <= 0.0) return c.q.ks;
    return 8.0 * c.q.effective_shear * std::sqrt(c.effective_radius * overlap);
  }
};

// The generic law's use of a tangential slot (contact/generic_law.hpp): energy of the spring
// |Fs|^2 / (2 kt) (J) and the release of a shear bond break, as CoulombTangential states them.
inline double shear_spring_energy(double kt, const Vec3& fs) { return 0.5 * fs.squaredNorm() / kt; }
inline double shear_spring_released(double kt, const Vec3& carried, const Vec3& trial, const Vec3& capped) {
  return (carried + capped).dot(trial - capped) / (2.0 * kt);
}

}  // namespace colza
