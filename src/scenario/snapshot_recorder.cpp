#include "scenario/snapshot_recorder.hpp"

#include <algorithm>
#include <cmath>

#include "walls/wall_mesh.hpp"

namespace colza {

namespace {

void append(std::vector<float>& out, const Vec3& v) {
  for (int d = 0; d < 3; ++d) out.push_back(static_cast<float>(v[d]));
}

void add_particles(const ParticleArrays& p, Snapshot& s) {
  const std::size_t n = p.size();
  for (auto* v : {&s.position, &s.velocity, &s.angular_velocity, &s.force}) v->reserve(3 * n);
  s.radius.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    append(s.position, p.position[i]);
    append(s.velocity, p.velocity[i]);
    append(s.angular_velocity, p.angular_velocity[i]);
    append(s.force, p.force[i]);
    s.radius.push_back(static_cast<float>(p.radius[i]));
  }
  s.coordination.assign(n, 0);
}

// The particle pairs that touch or are bonded: the contact network and each particle's
// coordination number.
void add_contacts(const ParticlePairList& pp, Snapshot& s) {
  for (std::size_t c = 0; c < pp.size(); ++c) {
    const ContactHistory& h = pp.history[c];
    if (!h.touching && !h.bonded) continue;
    const auto a = static_cast<std::int32_t>(pp.first[c]), b = static_cast<std::int32_t>(pp.second[c]);
    s.pairs.push_back(a);
    s.pairs.push_back(b);
    s.normal_force.push_back(static_cast<float>(h.normal_force));
    append(s.shear_force, h.shear_force);
    s.bonded.push_back(h.bonded);
    ++s.coordination[static_cast<std::size_t>(a)];
    ++s.coordination[static_cast<std::size_t>(b)];
  }
}

void add_walls(const World& w, Snapshot& s) {
  const ParticleArrays& p = w.particles;
  Vec3 lo = Vec3::Constant(0.0), hi = Vec3::Constant(0.0);
  double r_max = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 r = Vec3::Constant(p.radius[i]);
    lo = i == 0 ? Vec3(p.position[i] - r) : Vec3(lo.cwiseMin(p.position[i] - r));
    hi = i == 0 ? Vec3(p.position[i] + r) : Vec3(hi.cwiseMax(p.position[i] + r));
    r_max = std::max(r_max, p.radius[i]);
  }
  const double pad = std::max(0.1 * (hi - lo).maxCoeff(), 2.0 * r_max);
  for (std::size_t k = 0; k < w.walls.size(); ++k) {
    const WallMesh m = wall_mesh(w.walls[k], lo, hi, pad);
    const auto first = static_cast<std::int32_t>(s.wall_point_count());
    for (const Vec3& x : m.points) append(s.wall_points, x);
    for (const auto& q : m.quads) {
      for (int c : q) s.wall_quads.push_back(first + c);
      s.wall_of_quad.push_back(static_cast<std::int32_t>(k));
      append(s.wall_force, w.walls[k].force);
    }
  }
}

}  // namespace

Snapshot take_snapshot(const World& w, double start) {
  Snapshot s;
  s.time = w.time - start;
  s.step = w.step;
  add_particles(w.particles, s);
  add_contacts(w.contacts.particle_pairs, s);
  add_walls(w, s);
  return s;
}

void SnapshotRecorder::observe(const World& w) {
  if (!enabled()) return;
  // The next multiple of the interval since the start; the first, 0, is the start itself.
  if (w.time - start_ < static_cast<double>(next_) * series_.interval) return;
  record(w);
}

void SnapshotRecorder::record(const World& w) {
  if (!enabled()) return;
  series_.wall_names.clear();  // walls are only ever added: the latest list names them all
  for (const Wall& wall : w.walls) series_.wall_names.push_back(wall.name);
  if (!series_.snapshots.empty() && series_.snapshots.back().step == w.step) return;
  series_.snapshots.push_back(take_snapshot(w, start_));
  // Past every multiple reached (a step longer than the interval skips the ones it jumped).
  next_ = static_cast<std::uint64_t>(std::floor((w.time - start_) / series_.interval)) + 1;
}

}  // namespace colza
