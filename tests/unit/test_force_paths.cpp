// The three force-loop paths give the same bits (engine/force_loops_body.hpp, engine/pair_batch.hpp):
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

#include "engine/stepper.hpp"
#include "jostling_box.hpp"

using namespace colza;
using namespace jostling_box;

namespace {

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

// Rolling resistance, viscous damping, the Walton-Braun normal law or load-induced cohesion
// on the paper's law, or viscous damping with one of the others, runs its particle pairs in
// the batched kernel with the mechanism's lanes (engine/rolling_lanes.hpp, viscous_lanes.hpp,
// walton_braun_lanes.hpp, load_induced_lanes.hpp, damped_lanes.hpp): the generic tier's
// bits, both forms of the rolling spring, bonds breaking, the caps and the loading
// dissipating, with a wide skin (candidates apart) and on two threads.
TEST(ForcePaths, TheMechanismLanesGiveTheGenericTierBits) {
  struct Mechanism {
    const char* name;
    bool rolling, viscous, walton_braun, load_induced;
    RollingForm form;
    double rolling_damping = 0.0;
  };
  for (const Mechanism m : {Mechanism{"rolling, YADE's form", true, false, false, false, RollingForm::kYade},
                            Mechanism{"rolling, PFC's form", true, false, false, false, RollingForm::kPfc},
                            Mechanism{"viscous", false, true, false, false, RollingForm::kYade},
                            Mechanism{"Walton-Braun", false, false, true, false, RollingForm::kYade},
                            Mechanism{"load-induced", false, false, false, true, RollingForm::kYade},
                            Mechanism{"rolling with its dashpot", true, false, false, false, RollingForm::kYade, 0.3},
                            Mechanism{"viscous and rolling", true, true, false, false, RollingForm::kYade},
                            Mechanism{"viscous and rolling with its dashpot", true, true, false, false,
                                      RollingForm::kPfc, 0.5},
                            Mechanism{"viscous and Walton-Braun", false, true, true, false, RollingForm::kYade},
                            Mechanism{"viscous and load-induced", false, true, false, true, RollingForm::kYade}}) {
    for (const bool bonds : {false, true}) {
      if (bonds && m.load_induced) continue;  // its own bonds
      SCOPED_TRACE(std::string(m.name) + (bonds ? ", bonds" : ", no bonds"));
      const ::Setup lanes_setup{
          .bonds = bonds, .rolling = m.rolling, .rolling_form = m.form, .rolling_damping = m.rolling_damping,
                   .viscous = m.viscous,
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
    const ::Setup wide{.skin = 2.5e-3, .rolling = m.rolling, .rolling_form = m.form,
                       .rolling_damping = m.rolling_damping, .viscous = m.viscous,
                   .walton_braun = m.walton_braun, .load_induced = m.load_induced};
    ::Setup wide_generic = wide;
    wide_generic.generic_tier = true;
    expect_same_state(run_path(wide_generic, 1).world, run_path(wide, 1).world);
    const ::Setup bonded{.bonds = true, .rolling = m.rolling, .rolling_form = m.form,
                         .rolling_damping = m.rolling_damping, .viscous = m.viscous,
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
