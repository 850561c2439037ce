// Rolling resistance in the batched particle-pair kernel (engine/pair_batch.hpp): the lanes'
// moment columns. Each lane's stored moment Mr (N m, on body 2) is read from its pair's
// slot-state row (contact/slot_state.hpp, at the rolling slot's offset), the lane's new moment
// computed by lane_rolling_moment (engine/lane_rolling.hpp) beside the paper's law, and a
// steady lane's moment written back to the row; lanes that change state take the generic law
// (contact/generic_law.hpp) from their untouched row, as they do without rolling.
#pragma once
#include <algorithm>
#include <cstddef>
#include "contact/pair_context.hpp"
#include "contact/rolling_laws.hpp"
#include "core/particles.hpp"
#include "engine/lane_rolling.hpp"

namespace colza::detail {

template <int kLanes>
struct RollingLanes {
  static constexpr bool kMoment = true;
  static constexpr bool kDashpots = false;
  static constexpr bool kNormal = false;
  static constexpr bool kBondStrengths = false;
  LaneRollingLaw law;
  double* state;       // slot-state rows, `stride` doubles per pair
  std::size_t stride;  // doubles per row
  std::size_t offset;  // the rolling slot's Mr in a row
  alignas(64) double mr[3][kLanes];       // stored moment on body 2 (N m)
  alignas(64) double mr_new[3][kLanes];   // this step's moment on body 2 (N m)
  alignas(64) double inertia[kLanes] = {};  // I_r (kg m^2), filled with a dashpot only (else 0)
  alignas(64) double dissipated[kLanes];  // J, the cap's or the dashpot's this step

  RollingLanes(const ElasticPlasticRolling& rolling, double* rows, std::size_t row_stride, std::size_t mr_offset)
      : law{rolling.stiffness_factor, rolling.friction, rolling.form == RollingForm::kYade ? 1.0 : 0.0,
            rolling.damping_ratio},
        state(rows),
        stride(row_stride),
        offset(mr_offset) {}

  // The stored moments of the batch's lanes, and their I_r (PairContext's) with a dashpot.
  template <class Batch>
  void fill(const Batch& b, const ParticleArrays& p) {
    for (int l = 0; l < b.count; ++l) {
      const double* row = state + b.pair[l] * stride + offset;
      mr[0][l] = row[0];
      mr[1][l] = row[1];
      mr[2][l] = row[2];
    }
    if (law.damping_ratio > 0.0)
      for (int l = 0; l < b.count; ++l) {
        const Index i = b.body_i[l], j = b.body_j[l];
        inertia[l] = pair_rolling_inertia(inertia_about_contact(p.inertia[i], p.mass[i], p.radius[i]),
                                          inertia_about_contact(p.inertia[j], p.mass[j], p.radius[j]));
      }
  }
  // Lane l's moment this step, the spring's and the dashpot's (`rolling` a copy of `law` the
  // caller keeps out of its loop; n, h, twist as the paper's law takes them; rotation the
  // relative rotation (w2 - w1) dt; ri, rj the radii (m); fn the normal force (N); ks the
  // pair's shear stiffness (N/m); dt (s)); the spring's kept in the lane's columns.
  template <bool kDissipation>
  [[gnu::always_inline]] LaneMoment lane(int l, const LaneRollingLaw& rolling, double nx, double ny, double nz, double hx, double hy, double hz,
                                         double twist, double rx, double ry, double rz, double ri, double rj,
                                         double fn, double ks, double dt) {
    const LaneRollingSpring spring = lane_rolling_spring(rolling, ks, ri, rj);
    const double limit = spring.limit_per_force * std::max(fn, 0.0);
    const double dashpot = lane_rolling_dashpot_per_step(rolling, spring.kr, inertia[l], dt);
    const LaneRollingStep m = lane_rolling_moment<kDissipation>(LaneRollingContact{
        nx, ny, nz, hx, hy, hz, twist, rx, ry, rz, mr[0][l], mr[1][l], mr[2][l], spring.kr, limit, dashpot});
    mr_new[0][l] = m.mx;
    mr_new[1][l] = m.my;
    mr_new[2][l] = m.mz;
    dissipated[l] = m.applied.dissipated;
    return m.applied;
  }
  // A steady lane's moment into its pair's row.
  void keep(std::size_t pair, int l) {
    double* row = state + pair * stride + offset;
    row[0] = mr_new[0][l];
    row[1] = mr_new[1][l];
    row[2] = mr_new[2][l];
  }
  template <class Sink>
  void book(Sink& sink, int l) const {
    sink.rolling(dissipated[l]);
  }
};

}  // namespace colza::detail
