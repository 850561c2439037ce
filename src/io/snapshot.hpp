// A particle snapshot: what result.h5's /snapshots/<k> holds (schema in io/hdf5_writer.hpp)
// and result.xmf shows. Single precision: snapshots are for looking at a run (ParaView); the
// exact states are /particles/* in double precision.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace colza {

struct Snapshot {
  double time = 0.0;       // s since the test began (World::time minus the stage's start)
  std::uint64_t step = 0;  // World::step after the recorded step
  // Per particle (N): x at the end of the step (m), v and w at its middle (m/s, rad/s), the
  // contact force of the step without gravity and damping (N), radius (m), and the number
  // of particle-particle contacts that touch or are bonded (coordination number).
  std::vector<float> position, velocity, angular_velocity, force;  // 3 N each, row-major
  std::vector<float> radius;                                        // N
  std::vector<std::int32_t> coordination;                           // N
  // Contact network (M particle pairs that touch or are bonded): particle indices (2 M,
  // first < second), normal force (N, compression positive), shear force on the second
  // particle (3 M, N), bonded (1) or not (0).
  std::vector<std::int32_t> pairs;
  std::vector<float> normal_force, shear_force;
  std::vector<std::uint8_t> bonded;
  // Walls as quadrilaterals (walls/wall_mesh.hpp): corner points (3 P, m), corners of each
  // quad (4 Q, indices into the points), the wall of each quad (Q, index into wall_names)
  // and that wall's total force from the particles (3 Q, N).
  std::vector<float> wall_points;
  std::vector<std::int32_t> wall_quads, wall_of_quad;
  std::vector<float> wall_force;

  std::size_t particles() const { return radius.size(); }
  std::size_t contacts() const { return normal_force.size(); }
  std::size_t wall_point_count() const { return wall_points.size() / 3; }
  std::size_t quads() const { return wall_of_quad.size(); }
};

// The snapshots of one run and the names of its walls (index = World::walls index).
struct SnapshotSeries {
  double interval = 0.0;  // s; 0 = no snapshots
  std::vector<std::string> wall_names;
  std::vector<Snapshot> snapshots;
  bool empty() const { return snapshots.empty(); }
};

}  // namespace colza
