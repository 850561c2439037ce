// The force loops' definition (engine/force_loops.hpp), compiled once per instruction set:
// included only by engine/isa/force_loops_<isa>.cpp, which names the copy's namespace
// (COLZA_KERNEL_NAMESPACE: kernels_generic, kernels_avx2, kernels_avx512) and is compiled with
// that instruction set's -march (src/CMakeLists.txt).
//
// Code built for one instruction set must never run on a CPU without it. Here everything but
// the copy's entry point, force_loops, has internal linkage (an unnamed namespace), and the
// wider copies are compiled with -fno-weak: the inline functions and template instantiations
// of the headers below (colza's, Eigen's, the standard library's) become private copies in
// their object file instead of weak symbols, of which the linker keeps one for all callers
// and could keep the AVX-512 one. The test kernel_objects_export_only_their_entry
// (tests/kernel_objects_symbols.cmake) checks those object files' symbols.
#ifndef COLZA_KERNEL_NAMESPACE
#error "engine/force_loops_body.hpp is compiled by engine/isa/force_loops_<isa>.cpp only"
#endif

#include <chrono>
#include <cmath>
#include <type_traits>
#include <variant>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "contact/contact_law.hpp"
#include "engine/force_loops.hpp"
#include "engine/force_outputs.hpp"
#include "engine/force_partition.hpp"
#include "engine/generic_pair_force.hpp"
#include "engine/load_induced_lanes.hpp"
#include "engine/pair_batch.hpp"
#include "engine/pair_force.hpp"
#include "engine/pair_sinks.hpp"
#include "engine/damped_lanes.hpp"
#include "engine/rolling_lanes.hpp"
#include "engine/viscous_lanes.hpp"
#include "engine/wall_batch.hpp"
#include "engine/wall_pair_force.hpp"
#include "engine/walton_braun_lanes.hpp"

