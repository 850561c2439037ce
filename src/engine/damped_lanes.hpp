// Viscous contact damping together with one other lane mechanism (the elastic-plastic rolling
// moment, the Walton-Braun normal law or load-induced cohesion) in the batched particle-pair
// kernel (engine/pair_batch.hpp): the other mechanism's normal force, bond strengths or
// moment as its own lanes compute them, and the dashpots of engine/viscous_lanes.hpp on the
// resulting force. The normal dashpot's stiffness is the normal law's tangent stiffness, as
// the generic law takes it (contact/generic_law.hpp; physics.md 7.3): Kn for the linear law,
// k2 = (k2/k1) Kn for Walton-Braun (NormalLaw::tangent_stiffness). The rolling moment's cap
// reads the spring's normal force, not the damped one, as the generic law's does. So each
// lane gives the generic tier's bits; lanes that change state take the generic law.
#pragma once
#include <cstddef>
#include "core/particles.hpp"
#include "engine/lane_rolling.hpp"
#include "engine/viscous_lanes.hpp"
#include "engine/walton_braun_lanes.hpp"

namespace colza::detail {

// The normal dashpot's stiffness (N/m) with the other mechanism's normal law: Kn unless it
// replaces the linear spring.
template <class InnerLaw>
[[gnu::always_inline]] inline double dashpot_normal_stiffness(const InnerLaw&, double kn) {
  return kn;
}
[[gnu::always_inline]] inline double dashpot_normal_stiffness(const LaneWaltonBraunLaw& walton_braun, double kn) {
  return walton_braun.unloading_stiffness_ratio * kn;  // WaltonBraunNormal::tangent_stiffness
}

template <int kLanes, class Inner>
struct DampedLanes {
  static constexpr bool kMoment = Inner::kMoment;
  static constexpr bool kDashpots = true;
  static constexpr bool kNormal = Inner::kNormal;
  static constexpr bool kBondStrengths = Inner::kBondStrengths;
  static_assert(!Inner::kDashpots, "one set of dashpots");
  using InnerLaw = decltype(Inner::law);
  struct Law {
    LaneViscousLaw viscous;
    InnerLaw inner;
  };
  ViscousLanes<kLanes> dashpots;
  Inner inner;
  Law law;

  DampedLanes(ViscousLanes<kLanes> viscous, Inner other)
      : dashpots(viscous), inner(other), law{dashpots.law, inner.law} {}

  template <class Batch>
  void fill(const Batch& b, const ParticleArrays& p) {
    dashpots.fill(b, p);
    inner.fill(b, p);
  }
  [[gnu::always_inline]] double normal_force(int l, const Law& both, double overlap, double kn, double bonded) {
    return inner.normal_force(l, both.inner, overlap, kn, bonded);
  }
  [[gnu::always_inline]] auto bond_strengths(int l, const Law& both, double fn) {
    return inner.bond_strengths(l, both.inner, fn);
  }
  template <bool kDissipation>
  [[gnu::always_inline]] LaneMoment lane(int l, const Law& both, double nx, double ny, double nz, double hx,
                                         double hy, double hz, double twist, double rx, double ry, double rz,
                                         double ri, double rj, double fn, double ks, double dt) {
    return inner.template lane<kDissipation>(l, both.inner, nx, ny, nz, hx, hy, hz, twist, rx, ry, rz, ri, rj, fn,
                                             ks, dt);
  }
  // The dashpots as ViscousLanes::damp, with the normal law's tangent stiffness.
  template <bool kDissipation>
  [[gnu::always_inline]] LaneDamped damp(int l, const Law& both, double nx, double ny, double nz, double vn,
                                         double sx, double sy, double sz, double fn, double trial_x, double trial_y,
                                         double trial_z, double fsx, double fsy, double fsz, double bonded, double kn,
                                         double kt, double friction, double dt) {
    return dashpots.template damp<kDissipation>(l, both.viscous, nx, ny, nz, vn, sx, sy, sz, fn, trial_x, trial_y,
                                                trial_z, fsx, fsy, fsz, bonded,
                                                dashpot_normal_stiffness(both.inner, kn), kt, friction, dt);
  }
  void keep(std::size_t pair, int l) { inner.keep(pair, l); }
  template <class Sink>
  void book(Sink& sink, int l) const {
    dashpots.book(sink, l);
    inner.book(sink, l);
  }
};

}  // namespace colza::detail
