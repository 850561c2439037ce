// The three force-loop paths give the same bits (engine/stepper.cpp, engine/pair_batch.hpp):
//   * the scalar reference loop (taken when there is more than one particle material),
//   * the batched kernel (one contact per SIMD lane, one particle material),
//   * the threaded path (particle ranges, boundary particles summed from slots in pair
//     order, engine/force_partition.hpp), 2 and 3 threads, also with each thread's motion
//     done inside the force loop (Stepper::set_between_halves).
// A dense, jostling packing of 1200 spheres in a closed box (several thousand candidate pairs,
// above the threaded path's threshold of 2048) with friction sliding, contacts forming and separating, bonds
// holding and breaking, runs 300 steps on each path (also with a wide Verlet skin, where most
// candidate pairs are apart); positions, velocities, spins and contact histories must be
// identical to the last bit. So must runs whose candidate lists differ (another skin, extra
// rebuilds): which pairs are candidates never shows in a result.
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <string>
#include <utility>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/uniform_real_distribution.hpp>

#include "engine/stepper.hpp"

using namespace colza;

namespace {

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
  bool viscous = false;       // viscous dashpots alone on the paper's law (their lanes in the batched kernel)
  bool walton_braun = false;  // the Walton-Braun normal law alone in place of the linear spring (its lanes)
  bool load_induced = false;  // load-induced cohesion alone (its lanes): bonds forming under load and breaking
};

