// Normal slot: the normal force from the overlap (compression positive, N). Each law states
// its force, tangent stiffness (time step, servo), the overlap a force means (overlap guard,
// energies), its stored energy, and its per-contact state (physics.md sections 2 and 7).
#pragma once
#include <algorithm>
#include <cmath>
#include "contact/pair_context.hpp"

namespace colza {

// Force of a normal law in one step, and the energy it dissipated in that step (J).
struct NormalResult {
  double force = 0.0;       // Fn (N)
  double dissipated = 0.0;  // J
};

// Linear spring on the total overlap: Fn = Kn un (N), compression positive (physics.md 2).
struct LinearNormal {
  static constexpr const char* kName = "linear";
  static constexpr int kStateDoubles = 0;
  double force(const PairParameters& p, double overlap) const { return p.kn * overlap; }
  // Stored elastic energy 1/2 Fn^2 / Kn (J).
  double energy(const PairParameters& p, double fn) const { return 0.5 * fn * fn / p.kn; }

  NormalResult force(const PairContext& c, double overlap, double*, bool) const { return {c.q.kn * overlap, 0.0}; }
  double tangent_stiffness(const PairContext& c, double, const double*) const { return c.q.kn; }
  double overlap(const PairContext& c, double fn, const double*) const { return fn / c.q.kn; }
  double energy(const PairContext& c, double fn, const double*) const { return energy(c.q, fn); }
};

// Hertz: Fn = 4/3 E* sqrt(R*) un^(3/2) (N), tangent stiffness 2 E* sqrt(R* un) (N/m), stored
// energy 8/15 E* sqrt(R*) un^(5/2) = 2/5 Fn un (J) (Johnson 1985, eq. 4.23; physics.md 7.2).
// A bonded pair in tension (un < 0) is held by the linear spring Kn un of the pair's
// normal_stiffness: Hertz has no tensile branch.
struct HertzNormal {
  static constexpr const char* kName = "hertz";
  static constexpr int kStateDoubles = 0;
  NormalResult force(const PairContext& c, double overlap, double*, bool) const {
    if (overlap < 0.0) return {c.q.kn * overlap, 0.0};
    return {4.0 / 3.0 * c.q.effective_young * std::sqrt(c.effective_radius) * overlap * std::sqrt(overlap), 0.0};
  }
  double tangent_stiffness(const PairContext& c, double overlap, const double*) const {
    if (overlap <= 0.0) return c.q.kn;
    return 2.0 * c.q.effective_young * std::sqrt(c.effective_radius * overlap);
  }
  // un = (3 Fn / (4 E* sqrt(R*)))^(2/3) (m).
  double overlap(const PairContext& c, double fn, const double*) const {
    if (fn <= 0.0) return fn / c.q.kn;
    return std::cbrt(std::pow(3.0 * fn / (4.0 * c.q.effective_young * std::sqrt(c.effective_radius)), 2.0));
  }
  double energy(const PairContext& c, double fn, const double* s) const {
    if (fn <= 0.0) return 0.5 * fn * fn / c.q.kn;
    return 0.4 * fn * overlap(c, fn, s);
  }
};

// Elasto-plastic normal contact (Walton & Braun 1986; Luding 2008, eq. 4 without adhesion):
// loading stiffness k1 = Kn, un- and reloading stiffness k2 = ratio k1 >= k1. The largest
// overlap dmax is kept per contact (state[0], m); plastic overlap d0 = (1 - k1/k2) dmax.
//   loading (un >= dmax): Fn = k1 un;  otherwise Fn = k2 (un - d0), not below 0 unless bonded.
// Stored (recoverable) energy Fn^2 / (2 k2) (J). What loading adds beyond it is dissipated:
// raising dmax from a to b dissipates (1 - k1/k2) k1 (b^2 - a^2) / 2 (J). Head-on
// restitution e = sqrt(k1/k2).
struct WaltonBraunNormal {
  static constexpr const char* kName = "walton_braun";
  static constexpr int kStateDoubles = 1;  // dmax (m); unchanged when the pair's bodies swap
  double unloading_stiffness_ratio = 1.0;  // k2 / k1 (-), >= 1
  NormalResult force(const PairContext& c, double overlap, double* state, bool bonded) const {
    const double k1 = c.q.kn, k2 = unloading_stiffness_ratio * k1;
    double& dmax = state[0];
    if (overlap >= dmax) {
      const double dissipated = (1.0 - k1 / k2) * k1 * 0.5 * (overlap * overlap - dmax * dmax);
      dmax = overlap;
      return {k1 * overlap, dissipated};
    }
    const double fn = k2 * (overlap - plastic_overlap(c, state));
    return {bonded ? fn : std::max(fn, 0.0), 0.0};
  }
  // d0 = (1 - k1/k2) dmax (m).
  double plastic_overlap(const PairContext&, const double* state) const {
    return (1.0 - 1.0 / unloading_stiffness_ratio) * std::max(state[0], 0.0);
  }
  double tangent_stiffness(const PairContext& c, double, const double*) const {
    return unloading_stiffness_ratio * c.q.kn;  // k2 >= k1: the stiffer branch bounds the time step
  }
  double overlap(const PairContext& c, double fn, const double* state) const {
    return fn / (unloading_stiffness_ratio * c.q.kn) + plastic_overlap(c, state);
  }
  double energy(const PairContext& c, double fn, const double*) const {
    return 0.5 * fn * fn / (unloading_stiffness_ratio * c.q.kn);
  }
};

}  // namespace colza