namespace colza::COLZA_KERNEL_NAMESPACE {

namespace {

using detail::cross;
using detail::generic_particle_pair_force;
using detail::generic_wall_pair_force;
using detail::particle_pair_force;
using detail::V3;
using detail::kHasBatchedKernel;
using detail::particle_pairs_batched;
using detail::particle_pairs_in_lanes;
using detail::PairBatch;
using detail::RollingLanes;
using detail::ViscousLanes;
using detail::DampedLanes;
using detail::WaltonBraunLanes;
using detail::LoadInducedLanes;
using detail::wall_pair_force;
using detail::wall_pairs_batched;
using detail::ForceLoopTotals;
using detail::LogSink;
using detail::SerialSink;
using detail::with_slip_if;
using detail::clear_wall_sums;
using detail::ScatterOrStore;
using detail::ScatterToBodies;
using detail::StoreWallForce;
using detail::wall_takes;
using detail::WallTakesForce;

double seconds_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The two tiers of the contact law, as the force loops take them. BaselineLaw: the linear
// spring, the Coulomb cap and `Bond` (none or the contact bond), compiled for that bond and
// computed by the batched kernels. GenericLaw: any slot combination, chosen per contact at
// run time (contact/generic_law.hpp), with the slots' state rows.
template <class Bond>
struct BaselineLaw {
  LinearNormal normal;
  CoulombTangential tangential;
  const Bond& bond;
  bool bond_new_contacts;
};
struct GenericLaw {
  const ContactModel& model;
  const SlotStateLayout& layout;
  bool bond_new_contacts;
};
// MechanismLaw: the baseline's slots with one mechanism the lanes compute, or viscous damping
// and one other (`Mechanism`: the elastic-plastic rolling moment, viscous dashpots, the
// Walton-Braun normal law, load-induced cohesion, or ViscousWith one of the others;
// with_lane_mechanism): particle pairs in the batched kernels with the mechanism's lanes
// (engine/rolling_lanes.hpp, viscous_lanes.hpp, walton_braun_lanes.hpp,
// load_induced_lanes.hpp, damped_lanes.hpp), compiled for `Bond` and the mechanism; the generic law for the
// pairs that are not steady lanes, for wall pairs, for several particle materials and for
// dt = 0 (where the generic law leaves out the tangential dashpot). Same
// bits as the generic law (ForcePaths.TheMechanismLanesGiveTheGenericTierBits).
template <class Bond, class Mechanism>
struct MechanismLaw {
  const Bond& bond;
  const Mechanism& mechanism;
  GenericLaw generic;
};
template <class Law>
inline constexpr bool kIsMechanismLaw = false;
template <class Bond, class Mechanism>
inline constexpr bool kIsMechanismLaw<MechanismLaw<Bond, Mechanism>> = true;

// The lanes of a mechanism over the pairs' slot-state rows `state`.
inline RollingLanes<PairBatch::kLanes> lanes_of(const ElasticPlasticRolling& rolling, double* state,
                                                const SlotStateLayout& layout) {
  return RollingLanes<PairBatch::kLanes>(rolling, state, layout.stride, layout.rolling);
}
inline ViscousLanes<PairBatch::kLanes> lanes_of(const ViscousDamping& viscous, double*, const SlotStateLayout&) {
  return ViscousLanes<PairBatch::kLanes>(viscous);
}
inline WaltonBraunLanes<PairBatch::kLanes> lanes_of(const WaltonBraunNormal& normal, double* state,
                                                    const SlotStateLayout& layout) {
  return WaltonBraunLanes<PairBatch::kLanes>(normal, state, layout.stride, layout.normal);
}
inline LoadInducedLanes<PairBatch::kLanes> lanes_of(const LoadInducedBond& bond, double* state,
                                                    const SlotStateLayout& layout) {
  return LoadInducedLanes<PairBatch::kLanes>(bond, state, layout.stride, layout.bond);
}
// Viscous damping together with another lane mechanism (`Other`).
template <class Other>
struct ViscousWith {
  const ViscousDamping& viscous;
  const Other& other;
};
template <class Other>
inline auto lanes_of(const ViscousWith<Other>& m, double* state, const SlotStateLayout& layout) {
  using OtherLanes = decltype(lanes_of(m.other, state, layout));
  return DampedLanes<PairBatch::kLanes, OtherLanes>(lanes_of(m.viscous, state, layout),
                                                    lanes_of(m.other, state, layout));
}
// Load-induced cohesion runs the lanes' contact-bond rule with each lane's strengths
// (LoadInducedLanes): this bond's own strengths are never read.
constexpr ContactBond kStrengthsPerLane{};
// Whether a lane mechanism brings the bonds' strengths (load-induced cohesion, alone or damped).
template <class Mechanism>
inline constexpr bool kBringsBondStrengths = std::is_same_v<Mechanism, LoadInducedBond>;
template <class Other>
inline constexpr bool kBringsBondStrengths<ViscousWith<Other>> = kBringsBondStrengths<Other>;

// Calls f(mechanism) when the model is the baseline's slots (linear, Coulomb, no damping, no
// rolling, no bond or the contact bond) with one of them changed to a mechanism the lanes
// compute (the elastic-plastic rolling moment, viscous damping, the Walton-Braun normal law
// or load-induced cohesion), or with viscous damping and one other (ViscousWith). Returns
// whether it did.
template <class F>
bool with_lane_mechanism(const ContactModel& m, F&& f) {
  if (!std::holds_alternative<CoulombTangential>(m.tangential)) return false;
  const auto* rolling = std::get_if<ElasticPlasticRolling>(&m.rolling);
  const auto* viscous = std::get_if<ViscousDamping>(&m.damping);
  const auto* walton_braun = std::get_if<WaltonBraunNormal>(&m.normal);
  const auto* load_induced = std::get_if<LoadInducedBond>(&m.bond);
  const bool linear = std::holds_alternative<LinearNormal>(m.normal);
  const int others = (rolling != nullptr) + (walton_braun != nullptr) + (load_induced != nullptr);
  if (others > 1 || others + (viscous != nullptr) == 0 || !(linear || walton_braun)) return false;
  const auto with_dashpots = [&](const auto& other) {
    if (viscous)
      f(ViscousWith<std::decay_t<decltype(other)>>{*viscous, other});
    else
      f(other);
  };
  if (rolling) with_dashpots(*rolling);
  else if (walton_braun) with_dashpots(*walton_braun);
  else if (load_induced) with_dashpots(*load_induced);
  else f(*viscous);
  return true;
}

// Particle pairs [begin, end) in pair order: the batched kernel for the baseline with one
// particle material, the scalar reference otherwise (same results, see pair_batch.hpp); the
// generic law for the generic tier.
template <class Law, class Out, class Sink>
[[gnu::always_inline]] inline void particle_pair_range(const Law& law, const ParticleArrays& p, const PairTable& pairs,
                                                       double dt, ParticlePairList& pp, std::size_t begin,
                                                       std::size_t end, Out& out, Sink& sink) {
  const double half_dt = 0.5 * dt;
  const Index* first = pp.first.data();
  const Index* second = pp.second.data();
  ContactHistory* history = pp.history.data();
  if constexpr (kIsMechanismLaw<Law>) {
    if (pairs.particle_material_count() != 1 || !(dt > 0.0)) {
      particle_pair_range(law.generic, p, pairs, dt, pp, begin, end, out, sink);
      return;
    }
    const GenericLaw& generic = law.generic;
    const std::size_t stride = generic.layout.stride;
    double* state = pp.slot_state.data();
    auto mechanism = lanes_of(law.mechanism, state, generic.layout);
    const auto scalar_pair = [&](std::size_t k, V3& f, V3& t_i, V3& t_j) {
      return generic_particle_pair_force(generic.model, generic.layout, generic.bond_new_contacts, p, pairs, dt,
                                         half_dt, first[k], second[k], history[k], state + k * stride, f, t_i, t_j,
                                         sink);
    };
    particle_pairs_in_lanes(law.bond, mechanism, scalar_pair, p, pairs, dt, half_dt, first, second, history, begin,
                            end, out, sink);
  } else if constexpr (std::is_same_v<Law, GenericLaw>) {
    const std::size_t stride = law.layout.stride;
    double* state = pp.slot_state.data();
    for (std::size_t c = begin; c < end; ++c) {
      const Index i = first[c], j = second[c];
      V3 f, t_i, t_j;
      if (generic_particle_pair_force(law.model, law.layout, law.bond_new_contacts, p, pairs, dt, half_dt, i, j,
                                      history[c], state + c * stride, f, t_i, t_j, sink))
        out.carries(c, i, j, f, t_i, t_j);
      else
        out.none(c);
    }
  } else {
    if (pairs.particle_material_count() == 1) {
      particle_pairs_batched(law.normal, law.tangential, law.bond, law.bond_new_contacts, p, pairs, dt, half_dt, first,
                             second, history, begin, end, out, sink);
      return;
    }
    for (std::size_t c = begin; c < end; ++c) {
      const Index i = first[c], j = second[c];
      V3 f, arm_i, arm_j;
      if (particle_pair_force(law.normal, law.tangential, law.bond, law.bond_new_contacts, p, pairs, dt, half_dt, i,
                              j, history[c], f, arm_i, arm_j, sink))
        out.carries(c, i, j, f, cross(arm_i, f), cross(arm_j, f));
      else
        out.none(c);
    }
  }
}

// Wall pairs [begin, end) of one wall in pair order: the batched kernel for the baseline with
// one particle material, the scalar function otherwise (same results, see wall_batch.hpp); the
// generic law for the generic tier. `out.carries(c, i, f, torque)`, `out.none(c)` as in
// wall_pairs_batched.
template <class Law, class Out, class Sink>
[[gnu::always_inline]] inline void wall_pair_range(const Law& law, const ParticleArrays& p, const Wall& wall,
                                                   const PairTable& pairs, double dt, WallPairList& pw,
                                                   std::size_t begin, std::size_t end, Out& out, Sink& sink) {
  const double half_dt = 0.5 * dt;
  const Index* particle = pw.particle.data();
  ContactHistory* history = pw.history.data();
  if constexpr (kIsMechanismLaw<Law>) {
    wall_pair_range(law.generic, p, wall, pairs, dt, pw, begin, end, out, sink);
  } else if constexpr (std::is_same_v<Law, GenericLaw>) {
    const std::size_t stride = law.layout.stride;
    double* state = pw.slot_state.data();
    for (std::size_t c = begin; c < end; ++c) {
      Vec3 f, torque;
      if (generic_wall_pair_force(law.model, law.layout, p, wall, pairs, dt, half_dt, particle[c], history[c],
                                  state + c * stride, f, torque, sink))
        out.carries(c, particle[c], f, torque);
      else
        out.none(c);
    }
  } else {
    if (pairs.particle_material_count() == 1) {
      wall_pairs_batched(law.normal, law.tangential, p, wall, pairs, dt, half_dt, particle, history, begin, end, out,
                         sink);
      return;
    }
    for (std::size_t c = begin; c < end; ++c) {
      Vec3 f, torque;
      if (wall_pair_force(law.normal, law.tangential, p, wall, pairs, dt, half_dt, particle[c], history[c], f, torque,
                          sink))
        out.carries(c, particle[c], f, torque);
      else
        out.none(c);
    }
  }
}

// Serial particle-pair loop: forces scattered straight onto the bodies. kSlip: sum the slip
// energy (the energy ledger is kept).
template <bool kSlip, class Law>
[[gnu::flatten]] void particle_pairs_serial(const Law& law, World& world, const PairTable& pairs,
                                             ForceLoopTotals& totals) {
  ParticleArrays& p = world.particles;
  p.clear_forces();
  auto& pp = world.contacts.particle_pairs;
  ScatterToBodies out{p.force.data(), p.torque.data()};
  SerialSink serial{totals};
  with_slip_if<kSlip>(serial, [&](auto& sink) {
    particle_pair_range(law, p, pairs, world.dt, pp, 0, pp.size(), out, sink);
  });
}

// Threaded force loop (particle and wall pairs), partitioned as engine/force_partition.hpp
// explains. Phase 1: each thread computes the pairs of its particle range, scattering to
// inner bodies at once and storing pairs with a boundary body in slots. Barrier. Phase 2,
// over the finishing ranges (a cut of its own, balanced on phase 2's time): each thread sums
// the boundary particles of its range from the slots in pair order, starting from zero
// (the serial loop's sequence of additions: x - f == x + (-f) in IEEE arithmetic, and a
// pair without force adds +-0 to a sum started at +0, which changes nothing), then computes
// the wall pairs of its range's particles wall by wall (each particle: increasing wall =
// wall-pair order) and adds them. The walls' force sums, contact counts and power are summed
// serially in wall-pair order, and the logs replayed in pair order, then wall-pair order.
// Forces, torques, walls and ledger terms are those of the serial loops, bit for bit, at
// any thread count. kSlip as in particle_pairs_serial.
//
// With `motion` (not null), each thread then advances the particles of its finishing range
// (integrate_motion): their forces are final after its phase 2, and no other thread reads
// them after the barrier (phase 2 touches only its range's particles, the slots and the
// walls).
template <bool kSlip, class Law>
[[gnu::flatten]] void all_pairs_threaded(const Law& law, World& world, const PairTable& pairs,
                                          ForceLoopTotals& totals, ForcePartition& part,
                                          const IntegratorSettings* motion) {
  ParticleArrays& p = world.particles;
  auto& pp = world.contacts.particle_pairs;
  auto& pw = world.contacts.wall_pairs;
  const std::size_t n_walls = world.walls.size(), T = static_cast<std::size_t>(part.threads);
  Vec3* force = p.force.data();
  Vec3* torque = p.torque.data();
  const double dt = world.dt;
  ++part.steps_since_build;
  for (auto& log : part.pair_logs) log.clear();
  for (auto& log : part.wall_logs) log.clear();
#pragma omp parallel num_threads(part.threads)
  {
#ifdef _OPENMP
    const std::size_t first_range = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t stride = static_cast<std::size_t>(omp_get_num_threads());
#else
    const std::size_t first_range = 0, stride = 1;
#endif
    ScatterOrStore out{force, torque, part.slot.data(), part.boundary.data(), part.slot_force.data(),
                       part.slot_torque_1.data(), part.slot_torque_2.data()};
    double started = seconds_now();
    for (std::size_t r = first_range; r < T; r += stride) {
      std::fill(force + part.particle_begin[r], force + part.particle_begin[r + 1], Vec3::Zero());
      std::fill(torque + part.particle_begin[r], torque + part.particle_begin[r + 1], Vec3::Zero());
      with_slip_if<kSlip>(part.pair_logs[r], [&](auto& sink) {
        particle_pair_range(law, p, pairs, dt, pp, part.pair_begin[r], part.pair_begin[r + 1], out, sink);
      });
    }
    const double pair_busy = seconds_now() - started;
#pragma omp barrier
    started = seconds_now();
    const Index* start = part.gather_start.data();
    const Index* entries = part.gather_entries.data();
    const Vec3* slot_force = part.slot_force.data();
    const Vec3* slot_torque_1 = part.slot_torque_1.data();
    const Vec3* slot_torque_2 = part.slot_torque_2.data();
    StoreWallForce wall_out{force, torque, part.wall_force.data(), part.wall_carries.data()};
    for (std::size_t r = first_range; r < T; r += stride) {  // finishing ranges
      for (std::size_t b = part.boundary_begin[r]; b < part.boundary_begin[r + 1]; ++b) {
        Vec3 fi = Vec3::Zero(), ti = Vec3::Zero();
        for (Index k = start[b]; k < start[b + 1]; ++k) {
          const Index e = entries[k], s = e >> 1;
          if (e & 1u) {  // body 1
            fi -= slot_force[s];
            ti += slot_torque_1[s];
          } else {  // body 2
            fi += slot_force[s];
            ti += slot_torque_2[s];
          }
        }
        force[part.boundary_particles[b]] = fi;
        torque[part.boundary_particles[b]] = ti;
      }
      for (std::size_t w = 0; w < n_walls; ++w)
        with_slip_if<kSlip>(part.wall_logs[w * T + r], [&](auto& sink) {
          wall_pair_range(law, p, world.walls[w], pairs, dt, pw, part.wall_pair_begin[w * (T + 1) + r],
                          part.wall_pair_begin[w * (T + 1) + r + 1], wall_out, sink);
        });
      if (motion) integrate_motion(p, *motion, dt, part.finish_begin[r], part.finish_begin[r + 1]);
    }
    const double finish_busy = seconds_now() - started;
    // Measured cost of this thread's ranges in each phase, for the next partition (balance only).
    const double my_ranges = static_cast<double>((T - first_range + stride - 1) / stride);
    for (std::size_t r = first_range; r < T; r += stride) {
      part.pair_busy_seconds[r] += pair_busy / my_ranges;
      part.finish_busy_seconds[r] += finish_busy / my_ranges;
    }
  }
  for (const LogSink& s : part.pair_logs) s.replay_into(totals);  // range order = pair order
  for (const LogSink& s : part.wall_logs) s.replay_into(totals);  // [w * T + t]: wall-pair order
  clear_wall_sums(world.walls);
  for (std::size_t c = 0; c < pw.size(); ++c)
    if (part.wall_carries[c]) wall_takes(world.walls[pw.wall[c]], part.wall_force[c], totals);
}

// Sphere-wall pairs (serial, after the particle pairs, as in the reference loop). kSlip as in
// particle_pairs_serial.
template <bool kSlip, class Law>
[[gnu::flatten]] void wall_pairs_serial(const Law& law, World& world, const PairTable& pairs,
                                         ForceLoopTotals& totals) {
  ParticleArrays& p = world.particles;
  const double dt = world.dt;
  auto& pw = world.contacts.wall_pairs;
  clear_wall_sums(world.walls);
  SerialSink serial{totals};
  // Wall pairs are sorted by wall: one segment per wall, in wall-pair order.
  for (std::size_t begin = 0, end = 0; begin < pw.size(); begin = end) {
    Wall& wall = world.walls[pw.wall[begin]];
    end = begin;
    while (end < pw.size() && pw.wall[end] == pw.wall[begin]) ++end;
    WallTakesForce out{p.force.data(), p.torque.data(), wall, totals};
    with_slip_if<kSlip>(serial, [&](auto& sink) {
      wall_pair_range(law, p, wall, pairs, dt, pw, begin, end, out, sink);
    });
  }
}

}  // namespace

// The law the model asks for, instantiated per bond (and mechanism) through one std::visit per
// step; the baseline and the lane mechanisms take the batched kernels, anything else the
// generic tier.
void force_loops(const ForceLoopJob& job, ForceLoopTotals& totals) {
  const PhysicsSettings& physics = job.physics;
  World& world = job.world;
  const PairTable& pairs = job.pairs;
  const bool bond_new = physics.model.bond_install == BondInstallMoment::kOnNewContacts;
  const auto force_loop = [&](auto keep_slip) {
    constexpr bool kSlip = decltype(keep_slip)::value;
    const auto run = [&](const auto& law) {
      if (job.partition) {
        all_pairs_threaded<kSlip>(law, world, pairs, totals, *job.partition, job.motion);
      } else {
        particle_pairs_serial<kSlip>(law, world, pairs, totals);
        wall_pairs_serial<kSlip>(law, world, pairs, totals);
      }
    };
    if (is_baseline(physics.model) && !physics.generic_tier_only) {
      std::visit(
          [&](const auto& bond) {
            using Bond = std::decay_t<decltype(bond)>;
            if constexpr (kHasBatchedKernel<LinearNormal, CoulombTangential, Bond>)
              run(BaselineLaw<Bond>{LinearNormal{}, CoulombTangential{}, bond, bond_new});
          },
          physics.model.bond);
    } else {
      const GenericLaw generic{physics.model, world.contacts.slot_state_layout(), bond_new};
      const auto in_lanes = [&](const auto& mechanism) {
        using Mechanism = std::decay_t<decltype(mechanism)>;
        if constexpr (kBringsBondStrengths<Mechanism>) {
          run(MechanismLaw<ContactBond, Mechanism>{kStrengthsPerLane, mechanism, generic});
        } else {
          std::visit(
              [&](const auto& bond) {
                using Bond = std::decay_t<decltype(bond)>;
                if constexpr (kHasBatchedKernel<LinearNormal, CoulombTangential, Bond>)
                  run(MechanismLaw<Bond, Mechanism>{bond, mechanism, generic});
              },
              physics.model.bond);
        }
      };
      if (physics.generic_tier_only || !with_lane_mechanism(physics.model, in_lanes)) run(generic);
    }
  };
  if (job.keep_slip)
    force_loop(std::true_type{});
  else
    force_loop(std::false_type{});
}

}  // namespace colza::COLZA_KERNEL_NAMESPACE
