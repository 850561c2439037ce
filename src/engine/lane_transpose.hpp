// Copying 3-vectors from per-body or per-pair storage (Vec3, or the first three doubles of a
// row) into the lanes of a batched kernel, one array per component. The batched kernels
// (engine/pair_batch.hpp, engine/wall_batch.hpp) spent more time on this copy than on the
// contact law: one scalar load and one scalar store per value, about a cycle each
// (tests/bench/PERFORMANCE_LOG.md, session 13). With AVX, four lanes are filled at once by a
// 4x4 transpose of [x y z -] rows: four loads, seven shuffles and three stores for twelve
// values (without AVX, scalar copies). Only data move, so every value keeps its bits.
#pragma once
#include <vector>
#ifdef __AVX__
#include <immintrin.h>
#endif
#include "core/types.hpp"

namespace colza::detail {

// Lanes are filled in groups of this many; a batch's arrays hold a whole number of groups.
inline constexpr int kLaneGroup = 4;

// The lane count rounded up to whole groups.
constexpr int whole_lane_groups(int count) { return (count + kLaneGroup - 1) / kLaneGroup * kLaneGroup; }

// Fills the lanes from `count` to the end of its group with copies of lane 0 in each of the
// given per-lane index arrays, so that a group's lanes all name valid rows (the copies are
// computed and never read). Nothing to do when count is 0.
template <class... Arrays>
[[gnu::always_inline]] inline void pad_last_lane_group(int count, Arrays*... arrays) {
  for (int l = count; l < whole_lane_groups(count); ++l) ((arrays[l] = arrays[0]), ...);
}

// dst[d][l + k] = row_k[d] for d = 0, 1, 2 and k = 0..3. Reads exactly three doubles of each
// row (the masked load of the fourth cannot fault past the end of an array).
template <int kLanes>
[[gnu::always_inline]] inline void rows_to_lanes(const double* row_0, const double* row_1, const double* row_2,
                                                 const double* row_3, double (&dst)[3][kLanes], int l) {
  static_assert(kLanes % kLaneGroup == 0);
#ifdef __AVX__
  const __m256i first_three = _mm256_set_epi64x(0, -1, -1, -1);
  const __m256d r0 = _mm256_maskload_pd(row_0, first_three), r1 = _mm256_maskload_pd(row_1, first_three);
  const __m256d r2 = _mm256_maskload_pd(row_2, first_three), r3 = _mm256_maskload_pd(row_3, first_three);
  const __m256d x0x1z0z1 = _mm256_unpacklo_pd(r0, r1), y0y1 = _mm256_unpackhi_pd(r0, r1);
  const __m256d x2x3z2z3 = _mm256_unpacklo_pd(r2, r3), y2y3 = _mm256_unpackhi_pd(r2, r3);
  _mm256_storeu_pd(dst[0] + l, _mm256_permute2f128_pd(x0x1z0z1, x2x3z2z3, 0x20));
  _mm256_storeu_pd(dst[1] + l, _mm256_permute2f128_pd(y0y1, y2y3, 0x20));
  _mm256_storeu_pd(dst[2] + l, _mm256_permute2f128_pd(x0x1z0z1, x2x3z2z3, 0x31));
#else
  const double* rows[kLaneGroup] = {row_0, row_1, row_2, row_3};
  for (int k = 0; k < kLaneGroup; ++k)
    for (int d = 0; d < 3; ++d) dst[d][l + k] = rows[k][d];
#endif
}

// Lanes l..l+3 of dst from the 3-vectors state[body[l..l+3]] (positions, velocities or
// angular velocities of the lanes' bodies).
template <int kLanes>
[[gnu::always_inline]] inline void bodies_to_lanes(const std::vector<Vec3>& state, const Index* body,
                                                   double (&dst)[3][kLanes], int l) {
  rows_to_lanes(state[body[l]].data(), state[body[l + 1]].data(), state[body[l + 2]].data(),
                state[body[l + 3]].data(), dst, l);
}

}  // namespace colza::detail
