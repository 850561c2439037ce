// The Walton-Braun elasto-plastic normal force (physics.md section 7; contact/normal_laws.hpp
// WaltonBraunNormal) for the SIMD lanes of the batched particle-pair kernel
// (engine/pair_batch.hpp), in place of the linear spring, for a contact that was touching at
// the start of the step:
//   loading (un >= dmax): Fn = k1 un, dmax <- un, dissipating (1 - k1/k2) k1 (un^2 - dmax^2) / 2;
//   otherwise Fn = k2 (un - d0), d0 = (1 - k1/k2) max(dmax, 0), not below 0 unless bonded.
//
// Every line is WaltonBraunNormal::force's expression, with the same IEEE operations in the
// same order and no FMA contraction (-ffp-contract=off), so each lane gives the generic
// tier's bits.
#pragma once

namespace colza::detail {

// The unloading stiffness ratio k2 / k1 (-).
struct LaneWaltonBraunLaw {
  double unloading_stiffness_ratio;
};

// Fn (N), the new largest overlap dmax (m) and the energy the loading dissipated (J).
struct LaneNormalForce {
  double fn, dmax, dissipated;
};

// overlap un (m), k1 = Kn (N/m), the stored dmax (m), bonded 1 if a bond holds else 0.
// (std::max(a, 0.0) is (a < 0) ? 0 : a, written out by value: it vectorises.)
[[gnu::always_inline]] inline LaneNormalForce lane_walton_braun(const LaneWaltonBraunLaw& law, double overlap,
                                                                double kn, double dmax, double bonded) {
  const double k1 = kn, k2 = law.unloading_stiffness_ratio * k1;
  const bool loading = overlap >= dmax;
  const double loaded_dissipation = (1.0 - k1 / k2) * k1 * 0.5 * (overlap * overlap - dmax * dmax);
  const double plastic_overlap = (1.0 - 1.0 / law.unloading_stiffness_ratio) * (dmax < 0.0 ? 0.0 : dmax);
  const double unloading = k2 * (overlap - plastic_overlap);
  const bool clamps = (bonded == 0.0) & (unloading < 0.0);
  const double unloaded = clamps ? 0.0 : unloading;
  LaneNormalForce out;
  out.fn = loading ? k1 * overlap : unloaded;
  out.dmax = loading ? overlap : dmax;
  out.dissipated = loading ? loaded_dissipation : 0.0;
  return out;
}

}  // namespace colza::detail
