// The loop of the batched wall kernel (engine/wall_batch.hpp), and the pair-order merge
// that both batched kernels use (the particle-pair kernel, engine/pair_batch.hpp, only for
// its chunks that are not quiet, and with chunks of its own). A chunk of pairs [begin, end)
// ends after Batch::kLanes pairs that were touching at the start of the step (or at `end`):
// those go into lanes (`load(c)`), the lanes are filled with their state and computed
// (`compute()`), then every pair of the chunk is consumed in pair order: a lane that keeps
// its state by `steady(c, l)`, any other pair (not touching at the start of the step, or
// changing state) by `scalar(c)`, the scalar function from the untouched history. Pair
// order is what keeps every sum the reference loop's.
#pragma once
#include <cstddef>
#include "contact/history.hpp"
#include "core/types.hpp"
#include "engine/lane_transpose.hpp"

namespace colza::detail {

// Consumes the pairs [chunk_begin, chunk_end) of a computed batch in pair order: a lane that
// keeps its state by `steady(c, l)`, any other pair by `scalar(c)`.
template <class Batch, class Steady, class Scalar>
[[gnu::always_inline]] inline void consume_in_pair_order(const Batch& b, std::size_t chunk_begin,
                                                         std::size_t chunk_end, Steady&& steady, Scalar&& scalar) {
  int l = 0;
  for (std::size_t k = chunk_begin; k < chunk_end; ++k) {
    const bool in_lane = l < b.count && b.pair[l] == k;
    if (in_lane && b.fallback[l] == 0.0) {
      steady(k, l);
      ++l;
      continue;
    }
    if (in_lane) ++l;
    scalar(k);
  }
}

template <class Batch, class Load, class Compute, class Steady, class Scalar>
[[gnu::always_inline]] inline void run_in_batches(Batch& b, const ContactHistory* history, std::size_t begin,
                                                  std::size_t end, Load&& load, Compute&& compute, Steady&& steady,
                                                  Scalar&& scalar) {
  std::size_t c = begin;
  while (c < end) {
    const std::size_t chunk_begin = c;
    b.count = 0;
    for (; c < end && b.count < Batch::kLanes; ++c)
      if (history[c].touching) load(c);
    compute();
    consume_in_pair_order(b, chunk_begin, c, steady, scalar);
  }
}

// Lanes l..l+3's histories (stored shear force, previous normal) into the batch, by
// transposes (engine/lane_transpose.hpp); the counterpart of keep_lane_history.
template <class Batch>
[[gnu::always_inline]] inline void histories_to_lanes(Batch& b, const ContactHistory* history, int l) {
  const ContactHistory &h0 = history[b.pair[l]], &h1 = history[b.pair[l + 1]], &h2 = history[b.pair[l + 2]],
                       &h3 = history[b.pair[l + 3]];
  rows_to_lanes(h0.shear_force.data(), h1.shear_force.data(), h2.shear_force.data(), h3.shear_force.data(), b.fs, l);
  rows_to_lanes(h0.normal.data(), h1.normal.data(), h2.normal.data(), h3.normal.data(), b.prev_normal, l);
}

// A steady lane's new history: shear force, normal, Fn.
template <class Batch>
[[gnu::always_inline]] inline void keep_lane_history(ContactHistory& h, const Batch& b, int l) {
  h.shear_force = Vec3(b.fs_new[0][l], b.fs_new[1][l], b.fs_new[2][l]);
  h.normal = Vec3(b.normal[0][l], b.normal[1][l], b.normal[2][l]);
  h.normal_force = b.fn[l];
}

// What a lane's law gives that both batches keep: force on body 2, new shear force, normal, Fn.
template <class Batch, class LaneForce>
[[gnu::always_inline]] inline void store_lane_force(Batch& b, int l, const LaneForce& r, double nx, double ny,
                                                    double nz) {
  b.f[0][l] = r.Fx;
  b.f[1][l] = r.Fy;
  b.f[2][l] = r.Fz;
  b.fs_new[0][l] = r.fsx;
  b.fs_new[1][l] = r.fsy;
  b.fs_new[2][l] = r.fsz;
  b.normal[0][l] = nx;
  b.normal[1][l] = ny;
  b.normal[2][l] = nz;
  b.fn[l] = r.fn;
}

}  // namespace colza::detail
