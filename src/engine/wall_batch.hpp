// Batched sphere-wall kernel: the wall-pair law of engine/wall_pair_force.hpp for contacts
// that persist through the step, lane by lane over small structure-of-arrays batches, as
// engine/pair_batch.hpp does for particle pairs.
//
// Why: a wall pair through the scalar path cost about 30 ns here (against 13 ns for a
// particle pair in lanes): the geometry call, Eigen 3-vectors and the branches of the
// general law. The oedometer has ~550 wall pairs per 2300 particles (13 % of a step).
//
// The lanes of one batch belong to one wall, so the wall's shape is resolved once per batch
// and its geometry (walls/wall.cpp) is computed lane by lane with the same IEEE operations
// in the same order (Eigen's dot (a0 b0 + a1 b1) + a2 b2, norm sqrt of that, element-wise
// division; no FMA contraction), and the law by lane_law.hpp: every lane gives the scalar
// path's bits. A pair that was not touching at the start of the step, a pair whose sphere
// left the wall's range, and a contact that separates go through the scalar function from
// their untouched history. Results are consumed in pair order (wall by wall, particle by
// particle), so every sum is that of the reference loop.
#pragma once
#include <cmath>
#include "engine/batch_driver.hpp"
#include "engine/lane_law.hpp"
#include "engine/lane_transpose.hpp"
#include "engine/wall_pair_force.hpp"

