#include "engine/stepper.hpp"

#include <cmath>
#include <variant>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "contact/contact_law.hpp"

namespace colza {

Stepper::Stepper(PhysicsSettings physics)
    : physics_(std::move(physics)),
      pairs_(physics_.particle_materials, physics_.wall_materials, physics_.stiffness_rule),
      neighbours_(physics_.skin) {}

void Stepper::prepare(World& world) {
  neighbours_.invalidate();
  neighbours_.rebuild(world.particles, world.walls, world.contacts);
  update_time_step(world);
}

void Stepper::update_time_step(World& world) {
  world.dt = physics_.time_step.automatic
                 ? physics_.time_step.safety_factor * critical_time_step(world.particles, world.walls, world.contacts, pairs_)
                 : physics_.time_step.fixed_dt;
}

namespace {

// Below this many candidate pairs per thread the force loop runs serially (threading
// overhead would dominate; also keeps tiny unit-test systems on the reference path).
constexpr std::size_t kMinPairsPerThread = 1024;

int worker_threads() {
#ifdef _OPENMP
  return omp_in_parallel() ? 1 : omp_get_max_threads();
#else
  return 1;
#endif
}

struct ForceLoopTotals {
  double slip = 0.0, broken = 0.0, released = 0.0, wall_power = 0.0;
  std::uint64_t broken_tension = 0, broken_shear = 0;
};

inline void count_event(ContactEvent e, std::uint64_t& tension, std::uint64_t& shear) {
  if (e == ContactEvent::kBondBrokeTension) ++tension;
  if (e == ContactEvent::kBondBrokeShear) ++shear;
}

// Where the rare per-pair results go. The serial sink adds them to the totals at once, in
// pair order (the reference order). The logging sink keeps the non-zero ones of one
// contiguous chunk of pairs in pair order; chunk logs replayed in chunk order give the same
// sums as the serial sink (adding +0.0 to a sum that started at +0.0 changes nothing).
struct SerialSink {
  ForceLoopTotals& t;
  void slip(double s) { t.slip += s; }
  void broken(double e) { t.broken += e; }
  void released(double e) { t.released += e; }
  void event(ContactEvent e) { count_event(e, t.broken_tension, t.broken_shear); }
};
struct LogSink {
  std::vector<double> slips, brokens, releases;
  std::uint64_t broken_tension = 0, broken_shear = 0;
  void slip(double s) {
    if (s != 0.0) slips.push_back(s);
  }
  void broken(double e) {
    if (e != 0.0) brokens.push_back(e);
  }
  void released(double e) {
    if (e != 0.0) releases.push_back(e);
  }
  void event(ContactEvent e) { count_event(e, broken_tension, broken_shear); }
};

// Plain three-component arithmetic for the pair geometry. Every component is computed with
// the same IEEE operations in the same order as the Eigen expressions of the reference loop
// (element-wise ops; dot = (x0 y0 + x1 y1) + x2 y2; cross as Eigen's OrthoMethods), so the
// results are the same bits; it only avoids Eigen's packet shuffles on 3-vectors under SSE2.
struct V3 {
  double x, y, z;
};
inline V3 v3(const Vec3& v) { return {v[0], v[1], v[2]}; }
inline Vec3 vec(const V3& v) { return Vec3(v.x, v.y, v.z); }
inline V3 operator+(const V3& a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator*(double s, const V3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline V3 operator*(const V3& a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline V3 operator/(const V3& a, double s) { return {a.x / s, a.y / s, a.z / s}; }
inline double dot(const V3& a, const V3& b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }
inline V3 cross(const V3& a, const V3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline void add_to(Vec3& acc, const V3& a) {
  acc[0] += a.x;
  acc[1] += a.y;
  acc[2] += a.z;
}
inline void sub_from(Vec3& acc, const V3& a) {
  acc[0] -= a.x;
  acc[1] -= a.y;
  acc[2] -= a.z;
}

// Geometry and contact law of one particle pair (i < j): the arithmetic of the reference
// force loop, expression for expression. Returns false when the pair carries no force;
// otherwise f = force on body 2 (j), and arm_i, arm_j the lever arms.
template <class Normal, class Tangential, class Bond, class Sink>
[[gnu::always_inline]] inline bool particle_pair_force(const Normal& normal_law, const Tangential& tangential_law,
                                                       const Bond& bond_law, bool bond_new_contacts,
                                                       const ParticleArrays& p, const PairTable& pairs, double dt,
                                                       double half_dt, Index i, Index j, ContactHistory& h, V3& f,
                                                       V3& arm_i, V3& arm_j, Sink& sink) {
  const V3 xi = v3(p.position[i]), xj = v3(p.position[j]);
  const V3 d = xj - xi;
  const double ri = p.radius[i], rj = p.radius[j];
  const double dist2 = dot(d, d);
  const double reach = ri + rj;
  if (!h.touching && dist2 >= reach * reach) return false;  // candidate, not in contact
  const double dist = std::sqrt(dist2);
  const V3 n = d / dist;
  const double overlap = reach - dist;
  const V3 point = xi + (ri - 0.5 * overlap) * n;  // middle of the overlap
  arm_i = point - xi;
  arm_j = point - xj;
  const V3 wi = v3(p.angular_velocity[i]), wj = v3(p.angular_velocity[j]);
  const V3 rel_vel = (v3(p.velocity[j]) + cross(wj, arm_j)) - (v3(p.velocity[i]) + cross(wi, arm_i));
  ContactKinematics k;
  k.normal = vec(n);
  k.overlap = overlap;
  k.shear_increment = vec((rel_vel - dot(rel_vel, n) * n) * dt);
  k.twist_angle = half_dt * dot(wi + wj, v3(h.normal));  // previous normal (zero for a new contact)
  const PairParameters& q = pairs.particle_particle(p.material[i], p.material[j]);
  // State before the law runs: its stored energy is lost if the contact vanishes this step
  // (evaluated only then; same expression as evaluating it up front).
  const bool was_touching = h.touching != 0;
  const double fn_before = h.normal_force;
  const Vec3 fs_before = h.shear_force;
  const ContactOutcome out = evaluate_contact(normal_law, tangential_law, bond_law, q, k, h, bond_new_contacts);
  if (!out.carries_force) {
    if (was_touching) sink.broken(normal_law.energy(q, fn_before) + tangential_law.energy(q, fs_before));
    sink.event(out.event);
    return false;
  }
  sink.event(out.event);
  sink.slip(out.slip_dissipation);
  sink.released(out.bond_break_energy);
  f = v3(out.force_on_2);
  return true;
}

// Reference (serial) particle-pair loop: forces scattered straight onto the bodies.
template <class Normal, class Tangential, class Bond>
[[gnu::flatten]] void particle_pairs_serial(const Normal& normal_law, const Tangential& tangential_law,
                                             const Bond& bond_law, bool bond_new_contacts, World& world,
                                             const PairTable& pairs, ForceLoopTotals& totals) {
  ParticleArrays& p = world.particles;
  p.clear_forces();
  const double dt = world.dt, half_dt = 0.5 * dt;
  auto& pp = world.contacts.particle_pairs;
  const std::size_t n_pairs = pp.size();
  const Index* first = pp.first.data();
  const Index* second = pp.second.data();
  ContactHistory* history = pp.history.data();
  Vec3* force = p.force.data();
  Vec3* torque = p.torque.data();
  SerialSink sink{totals};
  for (std::size_t c = 0; c < n_pairs; ++c) {
    const Index i = first[c], j = second[c];
    V3 f, arm_i, arm_j;
    if (!particle_pair_force(normal_law, tangential_law, bond_law, bond_new_contacts, p, pairs, dt, half_dt, i, j,
                             history[c], f, arm_i, arm_j, sink))
      continue;
    add_to(force[j], f);
    sub_from(force[i], f);
    add_to(torque[j], cross(arm_j, f));
    sub_from(torque[i], cross(arm_i, f));
  }
}

// Threaded particle-pair loop. Phase 1: contiguous chunks of pairs (one per thread) store
// each pair's force and torques. Phase 2: each particle sums its pairs' contributions in
// pair order (its gather list), starting from zero. That is exactly the sequence of
// additions of the serial loop for that particle (x - f == x + (-f) in IEEE arithmetic,
// and a pair without force contributes +-0, which leaves a sum started at +0 unchanged),
// so forces and torques are bit-for-bit those of the serial loop at any thread count.
template <class Normal, class Tangential, class Bond>
[[gnu::flatten]] void particle_pairs_threaded(const Normal& normal_law, const Tangential& tangential_law,
                                               const Bond& bond_law, bool bond_new_contacts, World& world,
                                               const PairTable& pairs, ForceLoopTotals& totals, int threads,
                                               Stepper::GatherScratch& g) {
  ParticleArrays& p = world.particles;
  const double dt = world.dt, half_dt = 0.5 * dt;
  auto& pp = world.contacts.particle_pairs;
  const std::size_t n_pairs = pp.size(), n = p.size();
  const Index* first = pp.first.data();
  const Index* second = pp.second.data();
  ContactHistory* history = pp.history.data();
  Vec3* pair_force = g.pair_force.data();
  Vec3* torque_1 = g.torque_1.data();
  Vec3* torque_2 = g.torque_2.data();
  const Index* start = g.start.data();
  const Index* entries = g.entries.data();
  Vec3* force = p.force.data();
  Vec3* torque = p.torque.data();
  std::vector<LogSink> sinks(static_cast<std::size_t>(threads));
#pragma omp parallel num_threads(threads)
  {
#ifdef _OPENMP
    const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t nt = static_cast<std::size_t>(omp_get_num_threads());
#else
    const std::size_t t = 0, nt = 1;
#endif
    LogSink& sink = sinks[t];
    for (std::size_t c = n_pairs * t / nt, end = n_pairs * (t + 1) / nt; c < end; ++c) {
      const Index i = first[c], j = second[c];
      V3 f, arm_i, arm_j;
      if (!particle_pair_force(normal_law, tangential_law, bond_law, bond_new_contacts, p, pairs, dt, half_dt, i,
                               j, history[c], f, arm_i, arm_j, sink)) {
        pair_force[c].setZero();
        torque_1[c].setZero();
        torque_2[c].setZero();
        continue;
      }
      const V3 t1 = cross(arm_i, f), t2 = cross(arm_j, f);
      pair_force[c] = vec(f);
      torque_1[c] = Vec3(-t1.x, -t1.y, -t1.z);
      torque_2[c] = vec(t2);
    }
#pragma omp barrier
    for (std::size_t i = n * t / nt, end = n * (t + 1) / nt; i < end; ++i) {
      Vec3 fi = Vec3::Zero(), ti = Vec3::Zero();
      for (Index k = start[i]; k < start[i + 1]; ++k) {
        const Index e = entries[k], c = e >> 1;
        if (e & 1u) {  // body 1
          fi -= pair_force[c];
          ti += torque_1[c];
        } else {  // body 2
          fi += pair_force[c];
          ti += torque_2[c];
        }
      }
      force[i] = fi;
      torque[i] = ti;
    }
  }
  for (const LogSink& s : sinks) {  // chunk order = pair order
    for (double v : s.slips) totals.slip += v;
    for (double v : s.brokens) totals.broken += v;
    for (double v : s.releases) totals.released += v;
    totals.broken_tension += s.broken_tension;
    totals.broken_shear += s.broken_shear;
  }
}

// Sphere-wall pairs (serial, after the particle pairs, as in the reference loop).
template <class Normal, class Tangential>
[[gnu::flatten]] void wall_pairs_serial(const Normal& normal_law, const Tangential& tangential_law, World& world,
                                         const PairTable& pairs, ForceLoopTotals& totals) {
  ParticleArrays& p = world.particles;
  const double dt = world.dt, half_dt = 0.5 * dt;
  auto& pw = world.contacts.wall_pairs;
  for (auto& wall : world.walls) {
    wall.force.setZero();
    wall.contact_count = 0;
  }
  const std::size_t n_wall_pairs = pw.size();
  for (std::size_t c = 0; c < n_wall_pairs; ++c) {
    Wall& wall = world.walls[pw.wall[c]];
    const Index i = pw.particle[c];
    ContactHistory& h = pw.history[c];
    const WallContactGeometry g = wall_sphere_geometry(wall, p.position[i], p.radius[i]);
    if (!g.in_range || (!h.touching && g.overlap < 0.0)) {
      if (h.touching) h.reset();
      continue;
    }
    ContactKinematics k;
    k.normal = g.normal;
    k.overlap = g.overlap;
    const Vec3 arm = g.point - p.position[i];
    const Vec3 rel_vel = (p.velocity[i] + p.angular_velocity[i].cross(arm)) - wall.velocity;
    k.shear_increment = (rel_vel - rel_vel.dot(k.normal) * k.normal) * dt;
    k.twist_angle = half_dt * p.angular_velocity[i].dot(h.normal);  // previous normal
    const PairParameters& q = pairs.particle_wall(p.material[i], wall.material);
    const ContactOutcome out = evaluate_contact(normal_law, tangential_law, NoBond{}, q, k, h, false);
    if (!out.carries_force) continue;
    totals.slip += out.slip_dissipation;
    const Vec3& f = out.force_on_2;
    p.force[i] += f;
    p.torque[i] += arm.cross(f);
    wall.force -= f;
    ++wall.contact_count;
    totals.wall_power += f.dot(wall.velocity);  // power of the wall on the particle (W)
  }
}

}  // namespace

void Stepper::update_gather_lists(const World& world) {
  const auto& pp = world.contacts.particle_pairs;
  const std::size_t n_pairs = pp.size(), n = world.particles.size();
  GatherScratch& g = gather_;
  if (g.revision == world.contacts.revision() && g.first_data == pp.first.data() && g.n_pairs == n_pairs &&
      g.n_particles == n)
    return;
  g.start.assign(n + 1, 0);
  for (std::size_t c = 0; c < n_pairs; ++c) {
    ++g.start[pp.first[c] + 1];
    ++g.start[pp.second[c] + 1];
  }
  for (std::size_t i = 0; i < n; ++i) g.start[i + 1] += g.start[i];
  g.entries.resize(2 * n_pairs);
  std::vector<Index> fill(g.start.begin(), g.start.end() - 1);
  for (std::size_t c = 0; c < n_pairs; ++c) {  // increasing c: each list is in pair order
    g.entries[fill[pp.first[c]]++] = static_cast<Index>(2 * c + 1);
    g.entries[fill[pp.second[c]]++] = static_cast<Index>(2 * c);
  }
  g.pair_force.resize(n_pairs);
  g.torque_1.resize(n_pairs);
  g.torque_2.resize(n_pairs);
  g.revision = world.contacts.revision();
  g.first_data = pp.first.data();
  g.n_pairs = n_pairs;
  g.n_particles = n;
}

void Stepper::compute_forces(World& world) {
  const bool bond_new = physics_.model.bond_install == BondInstallMoment::kOnNewContacts;
  const int threads = worker_threads();
  const bool threaded = threads > 1 && world.contacts.particle_pairs.size() >= kMinPairsPerThread * 2;
  if (threaded) update_gather_lists(world);
  ForceLoopTotals totals;
  std::visit(
      [&](const auto& normal, const auto& tangential, const auto& bond) {
        if (threaded)
          particle_pairs_threaded(normal, tangential, bond, bond_new, world, pairs_, totals, threads, gather_);
        else
          particle_pairs_serial(normal, tangential, bond, bond_new, world, pairs_, totals);
        wall_pairs_serial(normal, tangential, world, pairs_, totals);
      },
      physics_.model.normal, physics_.model.tangential, physics_.model.bond);
  ledger_.slip_dissipated += totals.slip;
  ledger_.bond_break_lost += totals.broken;
  ledger_.shear_break_released += totals.released;
  ledger_.wall_work += totals.wall_power * world.dt;
  events_.bonds_broken_tension += totals.broken_tension;
  events_.bonds_broken_shear += totals.broken_shear;
}

void Stepper::begin_step(World& world) {
  if (physics_.time_step.automatic && physics_.time_step.recompute_interval > 0 &&
      world.step % physics_.time_step.recompute_interval == 0)
    update_time_step(world);
  if (neighbours_.needs_rebuild(world.particles, world.walls))
    neighbours_.rebuild(world.particles, world.walls, world.contacts);
  compute_forces(world);
}

void Stepper::finish_step(World& world) {
  last_integration_ = integrate_step(world.particles, physics_.integrator, world.dt, worker_threads(), gather_.unbalanced);
  ledger_.damping_dissipated += last_integration_.damping_work;
  for (auto& wall : world.walls) wall.origin += world.dt * wall.velocity;
  world.time += world.dt;
  ++world.step;
}

void Stepper::run(World& world, std::uint64_t steps) {
  for (std::uint64_t s = 0; s < steps; ++s) step(world);
}

}  // namespace colza
