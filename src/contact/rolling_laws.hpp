// Rolling slot: a moment at the contact that resists the bending part of the relative
// rotation (physics.md section 7.1).
#pragma once
#include <algorithm>
#include <cmath>
#include "contact/pair_context.hpp"

namespace colza {

struct NoRolling {
  static constexpr const char* kName = "none";
  static constexpr int kStateDoubles = 0;
};

// Which radii the rolling spring and its cap take.
enum class RollingForm {
  kYade,  // kr = beta Ks R1 R2, cap mu_r min(R1, R2) max(Fn, 0) (YADE CohFrictPhys, alphaKr / etaRoll)
  kPfc,   // kr = beta Ks R*^2,  cap mu_r R* max(Fn, 0)          (PFC3D `rrlinear`)
};
const char* to_string(RollingForm form);

// What a step of the rolling law gives besides the spring's new moment: the dashpot's moment
// on body 2 (N m; body 1 gets its opposite) and the energy the cap and the dashpot
// dissipated (J).
struct RollingStep {
  Vec3 dashpot_moment = Vec3::Zero();
  double dissipated = 0.0;
};

// Elastic-plastic rolling spring with its dashpot (type C of Ai et al. 2011, Powder Technol.
// 206:269, eqs. 12-16; the spring alone is YADE's
// Law2_ScGeom6D_CohFrictPhys_CohesionMoment, useIncrementalForm). The spring's moment on
// body 2, Mr (N m, state[0..2]), is carried into the new contact frame like the shear force,
// then
//   Mr <- Mr - kr dtheta_b,  dtheta_b = (w_r - (w_r . n) n) dt,  w_r = w2 - w1 (rad),
// and capped at |Mr| <= M_max; body 1 gets -Mr. Stored energy |Mr|^2 / (2 kr) (J); the cap
// dissipates (Mr_trial - Mr_capped) . Mr_capped / kr (J), as the Coulomb cap does.
// The dashpot, while the spring holds (Ai et al.'s f = 0 once the moment is at its cap, as
// the tangential dashpot acts only while the contact sticks):
//   Md = -Cr dtheta_b / dt,  Cr = 2 eta_r sqrt(I_r kr) (N m s/rad),
//   I_r = [1/(I1 + m1 R1^2) + 1/(I2 + m2 R2^2)]^-1 (kg m^2, PairContext::rolling_inertia),
// dissipating Md . (-dtheta_b) = Cr |dtheta_b|^2 / dt (J) a step. Under local damping the
// spin's damping stands in for it; under viscous contact damping alone a sphere would rock
// on its spring undamped (the contact dashpots see no velocity in rolling without slip).
struct ElasticPlasticRolling {
  static constexpr const char* kName = "elastic_plastic";
  static constexpr int kStateDoubles = 3;  // Mr on body 2: changes sign when the bodies swap
  double stiffness_factor = 0.0;  // beta (-)
  double friction = 0.0;          // mu_r (-)
  RollingForm form = RollingForm::kYade;
  bool at_walls = false;  // also at sphere-wall contacts (R1 = R2 = R* = the sphere's radius)
  double damping_ratio = 0.0;  // eta_r (-), the dashpot's share of its critical 2 sqrt(I_r kr)

  bool acts(const PairContext& c) const { return !c.with_wall || at_walls; }
  // kr (N m / rad).
  double stiffness(const PairContext& c) const {
    if (form == RollingForm::kYade) return stiffness_factor * c.q.ks * c.radius_1 * c.radius_2;
    return stiffness_factor * c.q.ks * c.effective_radius * c.effective_radius;
  }
  // M_max (N m) at normal force fn (N).
  double moment_limit(const PairContext& c, double fn) const {
    const double arm = form == RollingForm::kYade ? std::min(c.radius_1, c.radius_2) : c.effective_radius;
    return friction * arm * std::max(fn, 0.0);
  }
  // Cr (N m s/rad) at spring stiffness kr (N m/rad).
  double dashpot_coefficient(const PairContext& c, double kr) const {
    return 2.0 * damping_ratio * std::sqrt(c.rolling_inertia * kr);
  }
  // Adds the step's increment to the carried moment `mr` and caps it; the dashpot's moment
  // while it holds, and the energy the cap or the dashpot dissipated (J).
  RollingStep update(const PairContext& c, const Vec3& normal, const Vec3& rotation_increment, double fn,
                     Vec3& mr) const {
    const double kr = stiffness(c);
    const Vec3 bending = rotation_increment - rotation_increment.dot(normal) * normal;
    mr -= kr * bending;
    const double limit = moment_limit(c, fn);
    const double m2 = mr.squaredNorm();
    RollingStep step;
    if (m2 <= limit * limit) {
      if (damping_ratio > 0.0 && c.dt > 0.0) {
        const Vec3 rate = (dashpot_coefficient(c, kr) / c.dt) * bending;
        step.dashpot_moment = -rate;
        step.dissipated = rate.dot(bending);
      }
      return step;
    }
    const Vec3 trial = mr;
    mr *= limit / std::sqrt(m2);
    step.dissipated = (trial - mr).dot(mr) / kr;
    return step;
  }
  double energy(const PairContext& c, const Vec3& mr) const {
    const double kr = stiffness(c);
    return kr > 0.0 ? 0.5 * mr.squaredNorm() / kr : 0.0;
  }
};

}  // namespace colza
