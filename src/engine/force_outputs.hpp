// Where the force loops put a pair's force (internal to the stepper, engine/force_loops_body.hpp):
// onto the bodies at once (serial), or onto inner bodies and into per-pair slots for the
// boundary bodies (threaded, engine/force_partition.hpp); for wall pairs, onto the sphere and
// the wall, or onto the sphere with the wall's share kept by pair. Each output has
// `carries(...)` for a pair with force and `none(c)` for one without.
#pragma once
#include <cstdint>
#include <vector>
#include "core/types.hpp"
#include "engine/force_partition.hpp"
#include "engine/pair_force.hpp"
#include "engine/pair_sinks.hpp"
#include "walls/wall.hpp"

namespace colza::detail {

// The walls' per-step sums, accumulated in wall-pair order by both force loops.
inline void clear_wall_sums(std::vector<Wall>& walls) {
  for (auto& wall : walls) {
    wall.force.setZero();
    wall.contact_count = 0;
  }
}
// Wall pair carrying force f (N) on its particle: the wall takes -f, counts the contact,
// and the power of the wall on the particle f . v_wall (W) goes to the ledger.
inline void wall_takes(Wall& wall, const Vec3& f, ForceLoopTotals& totals) {
  wall.force -= f;
  ++wall.contact_count;
  totals.wall_power += f.dot(wall.velocity);
}

// A pair's force straight onto its bodies: body 2 gets +f and +t_j, body 1 gets -f and -t_i.
inline void scatter_to_bodies(Vec3* force, Vec3* torque, Index i, Index j, const V3& f, const V3& t_i,
                              const V3& t_j) {
  add_to(force[j], f);
  sub_from(force[i], f);
  add_to(torque[j], t_j);
  sub_from(torque[i], t_i);
}

// Where a pair's force goes. Serial: straight onto the bodies. Threaded: ScatterOrStore below.
struct ScatterToBodies {
  Vec3* force;
  Vec3* torque;
  void carries(std::size_t, Index i, Index j, const V3& f, const V3& t_i, const V3& t_j) {
    scatter_to_bodies(force, torque, i, j, f, t_i, t_j);
  }
  void none(std::size_t) {}
};
// Threaded: an inner body gets its share at once, as in the serial scatter; a pair with a
// boundary body also goes to its slot, from which the boundary body is summed after the
// barrier (engine/force_partition.hpp).
struct ScatterOrStore {
  Vec3* force;
  Vec3* torque;
  const Index* slot;
  const std::uint8_t* boundary;
  Vec3* slot_force;
  Vec3* slot_torque_1;
  Vec3* slot_torque_2;
  void carries(std::size_t c, Index i, Index j, const V3& f, const V3& t_i, const V3& t_j) {
    const Index s = slot[c];
    if (s == ForcePartition::kNoSlot) {
      scatter_to_bodies(force, torque, i, j, f, t_i, t_j);
      return;
    }
    slot_force[s] = vec(f);
    slot_torque_1[s] = Vec3(-t_i.x, -t_i.y, -t_i.z);
    slot_torque_2[s] = vec(t_j);
    if (!boundary[j]) {
      add_to(force[j], f);
      add_to(torque[j], t_j);
    }
    if (!boundary[i]) {
      sub_from(force[i], f);
      sub_from(torque[i], t_i);
    }
  }
  void none(std::size_t c) {
    const Index s = slot[c];
    if (s == ForcePartition::kNoSlot) return;
    slot_force[s].setZero();
    slot_torque_1[s].setZero();
    slot_torque_2[s].setZero();
  }
};

// Where a wall pair's force goes. Serial: onto the sphere and, opposite, the wall (with the
// ledger's wall power). Threaded: onto the sphere (its thread's own), and kept by pair for the
// walls' sums after the parallel region, in wall-pair order.
struct WallTakesForce {
  Vec3* force;
  Vec3* torque;
  Wall& wall;
  ForceLoopTotals& totals;
  void carries(std::size_t, Index i, const Vec3& f, const Vec3& t) {
    force[i] += f;
    torque[i] += t;
    wall_takes(wall, f, totals);
  }
  void none(std::size_t) {}
};
struct StoreWallForce {
  Vec3* force;
  Vec3* torque;
  Vec3* wall_force;
  std::uint8_t* wall_carries;
  void carries(std::size_t c, Index i, const Vec3& f, const Vec3& t) {
    wall_carries[c] = 1;
    wall_force[c] = f;
    force[i] += f;
    torque[i] += t;
  }
  void none(std::size_t c) { wall_carries[c] = 0; }
};

}  // namespace colza::detail
