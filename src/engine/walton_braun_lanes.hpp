// The Walton-Braun normal law in the batched particle-pair kernel (engine/pair_batch.hpp): each
// lane's largest overlap dmax (m) read from its pair's slot-state row (contact/slot_state.hpp,
// at the normal slot's offset), the lane's normal force computed by lane_walton_braun
// (engine/lane_walton_braun.hpp) in place of the linear spring, and a steady lane's dmax
// written back and its plastic dissipation booked. Lanes that change state take the generic
// law (contact/generic_law.hpp) from their untouched row, as they do without it.
#pragma once
#include <cstddef>
#include "contact/normal_laws.hpp"
#include "core/particles.hpp"
#include "engine/lane_walton_braun.hpp"

namespace colza::detail {

template <int kLanes>
struct WaltonBraunLanes {
  static constexpr bool kMoment = false;
  static constexpr bool kDashpots = false;
  static constexpr bool kNormal = true;
  static constexpr bool kBondStrengths = false;
  LaneWaltonBraunLaw law;
  double* state;       // slot-state rows, `stride` doubles per pair
  std::size_t stride;  // doubles per row
  std::size_t offset;  // the normal slot's dmax in a row
  alignas(64) double dmax[kLanes];        // stored largest overlap (m)
  alignas(64) double dmax_new[kLanes];    // after this step (m)
  alignas(64) double dissipated[kLanes];  // J, the loading's this step

  WaltonBraunLanes(const WaltonBraunNormal& normal, double* rows, std::size_t row_stride, std::size_t dmax_offset)
      : law{normal.unloading_stiffness_ratio}, state(rows), stride(row_stride), offset(dmax_offset) {}

  template <class Batch>
  void fill(const Batch& b, const ParticleArrays&) {
    for (int l = 0; l < b.count; ++l) dmax[l] = state[b.pair[l] * stride + offset];
  }
  // Lane l's normal force (`walton_braun` a copy of `law` the caller keeps out of its loop;
  // overlap (m), kn = k1 (N/m), bonded 1 or 0); dmax and the dissipation kept in its columns.
  [[gnu::always_inline]] double normal_force(int l, const LaneWaltonBraunLaw& walton_braun, double overlap,
                                             double kn, double bonded) {
    const LaneNormalForce n = lane_walton_braun(walton_braun, overlap, kn, dmax[l], bonded);
    dmax_new[l] = n.dmax;
    dissipated[l] = n.dissipated;
    return n.fn;
  }
  void keep(std::size_t pair, int l) { state[pair * stride + offset] = dmax_new[l]; }
  template <class Sink>
  void book(Sink& sink, int l) const {
    sink.plastic(dissipated[l]);
  }
};

}  // namespace colza::detail
