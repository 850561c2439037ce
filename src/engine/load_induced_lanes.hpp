// Load-induced cohesion (physics.md section 7.5; contact/bond_laws.hpp LoadInducedBond) in the
// batched particle-pair kernel (engine/pair_batch.hpp): each lane's largest normal force Fmax
// (N) and whether its bond has formed, read from its pair's slot-state row (at the bond slot's
// offset); Fmax raised to this step's Fn, and the bond's strengths
//   Cn = min(a_n Fmax, Cn_cap),  Cs = min(a_s Fmax, Cs_cap)  (N)
// handed to the lanes' contact-bond rule (lane_law.hpp); a steady lane's Fmax written back.
// A lane whose bond forms this step falls back to the generic law (contact/generic_law.hpp)
// from its untouched row, as lanes that change state do. Every line is LoadInducedBond's
// expression in its order (note_normal_force, strengths), so each lane gives the generic
// tier's bits.
#pragma once
#include <cstddef>
#include "contact/bond_laws.hpp"
#include "core/particles.hpp"

namespace colza::detail {

// F_on (N), a_n, a_s (-), Cn_cap, Cs_cap (N).
struct LaneLoadInducedLaw {
  double onset_force, normal_strength_ratio, shear_strength_ratio, normal_strength_cap, shear_strength_cap;
};

// A lane's bond strengths this step (N) and whether its bond forms now (1 or 0).
struct LaneBondStrengths {
  double normal, shear, forms;
};

template <int kLanes>
struct LoadInducedLanes {
  static constexpr bool kMoment = false;
  static constexpr bool kDashpots = false;
  static constexpr bool kNormal = false;
  static constexpr bool kBondStrengths = true;
  LaneLoadInducedLaw law;
  double* state;       // slot-state rows, `stride` doubles per pair
  std::size_t stride;  // doubles per row
  std::size_t offset;  // the bond slot's Fmax, then its formed flag, in a row
  alignas(64) double largest_force[kLanes];      // stored Fmax (N)
  alignas(64) double formed[kLanes];             // 1 once the bond has formed, else 0
  alignas(64) double largest_force_new[kLanes];  // after this step (N)

  LoadInducedLanes(const LoadInducedBond& bond, double* rows, std::size_t row_stride, std::size_t bond_offset)
      : law{bond.onset_force, bond.normal_strength_ratio, bond.shear_strength_ratio, bond.normal_strength_cap,
            bond.shear_strength_cap},
        state(rows),
        stride(row_stride),
        offset(bond_offset) {}

  template <class Batch>
  void fill(const Batch& b, const ParticleArrays&) {
    for (int l = 0; l < b.count; ++l) {
      const double* row = state + b.pair[l] * stride + offset;
      largest_force[l] = row[0];
      formed[l] = row[1];
    }
  }
  // Lane l's strengths at this step's normal force fn (N) (`load_induced` a copy of `law` the
  // caller keeps out of its loop); Fmax kept in its column. (std::max and std::min written out
  // by value, (a < b) ? b : a and (b < a) ? b : a: they vectorise.)
  [[gnu::always_inline]] LaneBondStrengths bond_strengths(int l, const LaneLoadInducedLaw& load_induced, double fn) {
    const double stored = largest_force[l];
    const double fmax = stored < fn ? fn : stored;
    largest_force_new[l] = fmax;
    const bool forms = (formed[l] == 0.0) & (fn > load_induced.onset_force);
    const double normal = load_induced.normal_strength_ratio * fmax;
    const double shear = load_induced.shear_strength_ratio * fmax;
    return {load_induced.normal_strength_cap < normal ? load_induced.normal_strength_cap : normal,
            load_induced.shear_strength_cap < shear ? load_induced.shear_strength_cap : shear, forms ? 1.0 : 0.0};
  }
  void keep(std::size_t pair, int l) { state[pair * stride + offset] = largest_force_new[l]; }
  template <class Sink>
  void book(Sink&, int) const {}
};

}  // namespace colza::detail
