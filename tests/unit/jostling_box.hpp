// A dense, jostling packing of 1200 spheres in a closed box that runs 300 steps on a chosen
// force-loop path (tests/unit/test_force_paths.cpp, test_kernel_isa.cpp): several thousand
// candidate pairs (above the threaded path's threshold of 2048), friction sliding, contacts
// forming and separating, bonds holding and breaking, walls moving, optional shaped walls and
// mechanisms; and the bit-for-bit comparisons of two runs' states.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_real_distribution.hpp>

#include "engine/stepper.hpp"

namespace jostling_box {

using namespace colza;

constexpr double kRadius = 3e-3;  // m
constexpr int kSites[3] = {10, 10, 12};  // lattice sites along x, y, z: 1200 spheres

struct Setup {
  int particle_materials = 1;  // 2 identical materials force the scalar reference loop
  bool bonds = false;
  bool walls_only_between_halves = false;  // no integration sums; motion may go into the threaded force loop
  bool shaped_walls = false;  // a cylinder and a rectangle (face, edge and corner contacts) besides planes
  bool restricted_plate_edges = false;  // with shaped_walls: two of the rectangle's edges restricted (walls/wall.hpp)
  double skin = 0.3e-3;       // m; 2.5 mm makes the diagonal lattice neighbours candidates that stay apart
  int rebuild_every = 0;      // > 0: also rebuild the candidate lists every this many steps
  bool generic_tier = false;  // run the generic law even for the baseline (contact/generic_law.hpp)
  bool mechanisms = false;    // rolling resistance, viscous dashpots and the elasto-plastic normal law on
  bool rolling = false;       // rolling resistance alone on the paper's law (its lanes in the batched kernel)
  RollingForm rolling_form = RollingForm::kYade;
  double rolling_damping = 0.0;  // eta_r of the rolling dashpot
  bool viscous = false;       // viscous dashpots alone on the paper's law (their lanes in the batched kernel)
  bool walton_braun = false;  // the Walton-Braun normal law alone in place of the linear spring (its lanes)
  bool load_induced = false;  // load-induced cohesion alone (its lanes): bonds forming under load and breaking
};

inline World make_world(const Setup& setup) {
  World w;
  boost::random::mt19937_64 rng(7);
  boost::random::uniform_real_distribution<double> jitter(-0.15e-3, 0.15e-3), speed(-0.05, 0.05);
  const double spacing = 2.0 * kRadius - 0.2e-3;  // lattice neighbours overlap by ~0.2 mm on average
  int placed = 0;
  for (int iz = 0; iz < kSites[2]; ++iz)
    for (int iy = 0; iy < kSites[1]; ++iy)
      for (int ix = 0; ix < kSites[0]; ++ix, ++placed) {
        const Vec3 x(ix * spacing + jitter(rng), iy * spacing + jitter(rng), iz * spacing + jitter(rng));
        const Vec3 v(speed(rng), speed(rng), speed(rng));
        const Vec3 spin(100.0 * speed(rng), 100.0 * speed(rng), 100.0 * speed(rng));
        const std::uint16_t material = static_cast<std::uint16_t>(placed % setup.particle_materials);
        w.particles.add(x, kRadius * (1.0 + 0.01 * jitter(rng) / 0.15e-3), 1250.0, material, v, spin);
      }
  // A closed box just around the lattice keeps the packing dense (walls slightly squeeze it).
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = -kRadius + 0.1e-3, hi = (kSites[axis] - 1) * spacing + kRadius - 0.1e-3;
    Vec3 n = Vec3::Zero();
    n[axis] = 1.0;
    w.walls.push_back(Wall::plane("low" + std::to_string(axis), lo * n, n));
    w.walls.push_back(Wall::plane("high" + std::to_string(axis), hi * n, -n));
  }
  w.walls.back().velocity = Vec3(0.002, 0.001, -0.02);  // the lid squeezes and drags (wall power, slip on walls)
  if (setup.shaped_walls) {
    // The low-x plane becomes a rectangle in the same plane whose edges lie 0.3 mm short of
    // lattice rows y = 2, 7 and z = 2, 8: the spheres of those rows touch an edge (or a
    // corner) at about 0.1 mm of overlap, those inside touch the face.
    const double lo = -kRadius + 0.1e-3;
    w.walls[0] = Wall::rectangle("plate", Vec3(lo, 4.5 * spacing, 5.0 * spacing), Vec3::UnitX(), Vec3::UnitY(),
                                 2.5 * spacing - 0.3e-3, 3.0 * spacing - 0.3e-3);
    w.walls[0].velocity = Vec3(0.0, 0.003, 0.001);  // sliding in its plane: slip on the face and edges
    if (setup.restricted_plate_edges) {  // beyond the +y edge no contact, beyond the -z edge only in front
      w.walls[0].edges.u_max = EdgeContact::kNone;
      w.walls[0].edges.v_min = EdgeContact::kFrontOnly;
    }
    // A vertical cylinder around the lattice that clips its four corner columns by ~0.1 mm.
    const double centre = 4.5 * spacing;
    w.walls.push_back(Wall::cylinder("envelope", Vec3(centre, centre, 0.0), Vec3::UnitZ(),
                                     std::sqrt(2.0) * centre + kRadius - 0.1e-3, -1.0, 1.0));
  }
  return w;
}

