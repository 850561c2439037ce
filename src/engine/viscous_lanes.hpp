// Viscous contact damping in the batched particle-pair kernel (engine/pair_batch.hpp): each
// lane's reduced mass m* = m1 m2 / (m1 + m2) (kg) gathered beside the batch, the dashpots
// computed by lane_dashpots (engine/lane_viscous.hpp) after the paper's law, and a steady
// lane's dissipation booked; the dashpots keep no state. Lanes that change state take the
// generic law (contact/generic_law.hpp), as they do without dashpots.
#pragma once
#include <cstddef>
#include "contact/damping_laws.hpp"
#include "core/particles.hpp"
#include "engine/lane_viscous.hpp"

namespace colza::detail {

template <int kLanes>
struct ViscousLanes {
  static constexpr bool kMoment = false;
  static constexpr bool kDashpots = true;
  static constexpr bool kNormal = false;
  static constexpr bool kBondStrengths = false;
  LaneViscousLaw law;
  alignas(64) double mass[kLanes];        // m* (kg)
  alignas(64) double dissipated[kLanes];  // J, the dashpots' this step

  explicit ViscousLanes(const ViscousDamping& viscous) : law{viscous.normal_ratio, viscous.tangential_ratio} {}

  // The reduced masses of the batch's lanes.
  template <class Batch>
  void fill(const Batch& b, const ParticleArrays& p) {
    for (int l = 0; l < b.count; ++l) {
      const double mi = p.mass[b.body_i[l]], mj = p.mass[b.body_j[l]];
      mass[l] = mi * mj / (mi + mj);
    }
  }
  // Lane l's force with the dashpots (`viscous` a copy of `law` the caller keeps out of its
  // loop; the rest as LaneDashpotContact states it); its dissipation kept in the lane's column.
  template <bool kDissipation>
  [[gnu::always_inline]] LaneDamped damp(int l, const LaneViscousLaw& viscous, double nx, double ny, double nz,
                                         double vn, double sx, double sy, double sz, double fn, double trial_x,
                                         double trial_y, double trial_z, double fsx, double fsy, double fsz,
                                         double bonded, double kn, double kt, double friction, double dt) {
    const LaneDamped d = lane_dashpots<kDissipation>(
        viscous, LaneDashpotContact{nx, ny, nz, vn, sx, sy, sz, fn, trial_x, trial_y, trial_z, fsx, fsy, fsz, bonded,
                                    kn, kt, mass[l], friction, dt});
    dissipated[l] = d.dissipated;
    return d;
  }
  void keep(std::size_t, int) {}
  template <class Sink>
  void book(Sink& sink, int l) const {
    sink.viscous(dissipated[l]);
  }
};

}  // namespace colza::detail
