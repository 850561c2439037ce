#include "engine/stepper.hpp"

#include <cmath>
#include <variant>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "contact/contact_law.hpp"
#include "engine/pair_batch.hpp"
#include "engine/pair_force.hpp"
#include "engine/pair_sinks.hpp"
#include "engine/wall_pair_force.hpp"

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

using detail::add_to;
using detail::cross;
using detail::particle_pair_force;
using detail::sub_from;
using detail::V3;
using detail::vec;
using detail::kHasBatchedKernel;
using detail::particle_pairs_batched;
using detail::wall_pair_force;
using detail::ForceLoopTotals;
using detail::LogSink;
using detail::SerialSink;

// Below this many candidate pairs per thread the force loop runs serially (threading
// overhead would dominate; also keeps tiny unit-test systems on the reference path).
constexpr std::size_t kMinPairsPerThread = 1024;
// Pairs per work item of the threaded force loop: small enough to balance the threads
// (contact states differ along the pair list), large enough to amortise the hand-out.
constexpr std::size_t kPairsPerChunk = 256;

int worker_threads() {
#ifdef _OPENMP
  return omp_in_parallel() ? 1 : omp_get_max_threads();
#else
  return 1;
#endif
}

// Where a pair's force goes. Serial: straight onto the bodies (body 2 gets +f and +t_j,
// body 1 gets -f and -t_i). Threaded: into per-pair buffers, gathered per particle later.
struct ScatterToBodies {
  Vec3* force;
  Vec3* torque;
  void carries(std::size_t, Index i, Index j, const V3& f, const V3& t_i, const V3& t_j) {
    add_to(force[j], f);
    sub_from(force[i], f);
    add_to(torque[j], t_j);
    sub_from(torque[i], t_i);
  }
  void none(std::size_t) {}
};
struct StoreByPair {
  Vec3* pair_force;
  Vec3* torque_1;
  Vec3* torque_2;
  void carries(std::size_t c, Index, Index, const V3& f, const V3& t_i, const V3& t_j) {
    pair_force[c] = vec(f);
    torque_1[c] = Vec3(-t_i.x, -t_i.y, -t_i.z);
    torque_2[c] = vec(t_j);
  }
  void none(std::size_t c) {
    pair_force[c].setZero();
    torque_1[c].setZero();
    torque_2[c].setZero();
  }
};

// Particle pairs [begin, end) in pair order: the batched kernel for the built-in law, the
// scalar reference for any other slot combination (same results, see pair_batch.hpp).
template <class Normal, class Tangential, class Bond, class Out, class Sink>
[[gnu::always_inline]] inline void particle_pair_range(const Normal& normal_law, const Tangential& tangential_law,
                                                       const Bond& bond_law, bool bond_new_contacts,
                                                       const ParticleArrays& p, const PairTable& pairs, double dt,
                                                       ParticlePairList& pp, std::size_t begin,
                                                       std::size_t end, Out& out, Sink& sink) {
  const double half_dt = 0.5 * dt;
  const Index* first = pp.first.data();
  const Index* second = pp.second.data();
  ContactHistory* history = pp.history.data();
  if constexpr (kHasBatchedKernel<Normal, Tangential>) {
    if (pairs.particle_material_count() == 1) {
      particle_pairs_batched(normal_law, tangential_law, bond_law, bond_new_contacts, p, pairs, dt, half_dt, first,
                             second, history, begin, end, out, sink);
      return;
    }
  }
  for (std::size_t c = begin; c < end; ++c) {
    const Index i = first[c], j = second[c];
    V3 f, arm_i, arm_j;
    if (particle_pair_force(normal_law, tangential_law, bond_law, bond_new_contacts, p, pairs, dt, half_dt, i, j,
                            history[c], f, arm_i, arm_j, sink))
      out.carries(c, i, j, f, cross(arm_i, f), cross(arm_j, f));
    else
      out.none(c);
  }
}