inline PhysicsSettings physics(const Setup& setup) {
  PhysicsSettings s;
  for (int m = 0; m < setup.particle_materials; ++m)
    s.particle_materials.push_back({"seed" + std::to_string(m), 1250.0, 437e3, 100e3, 0.2});
  s.wall_materials = {{"steel", 4000e3, 1000e3, 0.23}};
  s.model.normal = LinearNormal{};
  s.model.tangential = CoulombTangential{};
  if (setup.bonds) {
    s.model.bond = ContactBond{0.05, 0.08};  // weak: some bonds break in tension, some in shear
    s.model.bond_install = BondInstallMoment::kOnNewContacts;
  }
  s.generic_tier_only = setup.generic_tier;
  if (setup.mechanisms) {
    s.model.normal = WaltonBraunNormal{2.0};
    s.model.damping = ViscousDamping{0.2, 0.1};
    s.model.rolling = ElasticPlasticRolling{1.0, 0.1, RollingForm::kYade, true, 0.3};
  }
  if (setup.rolling) s.model.rolling = ElasticPlasticRolling{1.0, 0.05, setup.rolling_form, true, setup.rolling_damping};
  if (setup.viscous) s.model.damping = ViscousDamping{0.3, 0.2};
  if (setup.walton_braun) s.model.normal = WaltonBraunNormal{2.0};
  if (setup.load_induced) s.model.bond = LoadInducedBond{0.02, 1.0, 1.5, 0.08, 0.1};
  s.integrator.damping = 0.3;
  s.integrator.gravity = Vec3(0.0, 0.0, -9.81);
  s.time_step.automatic = false;
  s.time_step.fixed_dt = 5e-6;
  s.skin = setup.skin;
  return s;
}

struct PathRun {
  World world;
  std::uint64_t steps = 0;
  std::size_t max_pairs = 0;
  std::uint64_t broken_tension = 0, broken_shear = 0;
  EnergyLedger ledger;
  std::uint64_t threaded_steps = 0;
  std::uint64_t motion_with_forces_steps = 0;
};