World make_world(const Setup& setup) {
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

PhysicsSettings physics(const Setup& setup) {
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
    s.model.rolling = ElasticPlasticRolling{1.0, 0.1, RollingForm::kYade, true};
  }
  if (setup.rolling) s.model.rolling = ElasticPlasticRolling{1.0, 0.05, setup.rolling_form, true};
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

PathRun run_path(const Setup& setup, int threads) {
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
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// Positions, velocities, spins, forces and torques, to the last bit.
void expect_same_particles(const World& a, const World& b) {
  EXPECT_TRUE(same_bits(a.particles.position, b.particles.position));
  EXPECT_TRUE(same_bits(a.particles.velocity, b.particles.velocity));
  EXPECT_TRUE(same_bits(a.particles.angular_velocity, b.particles.angular_velocity));
  EXPECT_TRUE(same_bits(a.particles.force, b.particles.force));
  EXPECT_TRUE(same_bits(a.particles.torque, b.particles.torque));
}

void expect_same_state(const World& a, const World& b) {
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

// The touching contacts of a and b, matched by their bodies (a particle pair, or a wall and a
// particle): lists built with another skin or at other moments hold other candidates, but
// must hold the same contacts with the same histories to the last bit.
void expect_same_contacts(const World& a, const World& b) {
  // Touching entries of a pair list (keys: first and second body, or wall and particle).
  const auto touching_by_key = [](const std::vector<Index>& key_1, const std::vector<Index>& key_2,
                                  const std::vector<ContactHistory>& history) {
    std::map<std::pair<Index, Index>, const ContactHistory*> m;
    for (std::size_t c = 0; c < history.size(); ++c)
      if (history[c].touching) m[{key_1[c], key_2[c]}] = &history[c];
    return m;
  };
  const auto particle_contacts = [&](const World& w) {
    const auto& pp = w.contacts.particle_pairs;
    return touching_by_key(pp.first, pp.second, pp.history);
  };
  const auto wall_contacts = [&](const World& w) {
    const auto& pw = w.contacts.wall_pairs;
    return touching_by_key(pw.wall, pw.particle, pw.history);
  };
  for (const auto& [ma, mb] : {std::pair{particle_contacts(a), particle_contacts(b)},
                               std::pair{wall_contacts(a), wall_contacts(b)}}) {
    ASSERT_EQ(ma.size(), mb.size());
    for (const auto& [key, ha] : ma) {
      const auto it = mb.find(key);
      ASSERT_NE(it, mb.end()) << "contact " << key.first << "-" << key.second;
      const ContactHistory* hb = it->second;
      ASSERT_EQ(std::memcmp(ha->shear_force.data(), hb->shear_force.data(), sizeof(Vec3)), 0);
      ASSERT_EQ(std::memcmp(ha->normal.data(), hb->normal.data(), sizeof(Vec3)), 0);
      ASSERT_EQ(std::memcmp(&ha->normal_force, &hb->normal_force, sizeof(double)), 0);
      ASSERT_EQ(ha->bonded, hb->bonded);
    }
  }
}

// The ledger terms summed in pair order (the damping work is summed per thread range).
void expect_same_pair_energies(const EnergyLedger& a, const EnergyLedger& b) {
  EXPECT_EQ(std::memcmp(&a.slip_dissipated, &b.slip_dissipated, sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&a.wall_work, &b.wall_work, sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&a.bond_break_lost, &b.bond_break_lost, sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&a.shear_break_released, &b.shear_break_released, sizeof(double)), 0);
}

}  // namespace

TEST(ForcePaths, BatchedKernelGivesTheScalarReferenceBits) {
  const PathRun batched = run_path({1, false}, 1);
  const PathRun reference = run_path({2, false}, 1);
  ASSERT_GT(batched.world.contacts.touching_particle_contacts(), 1000u);  // a real contact network
  expect_same_state(batched.world, reference.world);
  expect_same_pair_energies(batched.ledger, reference.ledger);
}

TEST(ForcePaths, BatchedKernelGivesTheScalarReferenceBitsWithBondsBreaking) {
  const PathRun batched = run_path({1, true}, 1);
  const PathRun reference = run_path({2, true}, 1);
  EXPECT_GT(batched.broken_tension + batched.broken_shear, 0u);  // bonds do break in the run
  EXPECT_EQ(batched.broken_tension, reference.broken_tension);
  EXPECT_EQ(batched.broken_shear, reference.broken_shear);
  expect_same_state(batched.world, reference.world);
  expect_same_pair_energies(batched.ledger, reference.ledger);
}

// With a wide skin most candidate pairs are apart (the diagonal lattice neighbours, 8.2 mm
// apart for a reach of 6 mm): the particle-pair kernel's quiet chunks then pass over many
// such pairs (engine/pair_batch.hpp) and the scalar loop tests each of them. Same bits on
// every path, threads included. (A threaded slot left stale by a quiet chunk that skipped
// out.none() is caught by TwoThreadsGiveTheOneThreadBitsWithShapedWalls, whose pairs are
// repartitioned during the run.)
TEST(ForcePaths, CandidatesApartGiveTheSameBitsOnEveryPath) {
  const PathRun batched = run_path({.particle_materials = 1, .bonds = true, .skin = 2.5e-3}, 1);
  const PathRun reference = run_path({.particle_materials = 2, .bonds = true, .skin = 2.5e-3}, 1);
  const std::size_t pairs = batched.world.contacts.particle_pairs.size();
  const std::size_t touching = batched.world.contacts.touching_particle_contacts();
  ASSERT_GT(touching, 1000u);
  ASSERT_GT(pairs - touching, touching);  // more candidates apart than in contact
  expect_same_state(batched.world, reference.world);
  expect_same_pair_energies(batched.ledger, reference.ledger);
#ifdef _OPENMP
  const PathRun two = run_path({.particle_materials = 1, .bonds = true, .skin = 2.5e-3}, 2);
  EXPECT_EQ(two.threaded_steps, 300u);
  expect_same_state(batched.world, two.world);
  expect_same_pair_energies(batched.ledger, two.ledger);
#endif
}

// Which pairs are candidates, and when the lists are built, never shows in a result: forces
// are summed in pair order, a candidate that is not touching carries no force, and a
// contact's history is carried across rebuilds. install_bonds (scenario/bonds.hpp) relies
// on this when it rebuilds the lists before bonding; the skin is then a speed setting only.
TEST(ForcePaths, TheSkinAndTheMomentOfRebuildsChangeNoResult) {
  const PathRun narrow = run_path({.particle_materials = 1, .bonds = true, .skin = 0.3e-3}, 1);
  const PathRun wide = run_path({.particle_materials = 1, .bonds = true, .skin = 2.5e-3}, 1);
  const PathRun rebuilt = run_path({.particle_materials = 1, .bonds = true, .skin = 0.3e-3, .rebuild_every = 7}, 1);
  ASSERT_GT(narrow.world.contacts.touching_particle_contacts(), 1000u);
  ASSERT_GT(wide.max_pairs, narrow.max_pairs);  // other candidate lists
  ASSERT_GT(narrow.broken_tension + narrow.broken_shear, 0u);  // bonds broke on the way
  for (const PathRun* other : {&wide, &rebuilt}) {
    expect_same_particles(narrow.world, other->world);
    expect_same_contacts(narrow.world, other->world);
    EXPECT_EQ(narrow.broken_tension, other->broken_tension);
    EXPECT_EQ(narrow.broken_shear, other->broken_shear);
    expect_same_pair_energies(narrow.ledger, other->ledger);
  }
}

// The same for a wall whose candidates change because a sphere crosses the end of a finite
// cylinder: a sphere just beyond the end at a build, moving back into the axial range while
// pressed against the surface, meets the wall as it enters whether or not the lists were
// built in between (neighbour/neighbour_search.cpp: the candidate test takes the cylinder
// as reaching one skin beyond its ends).
TEST(ForcePaths, ASphereEnteringAShortCylinderMeetsItBetweenBuilds) {
  const auto run = [](int rebuild_every, std::uint64_t expected_builds) {
    World w;
    // A sleeve of radius 10 mm from z = 0 to 20 mm. The sphere overlaps its surface by 5 um,
    // its centre 0.2 mm above the top end, and moves down at 0.5 m/s: it enters the range
    // after ~400 steps of 1 us, and the wall pushes it towards the axis (at ~0.25 m/s). With a
    // 2 mm skin nothing moves 1 mm in 800 steps, so the lists are built once unless rebuilt.
    const double sleeve_radius = 0.01, top = 0.02;
    w.walls.push_back(Wall::cylinder("sleeve", Vec3::Zero(), Vec3::UnitZ(), sleeve_radius, 0.0, top));
    w.particles.add(Vec3(sleeve_radius - kRadius + 5e-6, 0.0, top + 0.2e-3), kRadius, 1250.0, 0,
                    Vec3(0.0, 0.0, -0.5), Vec3::Zero());
    PhysicsSettings settings = physics({.skin = 2e-3});
    settings.time_step.fixed_dt = 1e-6;
    Stepper stepper(settings);
    stepper.prepare(w);
    for (int s = 0; s < 800; ++s) {
      if (rebuild_every > 0 && s % rebuild_every == 0) stepper.rebuild_neighbours(w);
      stepper.step(w);
    }
    EXPECT_EQ(stepper.neighbours().rebuild_count(), expected_builds);
    return w;
  };
  // prepare() builds once; rebuild_neighbours() once more per step, and a step after it never does.
  const World built_once = run(0, 1), rebuilt_every_step = run(1, 801);
  ASSERT_LT(rebuilt_every_step.particles.velocity[0].x(), -0.1);  // the wall did push it inwards
  expect_same_particles(built_once, rebuilt_every_step);
  expect_same_contacts(built_once, rebuilt_every_step);
}

// The batched wall kernel (engine/wall_batch.hpp) on every wall shape: a rectangle's face,
// edges and corners, a cylinder, planes.
TEST(ForcePaths, BatchedWallKernelGivesTheScalarReferenceBitsOnEveryShape) {
  const PathRun batched = run_path({.particle_materials = 1, .shaped_walls = true}, 1);
  const PathRun reference = run_path({.particle_materials = 2, .shaped_walls = true}, 1);
  // Touching wall contacts per wall at the end: the rectangle and the cylinder carry some.
  std::vector<std::size_t> touching(batched.world.walls.size(), 0);
  const auto& pw = batched.world.contacts.wall_pairs;
  for (std::size_t c = 0; c < pw.size(); ++c) touching[pw.wall[c]] += pw.history[c].touching;
  EXPECT_GT(touching[0], 20u);                   // rectangle "plate"
  EXPECT_GT(touching.back(), 10u);               // cylinder "envelope"
  EXPECT_GT(batched.ledger.slip_dissipated, 0.0);
  expect_same_state(batched.world, reference.world);
  expect_same_pair_energies(batched.ledger, reference.ledger);
}

TEST(ForcePaths, BatchedWallKernelGivesTheScalarReferenceBitsWithRestrictedEdges) {
  // Restricted edges (the shear box's seams and corners with edge_contacts = "per_surface"):
  // the lanes leave the spheres beyond them out exactly as the scalar geometry does.
  const PathRun batched = run_path({.particle_materials = 1, .shaped_walls = true, .restricted_plate_edges = true}, 1);
  const PathRun reference =
      run_path({.particle_materials = 2, .shaped_walls = true, .restricted_plate_edges = true}, 1);
  const PathRun closed = run_path({.particle_materials = 1, .shaped_walls = true}, 1);
  auto touching_plate = [](const World& w) {
    std::size_t n = 0;
    const auto& pw = w.contacts.wall_pairs;
    for (std::size_t c = 0; c < pw.size(); ++c) n += (pw.wall[c] == 0) & pw.history[c].touching;
    return n;
  };
  EXPECT_GT(touching_plate(batched.world), 20u);
  EXPECT_LT(touching_plate(batched.world), touching_plate(closed.world));  // the +y edge's row is let go
  expect_same_state(batched.world, reference.world);
  expect_same_pair_energies(batched.ledger, reference.ledger);
}

#ifdef _OPENMP
TEST(ForcePaths, TwoThreadsGiveTheOneThreadBitsWithShapedWalls) {
  const PathRun one = run_path({.particle_materials = 1, .shaped_walls = true}, 1);
  const PathRun two = run_path({.particle_materials = 1, .shaped_walls = true}, 2);
  EXPECT_EQ(two.threaded_steps, 300u);
  expect_same_state(one.world, two.world);
  expect_same_pair_energies(one.ledger, two.ledger);
}

TEST(ForcePaths, TwoThreadsGiveTheOneThreadBits) {
  const PathRun one = run_path({1, true}, 1);
  const PathRun two = run_path({1, true}, 2);
  ASSERT_GE(one.max_pairs, 2048u);  // the threaded path's threshold (stepper.cpp) is reached
  EXPECT_EQ(one.threaded_steps, 0u);
  EXPECT_EQ(two.threaded_steps, 300u);  // every step took the threaded path
  ASSERT_GT(one.world.contacts.touching_wall_contacts(), 100u);  // wall pairs take the threaded path too
  EXPECT_GT(one.ledger.slip_dissipated, 0.0);
  EXPECT_NE(one.ledger.wall_work, 0.0);
  expect_same_state(one.world, two.world);
  expect_same_pair_energies(one.ledger, two.ledger);
}

// The generic tier with the baseline's slots performs the baseline's operations in the same
// order (contact/generic_law.hpp): the same bits as the batched kernels, bonds breaking.
TEST(ForcePaths, TheGenericTierGivesTheBaselineBits) {
  const PathRun baseline = run_path({.bonds = true}, 1);
  const PathRun generic = run_path({.bonds = true, .generic_tier = true}, 1);
  EXPECT_GT(baseline.broken_tension + baseline.broken_shear, 0u);
  EXPECT_EQ(baseline.broken_tension, generic.broken_tension);
  EXPECT_EQ(baseline.broken_shear, generic.broken_shear);
  expect_same_state(baseline.world, generic.world);
  expect_same_pair_energies(baseline.ledger, generic.ledger);
}

// The generic tier with mechanisms on (rolling moments in the torques, dashpots, slot state
// carried across rebuilds) on the threaded path: the one-thread bits at two and three threads.
TEST(ForcePaths, TheGenericTierWithMechanismsGivesTheOneThreadBitsOnThreads) {
  const PathRun one = run_path({.bonds = true, .mechanisms = true}, 1);
  const PathRun two = run_path({.bonds = true, .mechanisms = true}, 2);
  const PathRun three = run_path({.bonds = true, .mechanisms = true}, 3);
  EXPECT_EQ(two.threaded_steps, 300u);
  EXPECT_GT(one.ledger.rolling_dissipated, 0.0);
  EXPECT_GT(one.ledger.viscous_dissipated, 0.0);
  EXPECT_GT(one.ledger.plastic_dissipated, 0.0);
  expect_same_state(one.world, two.world);
  expect_same_state(one.world, three.world);
  expect_same_pair_energies(one.ledger, two.ledger);
  EXPECT_EQ(std::memcmp(&one.ledger.rolling_dissipated, &three.ledger.rolling_dissipated, sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&one.ledger.viscous_dissipated, &three.ledger.viscous_dissipated, sizeof(double)), 0);
}

// Rolling resistance, viscous damping or the Walton-Braun normal law on the paper's law runs
// its particle pairs in the batched kernel with the mechanism's lanes
// (engine/rolling_lanes.hpp, viscous_lanes.hpp, walton_braun_lanes.hpp): the generic tier's
// bits, both forms of the rolling spring, bonds breaking, the caps and the loading
// dissipating, with a wide skin (candidates apart) and on two threads.
TEST(ForcePaths, TheMechanismLanesGiveTheGenericTierBits) {
  struct Mechanism {
    const char* name;
    bool rolling, viscous, walton_braun, load_induced;
    RollingForm form;
  };
  for (const Mechanism m : {Mechanism{"rolling, YADE's form", true, false, false, false, RollingForm::kYade},
                            Mechanism{"rolling, PFC's form", true, false, false, false, RollingForm::kPfc},
                            Mechanism{"viscous", false, true, false, false, RollingForm::kYade},
                            Mechanism{"Walton-Braun", false, false, true, false, RollingForm::kYade},
                            Mechanism{"load-induced", false, false, false, true, RollingForm::kYade}}) {
    for (const bool bonds : {false, true}) {
      if (bonds && m.load_induced) continue;  // its own bonds
      SCOPED_TRACE(std::string(m.name) + (bonds ? ", bonds" : ", no bonds"));
      const ::Setup lanes_setup{
          .bonds = bonds, .rolling = m.rolling, .rolling_form = m.form, .viscous = m.viscous,
                   .walton_braun = m.walton_braun, .load_induced = m.load_induced};
      ::Setup generic_setup = lanes_setup;
      generic_setup.generic_tier = true;
      const PathRun generic = run_path(generic_setup, 1);
      const PathRun lanes = run_path(lanes_setup, 1);
      if (m.rolling) EXPECT_GT(generic.ledger.rolling_dissipated, 0.0);
      if (m.viscous) EXPECT_GT(generic.ledger.viscous_dissipated, 0.0);
      if (m.walton_braun) EXPECT_GT(generic.ledger.plastic_dissipated, 0.0);
      if (bonds || m.load_induced) EXPECT_GT(generic.broken_tension + generic.broken_shear, 0u);
      EXPECT_EQ(generic.broken_tension, lanes.broken_tension);
      EXPECT_EQ(generic.broken_shear, lanes.broken_shear);
      expect_same_state(generic.world, lanes.world);
      expect_same_pair_energies(generic.ledger, lanes.ledger);
      EXPECT_EQ(std::memcmp(&generic.ledger.rolling_dissipated, &lanes.ledger.rolling_dissipated, sizeof(double)), 0);
      EXPECT_EQ(std::memcmp(&generic.ledger.viscous_dissipated, &lanes.ledger.viscous_dissipated, sizeof(double)), 0);
      EXPECT_EQ(std::memcmp(&generic.ledger.plastic_dissipated, &lanes.ledger.plastic_dissipated, sizeof(double)), 0);
    }
    SCOPED_TRACE(std::string(m.name) + ", wide skin and two threads");
    const ::Setup wide{.skin = 2.5e-3, .rolling = m.rolling, .rolling_form = m.form, .viscous = m.viscous,
                   .walton_braun = m.walton_braun, .load_induced = m.load_induced};
    ::Setup wide_generic = wide;
    wide_generic.generic_tier = true;
    expect_same_state(run_path(wide_generic, 1).world, run_path(wide, 1).world);
    const ::Setup bonded{.bonds = true, .rolling = m.rolling, .rolling_form = m.form, .viscous = m.viscous,
                   .walton_braun = m.walton_braun, .load_induced = m.load_induced};
    ::Setup bonded_generic = bonded;
    bonded_generic.generic_tier = true;
    const PathRun two = run_path(bonded, 2);
    const PathRun one = run_path(bonded_generic, 1);
    EXPECT_EQ(two.threaded_steps, 300u);
    expect_same_state(one.world, two.world);
    expect_same_pair_energies(one.ledger, two.ledger);
    EXPECT_EQ(std::memcmp(&one.ledger.rolling_dissipated, &two.ledger.rolling_dissipated, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&one.ledger.viscous_dissipated, &two.ledger.viscous_dissipated, sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(&one.ledger.plastic_dissipated, &two.ledger.plastic_dissipated, sizeof(double)), 0);
  }
}

// Three ranges: a middle range has boundary particles and outgoing pairs at once.
TEST(ForcePaths, ThreeThreadsGiveTheOneThreadBits) {
  const PathRun one = run_path({1, true}, 1);
  const PathRun three = run_path({1, true}, 3);
  EXPECT_EQ(three.threaded_steps, 300u);
  expect_same_state(one.world, three.world);
  expect_same_pair_energies(one.ledger, three.ledger);
}
// The motion inside the threaded force loop (set_between_halves(kWallsOnly), no sums): the
// same bits as the separate integration, at two and three threads; and no energy ledger.
TEST(ForcePaths, MotionInsideTheThreadedForceLoopGivesTheSameBits) {
  const PathRun one = run_path({1, true}, 1);
  const PathRun one_walls_only = run_path({1, true, true}, 1);
  EXPECT_EQ(one_walls_only.motion_with_forces_steps, 0u);  // serial path: separate integration
  // Those runs keep no energy ledger (no damping work summed): the force loop skips the slip
  // energy (lanes without its division), and nothing else changes.
  expect_same_state(one.world, one_walls_only.world);
  EXPECT_GT(one.ledger.slip_dissipated, 0.0);
  EXPECT_EQ(one_walls_only.ledger.slip_dissipated, 0.0);
  EXPECT_EQ(one_walls_only.broken_tension + one_walls_only.broken_shear, one.broken_tension + one.broken_shear);
  for (int threads : {2, 3}) {
    const PathRun fused = run_path({1, true, true}, threads);
    EXPECT_EQ(fused.motion_with_forces_steps, 300u) << threads << " threads";
    expect_same_state(one.world, fused.world);
    expect_same_pair_energies(one_walls_only.ledger, fused.ledger);
  }
}
#endif