namespace colza::detail {

struct WallBatch {
  static constexpr int kLanes = 32;
  int count = 0;
  std::size_t pair[kLanes];  // wall-pair index of each lane, increasing
  Index sphere[kLanes];      // its sphere
  // inputs: the sphere's state and the history
  alignas(64) double x[3][kLanes], v[3][kLanes], w[3][kLanes], r[kLanes];
  alignas(64) double fs[3][kLanes], prev_normal[3][kLanes];
  // outputs: new normal, Fn, new shear force, force on the sphere, its moment, slip energy
  alignas(64) double normal[3][kLanes], fn[kLanes], fs_new[3][kLanes], f[3][kLanes], torque[3][kLanes];
  alignas(64) double slip[kLanes], fallback[kLanes];
};

// Records wall pair c (sphere i, touching at the start of the step) in the next lane.
inline void note_wall_lane(WallBatch& b, const ParticleArrays& p, std::size_t c, Index i) {
  const int l = b.count++;
  b.pair[l] = c;
  b.sphere[l] = i;
  b.r[l] = p.radius[i];
}

// The noted lanes' sphere states (position, velocity, angular velocity) and histories
// (stored shear force, previous normal), four lanes at a time (engine/lane_transpose.hpp).
inline void fill_wall_lanes(WallBatch& b, const ParticleArrays& p, const ContactHistory* history) {
  pad_last_lane_group(b.count, b.pair, b.sphere);
  for (int l = 0; l < b.count; l += kLaneGroup) {
    bodies_to_lanes(p.position, b.sphere, b.x, l);
    bodies_to_lanes(p.velocity, b.sphere, b.v, l);
    bodies_to_lanes(p.angular_velocity, b.sphere, b.w, l);
    histories_to_lanes(b, history, l);
  }
}

// Distance from the sphere centre (x, y, z) to the wall surface and the unit normal from the
// wall into the sphere (walls/wall.cpp, shape by shape); in_range false where the scalar
// geometry says the sphere cannot touch the wall (or the normal is undefined).
struct LaneWallGeometry {
  double distance, nx, ny, nz;
  bool in_range;
};

template <WallShape kShape>
[[gnu::always_inline]] inline LaneWallGeometry lane_wall_geometry(const Wall& wall, double x, double y, double z) {
  const double ox = wall.origin[0], oy = wall.origin[1], oz = wall.origin[2];
  const double ax = wall.normal[0], ay = wall.normal[1], az = wall.normal[2];
  const double rx = x - ox, ry = y - oy, rz = z - oz;  // rel = x - origin
  const double along_normal = (rx * ax + ry * ay) + rz * az;
  LaneWallGeometry g;
  if constexpr (kShape == WallShape::kPlane) {  // signed distance, wall normal
    g.distance = along_normal;
    g.nx = ax;
    g.ny = ay;
    g.nz = az;
    g.in_range = true;
  } else if constexpr (kShape == WallShape::kCylinder) {  // inner surface; `normal` is the axis
    const double axial = along_normal;
    const double radial_x = rx - axial * ax, radial_y = ry - axial * ay, radial_z = rz - axial * az;
    const double rho = std::sqrt((radial_x * radial_x + radial_y * radial_y) + radial_z * radial_z);
    g.in_range = !(axial < wall.axial_min) & !(axial > wall.axial_max) & (rho != 0.0);
    g.distance = wall.radius - rho;
    g.nx = -radial_x / rho;
    g.ny = -radial_y / rho;
    g.nz = -radial_z / rho;
  } else {  // rectangle: the face seen from either side, or its nearest edge or corner point
    const double ux = wall.axis_u[0], uy = wall.axis_u[1], uz = wall.axis_u[2];
    const double vx = wall.axis_v[0], vy = wall.axis_v[1], vz = wall.axis_v[2];
    const double su = (rx * ux + ry * uy) + rz * uz, sv = (rx * vx + ry * vy) + rz * vz;
    const double lo_u = -wall.half_u, lo_v = -wall.half_v;
    // Beyond a restricted edge: no contact (kNone), or none behind the plate (kFrontOnly).
    const RectangleEdges& e = wall.edges;
    const bool behind = !(along_normal > 0.0);
    const bool refused =
        ((su < lo_u) & edge_refuses(e.u_min, behind)) | ((su > wall.half_u) & edge_refuses(e.u_max, behind)) |
        ((sv < lo_v) & edge_refuses(e.v_min, behind)) | ((sv > wall.half_v) & edge_refuses(e.v_max, behind));
    // std::clamp(s, lo, hi) = s < lo ? lo : (hi < s ? hi : s)
    const double cu = su < lo_u ? lo_u : (wall.half_u < su ? wall.half_u : su);
    const double cv = sv < lo_v ? lo_v : (wall.half_v < sv ? wall.half_v : sv);
    const double h = along_normal;
    const bool on_face = (cu == su) & (cv == sv);
    // closest = origin + cu u + cv v; d = x - closest
    const double dx = x - ((ox + cu * ux) + cv * vx), dy = y - ((oy + cu * uy) + cv * vy),
                 dz = z - ((oz + cu * uz) + cv * vz);
    const double dist = std::sqrt((dx * dx + dy * dy) + dz * dz);
    const bool front = h >= 0.0;
    g.distance = on_face ? std::abs(h) : dist;
    g.nx = on_face ? (front ? ax : -ax) : dx / dist;
    g.ny = on_face ? (front ? ay : -ay) : dy / dist;
    g.nz = on_face ? (front ? az : -az) : dz / dist;
    g.in_range = (!refused) & (on_face | (dist != 0.0));
  }
  return g;
}

// The law for every lane of one wall (the wall is body 1, the sphere body 2): contact point
// in the middle of the overlap, c = x - (R - un/2) n, arm = c - x; velocity of the sphere
// relative to the wall at c, v + w x arm - v_wall; twist dt/2 w . n_old.
template <WallShape kShape, bool kSlip>
inline void compute_wall_lanes(WallBatch& b, const Wall& wall, const PairParameters& q, double dt, double half_dt) {
  const double kn = q.kn, ks = q.ks, mu = q.friction;
  const double wvx = wall.velocity[0], wvy = wall.velocity[1], wvz = wall.velocity[2];
  const int count = b.count;
#pragma omp simd
  for (int l = 0; l < count; ++l) {
    const double x = b.x[0][l], y = b.x[1][l], z = b.x[2][l];
    const LaneWallGeometry g = lane_wall_geometry<kShape>(wall, x, y, z);
    const double nx = g.nx, ny = g.ny, nz = g.nz;
    const double overlap = b.r[l] - g.distance;
    const double offset = b.r[l] - 0.5 * overlap;
    const double ax = (x - offset * nx) - x, ay = (y - offset * ny) - y, az = (z - offset * nz) - z;  // arm
    const double wx = b.w[0][l], wy = b.w[1][l], wz = b.w[2][l];
    const double rvx = (b.v[0][l] + (wy * az - wz * ay)) - wvx;
    const double rvy = (b.v[1][l] + (wz * ax - wx * az)) - wvy;
    const double rvz = (b.v[2][l] + (wx * ay - wy * ax)) - wvz;
    // Shear displacement increment dus = (vr - (vr.n) n) dt (m).
    const double vn = (rvx * nx + rvy * ny) + rvz * nz;
    const double sx = (rvx - vn * nx) * dt, sy = (rvy - vn * ny) * dt, sz = (rvz - vn * nz) * dt;
    const double hx = b.prev_normal[0][l], hy = b.prev_normal[1][l], hz = b.prev_normal[2][l];
    const double twist = half_dt * ((wx * hx + wy * hy) + wz * hz);
    const LaneForce r = lane_law<false, kSlip>(
        LaneContact{nx, ny, nz, overlap, sx, sy, sz, twist, hx, hy, hz, b.fs[0][l], b.fs[1][l], b.fs[2][l], false}, kn,
        ks, mu, 0.0, 0.0);
    b.slip[l] = r.slip;
    b.fallback[l] = (r.falls_back | !g.in_range) ? 1.0 : 0.0;
    const double Fx = r.Fx, Fy = r.Fy, Fz = r.Fz;
    b.torque[0][l] = ay * Fz - az * Fy;
    b.torque[1][l] = az * Fx - ax * Fz;
    b.torque[2][l] = ax * Fy - ay * Fx;
    store_lane_force(b, l, r, nx, ny, nz);
  }
}

template <bool kSlip>
inline void compute_wall_lanes(WallBatch& b, const Wall& wall, const PairParameters& q, double dt, double half_dt) {
  switch (wall.shape) {
    case WallShape::kPlane: return compute_wall_lanes<WallShape::kPlane, kSlip>(b, wall, q, dt, half_dt);
    case WallShape::kCylinder: return compute_wall_lanes<WallShape::kCylinder, kSlip>(b, wall, q, dt, half_dt);
    case WallShape::kRectangle: return compute_wall_lanes<WallShape::kRectangle, kSlip>(b, wall, q, dt, half_dt);
  }
}

// Wall pairs [begin, end) of one wall through the batched kernel, in pair order:
// `out.carries(c, i, f, torque)` receives the force on sphere i (the wall gets -f) and its
// moment about the centre; `out.none(c)` a pair without force. Requires one particle
// material (the caller checks).
template <class Normal, class Tangential, class Out, class Sink>
[[gnu::always_inline]] inline void wall_pairs_batched(const Normal& normal_law, const Tangential& tangential_law,
                                                      const ParticleArrays& p, const Wall& wall,
                                                      const PairTable& pairs, double dt, double half_dt,
                                                      const Index* particle, ContactHistory* history,
                                                      std::size_t begin, std::size_t end, Out& out, Sink& sink) {
  const PairParameters& q = pairs.particle_wall(0, wall.material);
  WallBatch b;
  run_in_batches(
      b, history, begin, end, [&](std::size_t c) { note_wall_lane(b, p, c, particle[c]); },
      [&] {
        fill_wall_lanes(b, p, history);
        compute_wall_lanes<Sink::kKeepsSlip>(b, wall, q, dt, half_dt);
      },
      [&](std::size_t k, int l) {  // steady contact: the lane's result
        keep_lane_history(history[k], b, l);
        sink.slip(b.slip[l]);
        out.carries(k, particle[k], Vec3(b.f[0][l], b.f[1][l], b.f[2][l]),
                    Vec3(b.torque[0][l], b.torque[1][l], b.torque[2][l]));
      },
      [&](std::size_t k) {
        Vec3 f, torque;
        if (wall_pair_force(normal_law, tangential_law, p, wall, pairs, dt, half_dt, particle[k], history[k], f,
                            torque, sink))
          out.carries(k, particle[k], f, torque);
        else
          out.none(k);
      });
}

}  // namespace colza::detail