inline PathRun run_path(const Setup& setup, int threads) {
#ifdef _OPENMP
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
#else
  (void)threads;
#endif
  PathRun r{make_world(setup)};
  Stepper stepper(physics(setup));
  stepper.prepare(r.world);
  if (setup.walls_only_between_halves) {
    stepper.set_integration_sums({.unbalanced = false, .damping_work = false});
    stepper.set_between_halves(Stepper::BetweenHalves::kWallsOnly);
  }
  for (int s = 0; s < 300; ++s) {
    if (setup.rebuild_every > 0 && s % setup.rebuild_every == 0) stepper.rebuild_neighbours(r.world);
    stepper.step(r.world);
    r.max_pairs = std::max(r.max_pairs, r.world.contacts.particle_pairs.size());
  }
  r.broken_tension = stepper.events().bonds_broken_tension;
  r.broken_shear = stepper.events().bonds_broken_shear;
  r.ledger = stepper.ledger();
  r.threaded_steps = stepper.threaded_force_steps();
  r.motion_with_forces_steps = stepper.motion_with_forces_steps();
#ifdef _OPENMP
  omp_set_num_threads(saved);
#endif
  return r;
}

template <class T>
inline bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// Positions, velocities, spins, forces and torques, to the last bit.
inline void expect_same_particles(const World& a, const World& b) {
  EXPECT_TRUE(same_bits(a.particles.position, b.particles.position));
  EXPECT_TRUE(same_bits(a.particles.velocity, b.particles.velocity));
  EXPECT_TRUE(same_bits(a.particles.angular_velocity, b.particles.angular_velocity));
  EXPECT_TRUE(same_bits(a.particles.force, b.particles.force));
  EXPECT_TRUE(same_bits(a.particles.torque, b.particles.torque));
}

inline void expect_same_state(const World& a, const World& b) {
  expect_same_particles(a, b);
  const auto& ha = a.contacts.particle_pairs.history;
  const auto& hb = b.contacts.particle_pairs.history;
  ASSERT_EQ(ha.size(), hb.size());
  for (std::size_t c = 0; c < ha.size(); ++c) {
    ASSERT_EQ(std::memcmp(ha[c].shear_force.data(), hb[c].shear_force.data(), sizeof(Vec3)), 0) << "pair " << c;
    ASSERT_EQ(std::memcmp(ha[c].normal.data(), hb[c].normal.data(), sizeof(Vec3)), 0) << "pair " << c;
    ASSERT_EQ(std::memcmp(&ha[c].normal_force, &hb[c].normal_force, sizeof(double)), 0) << "pair " << c;
    ASSERT_EQ(ha[c].touching, hb[c].touching) << "pair " << c;
    ASSERT_EQ(ha[c].bonded, hb[c].bonded) << "pair " << c;
  }
  const auto& wa = a.contacts.wall_pairs.history;
  const auto& wb = b.contacts.wall_pairs.history;
  ASSERT_EQ(wa.size(), wb.size());
  for (std::size_t c = 0; c < wa.size(); ++c) {
    ASSERT_EQ(std::memcmp(wa[c].shear_force.data(), wb[c].shear_force.data(), sizeof(Vec3)), 0) << "wall pair " << c;
    ASSERT_EQ(wa[c].touching, wb[c].touching) << "wall pair " << c;
  }
  EXPECT_TRUE(same_bits(a.contacts.particle_pairs.slot_state, b.contacts.particle_pairs.slot_state));
  EXPECT_TRUE(same_bits(a.contacts.wall_pairs.slot_state, b.contacts.wall_pairs.slot_state));
  ASSERT_EQ(a.walls.size(), b.walls.size());
  for (std::size_t w = 0; w < a.walls.size(); ++w) {
    EXPECT_EQ(std::memcmp(a.walls[w].force.data(), b.walls[w].force.data(), sizeof(Vec3)), 0) << "wall " << w;
    EXPECT_EQ(a.walls[w].contact_count, b.walls[w].contact_count) << "wall " << w;
  }
}

// The ledger terms summed in pair order (the damping work is summed per thread range).
inline void expect_same_pair_energies(const EnergyLedger& a, const EnergyLedger& b) {
  EXPECT_EQ(std::memcmp(&a.slip_dissipated, &b.slip_dissipated, sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&a.wall_work, &b.wall_work, sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&a.bond_break_lost, &b.bond_break_lost, sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&a.shear_break_released, &b.shear_break_released, sizeof(double)), 0);
}

}  // namespace jostling_box