// Serial particle-pair loop: forces scattered straight onto the bodies.
template <class Normal, class Tangential, class Bond>
[[gnu::flatten]] void particle_pairs_serial(const Normal& normal_law, const Tangential& tangential_law,
                                             const Bond& bond_law, bool bond_new_contacts, World& world,
                                             const PairTable& pairs, ForceLoopTotals& totals) {
  ParticleArrays& p = world.particles;
  p.clear_forces();
  auto& pp = world.contacts.particle_pairs;
  ScatterToBodies out{p.force.data(), p.torque.data()};
  SerialSink sink{totals};
  particle_pair_range(normal_law, tangential_law, bond_law, bond_new_contacts, p, pairs, world.dt, pp, 0, pp.size(),
                      out, sink);
}

// Threaded particle-pair loop. Phase 1: fixed chunks of kPairsPerChunk contiguous pairs,
// handed to the threads dynamically (balances uneven chunks), store each pair's force and
// torques; which thread computes a chunk does not matter, each pair has its own slot and
// each chunk its own log. Phase 2: each particle sums its pairs' contributions in
// pair order (its gather list), starting from zero. That is exactly the sequence of
// additions of the serial loop for that particle (x - f == x + (-f) in IEEE arithmetic,
// and a pair without force contributes +-0, which leaves a sum started at +0 unchanged),
// so forces and torques are bit-for-bit those of the serial loop at any thread count.
//
// Sphere-wall pairs run in the same parallel phase (chunks of wall pairs, after the
// particle-pair chunks, into per-wall-pair buffers); each particle adds its wall pairs in wall-pair order after its
// particle pairs, as the serial loop does, and the walls' force sums, contact counts and
// power are then summed serially in wall-pair order. Same bits as the serial loops.
template <class Normal, class Tangential, class Bond>
[[gnu::flatten]] void all_pairs_threaded(const Normal& normal_law, const Tangential& tangential_law,
                                          const Bond& bond_law, bool bond_new_contacts, World& world,
                                          const PairTable& pairs, ForceLoopTotals& totals, int threads,
                                          Stepper::GatherScratch& g) {
  ParticleArrays& p = world.particles;
  auto& pp = world.contacts.particle_pairs;
  const std::size_t n_pairs = pp.size(), n = p.size();
  Vec3* pair_force = g.pair_force.data();
  Vec3* torque_1 = g.torque_1.data();
  Vec3* torque_2 = g.torque_2.data();
  const Index* start = g.start.data();
  const Index* entries = g.entries.data();
  Vec3* force = p.force.data();
  Vec3* torque = p.torque.data();
  auto& pw = world.contacts.wall_pairs;
  const std::size_t n_wall_pairs = pw.size();
  Vec3* wall_force = g.wall_force.data();
  Vec3* wall_torque = g.wall_torque.data();
  std::uint8_t* wall_carries = g.wall_carries.data();
  const Index* wall_start = g.wall_start.data();
  const Index* wall_entries = g.wall_entries.data();
  const double dt = world.dt, half_dt = 0.5 * dt;
  const std::size_t particle_chunks = (n_pairs + kPairsPerChunk - 1) / kPairsPerChunk;
  const std::size_t wall_chunks = (n_wall_pairs + kPairsPerChunk - 1) / kPairsPerChunk;
  const std::size_t n_chunks = particle_chunks + wall_chunks;
  std::vector<LogSink>& sinks = g.chunk_logs;  // chunk order = pair order, then wall-pair order
  sinks.resize(std::max(sinks.size(), n_chunks));
  for (std::size_t k = 0; k < n_chunks; ++k) sinks[k].clear();
#pragma omp parallel num_threads(threads)
  {
#ifdef _OPENMP
    const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t nt = static_cast<std::size_t>(omp_get_num_threads());
#else
    const std::size_t t = 0, nt = 1;
#endif
    StoreByPair out{pair_force, torque_1, torque_2};
#pragma omp for schedule(dynamic, 1)
    for (std::size_t k = 0; k < n_chunks; ++k) {
      if (k < particle_chunks) {
        particle_pair_range(normal_law, tangential_law, bond_law, bond_new_contacts, p, pairs, world.dt, pp,
                            k * kPairsPerChunk, std::min(n_pairs, (k + 1) * kPairsPerChunk), out, sinks[k]);
      } else {
        const std::size_t begin = (k - particle_chunks) * kPairsPerChunk;
        for (std::size_t c = begin, end = std::min(n_wall_pairs, begin + kPairsPerChunk); c < end; ++c)
          wall_carries[c] = wall_pair_force(normal_law, tangential_law, p, world.walls[pw.wall[c]], pairs, dt,
                                            half_dt, pw.particle[c], pw.history[c], wall_force[c], wall_torque[c],
                                            sinks[k]);
      }
    }  // implicit barrier: every pair is done before the gather
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
      for (Index k = wall_start[i]; k < wall_start[i + 1]; ++k) {
        const Index c = wall_entries[k];
        if (!wall_carries[c]) continue;
        fi += wall_force[c];
        ti += wall_torque[c];
      }
      force[i] = fi;
      torque[i] = ti;
    }
  }
  for (std::size_t k = 0; k < n_chunks; ++k) {  // chunk order = pair order, then wall-pair order
    const LogSink& s = sinks[k];
    for (double v : s.slips) totals.slip += v;
    for (double v : s.brokens) totals.broken += v;
    for (double v : s.releases) totals.released += v;
    totals.broken_tension += s.broken_tension;
    totals.broken_shear += s.broken_shear;
  }
  for (auto& wall : world.walls) {
    wall.force.setZero();
    wall.contact_count = 0;
  }
  for (std::size_t c = 0; c < n_wall_pairs; ++c) {
    if (!wall_carries[c]) continue;
    Wall& wall = world.walls[pw.wall[c]];
    wall.force -= wall_force[c];
    ++wall.contact_count;
    totals.wall_power += wall_force[c].dot(wall.velocity);  // power of the wall on the particle (W)
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
  SerialSink sink{totals};
  const std::size_t n_wall_pairs = pw.size();
  for (std::size_t c = 0; c < n_wall_pairs; ++c) {
    Wall& wall = world.walls[pw.wall[c]];
    const Index i = pw.particle[c];
    Vec3 f, torque;
    if (!wall_pair_force(normal_law, tangential_law, p, wall, pairs, dt, half_dt, i, pw.history[c], f, torque, sink))
      continue;
    p.force[i] += f;
    p.torque[i] += torque;
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
  const auto& pw = world.contacts.wall_pairs;
  const std::size_t n_wall_pairs = pw.size();
  g.wall_start.assign(n + 1, 0);
  for (std::size_t c = 0; c < n_wall_pairs; ++c) ++g.wall_start[pw.particle[c] + 1];
  for (std::size_t i = 0; i < n; ++i) g.wall_start[i + 1] += g.wall_start[i];
  g.wall_entries.resize(n_wall_pairs);
  fill.assign(g.wall_start.begin(), g.wall_start.end() - 1);
  for (std::size_t c = 0; c < n_wall_pairs; ++c) g.wall_entries[fill[pw.particle[c]]++] = static_cast<Index>(c);
  g.wall_force.resize(n_wall_pairs);
  g.wall_torque.resize(n_wall_pairs);
  g.wall_carries.resize(n_wall_pairs);
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
        if (threaded) {
          all_pairs_threaded(normal, tangential, bond, bond_new, world, pairs_, totals, threads, gather_);
        } else {
          particle_pairs_serial(normal, tangential, bond, bond_new, world, pairs_, totals);
          wall_pairs_serial(normal, tangential, world, pairs_, totals);
        }
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
