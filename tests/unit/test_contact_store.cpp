// Contact history kept by pair across neighbour-list rebuilds and particle removal
// (contact/contact_store.hpp), and bond installation (scenario/bonds.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "contact/contact_store.hpp"
#include "core/particles.hpp"
#include "engine/stepper.hpp"
#include "scenario/bonds.hpp"
#include "scenario/sample_preparation.hpp"

using namespace colza;

namespace {

ContactHistory touching(double fs_x, bool bonded = false) {
  ContactHistory h;
  h.touching = 1;
  h.bonded = bonded ? 1 : 0;
  h.shear_force = Vec3(fs_x, 0.5 * fs_x, 0.0);
  h.normal = Vec3::UnitZ();
  h.normal_force = 10.0 * fs_x;
  return h;
}

void set_pairs(ParticlePairList& l, std::vector<Index> a, std::vector<Index> b, std::vector<ContactHistory> h) {
  l.first = std::move(a);
  l.second = std::move(b);
  l.history = std::move(h);
}

// One seed material, no gravity, a fixed dt, the given Verlet skin (m): spheres that stay
// where they are put unless a test moves them.
PhysicsSettings resting_spheres(double skin) {
  PhysicsSettings ph;
  ph.particle_materials = {{"seed", 1000.0, 1e5, 1e5, 0.3}};
  ph.integrator.gravity = Vec3::Zero();
  ph.time_step.automatic = false;
  ph.time_step.fixed_dt = 1e-7;
  ph.skin = skin;
  return ph;
}

// Three spheres R = 1 mm on the x axis: 0-1 overlap by 1 um, 1-2 are 2 um apart, 0-2 far apart.
World three_spheres_on_x() {
  const double R = 1e-3;  // m
  World w;
  w.particles.add(Vec3(0, 0, 0), R, 1000.0);
  w.particles.add(Vec3(2 * R - 1e-6, 0, 0), R, 1000.0);
  w.particles.add(Vec3(4 * R - 1e-6 + 2e-6, 0, 0), R, 1000.0);
  return w;
}

bool same(const ContactHistory& a, const ContactHistory& b) {
  return a.shear_force == b.shear_force && a.normal == b.normal && a.normal_force == b.normal_force &&
         a.touching == b.touching && a.bonded == b.bonded;
}

}  // namespace

TEST(ContactStore, AdoptKeepsSurvivorsDropsVanishedKeepsBonded) {
  ContactStore s;
  // Old list: (0,1) touching, (0,2) touching unbonded, (1,2) bonded, (2,5) candidate only.
  set_pairs(s.particle_pairs, {0, 0, 1, 2}, {1, 2, 2, 5},
            {touching(1.0), touching(2.0), touching(3.0, true), ContactHistory{}});
  // New list: (0,1) survives, (1,3) and (2,5) present, (0,2) and (1,2) missing.
  s.adopt_particle_pairs({0, 1, 2}, {1, 3, 5});
  const auto& l = s.particle_pairs;
  // Expected, sorted by (first, second): (0,1) with its history, (1,2) kept because bonded,
  // (1,3) fresh, (2,5) with its (empty) history; (0,2) dropped (vanished, unbonded).
  ASSERT_EQ(l.size(), 4u);
  EXPECT_EQ(l.first, (std::vector<Index>{0, 1, 1, 2}));
  EXPECT_EQ(l.second, (std::vector<Index>{1, 2, 3, 5}));
  EXPECT_TRUE(same(l.history[0], touching(1.0)));
  EXPECT_TRUE(same(l.history[1], touching(3.0, true)));
  EXPECT_TRUE(same(l.history[2], ContactHistory{}));
  EXPECT_TRUE(same(l.history[3], ContactHistory{}));
  EXPECT_EQ(s.touching_particle_contacts(), 2u);
  EXPECT_EQ(s.bonded_contacts(), 1u);
}

TEST(ContactStore, AdoptIntoEmptyAndFromEmpty) {
  ContactStore s;
  s.adopt_particle_pairs({0, 3}, {4, 7});
  ASSERT_EQ(s.particle_pairs.size(), 2u);
  EXPECT_EQ(s.touching_particle_contacts(), 0u);
  s.particle_pairs.history[1] = touching(5.0);
  s.adopt_particle_pairs({}, {});
  EXPECT_EQ(s.particle_pairs.size(), 0u);  // nothing bonded: everything dropped
}

TEST(ContactStore, AdoptWallPairs) {
  ContactStore s;
  s.wall_pairs.wall = {0, 0, 1};
  s.wall_pairs.particle = {2, 4, 2};
  s.wall_pairs.history = {touching(1.0), touching(2.0), touching(3.0)};
  s.adopt_wall_pairs({0, 1, 1}, {4, 0, 2});
  // (0,2) vanished -> dropped; (0,4) and (1,2) keep history; (1,0) fresh.
  ASSERT_EQ(s.wall_pairs.size(), 3u);
  EXPECT_EQ(s.wall_pairs.wall, (std::vector<Index>{0, 1, 1}));
  EXPECT_EQ(s.wall_pairs.particle, (std::vector<Index>{4, 0, 2}));
  EXPECT_TRUE(same(s.wall_pairs.history[0], touching(2.0)));
  EXPECT_TRUE(same(s.wall_pairs.history[1], ContactHistory{}));
  EXPECT_TRUE(same(s.wall_pairs.history[2], touching(3.0)));
  EXPECT_EQ(s.touching_wall_contacts(), 2u);
}

TEST(ContactStore, RenumberAfterRemoval) {
  ContactStore s;
  // Particles 0..4; remove particle 1: old_to_new = {0, removed, 1, 2, 3}.
  set_pairs(s.particle_pairs, {0, 0, 1, 2, 3}, {1, 2, 4, 4, 4},
            {touching(1.0), touching(2.0), touching(3.0), touching(4.0, true), touching(5.0)});
  s.wall_pairs.wall = {0, 0, 1};
  s.wall_pairs.particle = {1, 3, 0};
  s.wall_pairs.history = {touching(6.0), touching(7.0), touching(8.0)};
  const Index X = ParticleArrays::kRemoved;
  s.renumber_particles({0, X, 1, 2, 3});
  // Pairs with particle 1 vanish; (0,2)->(0,1), (2,4)->(1,3), (3,4)->(2,3), history kept.
  const auto& l = s.particle_pairs;
  ASSERT_EQ(l.size(), 3u);
  EXPECT_EQ(l.first, (std::vector<Index>{0, 1, 2}));
  EXPECT_EQ(l.second, (std::vector<Index>{1, 3, 3}));
  EXPECT_TRUE(same(l.history[0], touching(2.0)));
  EXPECT_TRUE(same(l.history[1], touching(4.0, true)));
  EXPECT_TRUE(same(l.history[2], touching(5.0)));
  // Wall pairs: (0, p1) dropped, (0, p3)->(0, 2), (1, p0)->(1, 0).
  ASSERT_EQ(s.wall_pairs.size(), 2u);
  EXPECT_EQ(s.wall_pairs.wall, (std::vector<Index>{0, 1}));
  EXPECT_EQ(s.wall_pairs.particle, (std::vector<Index>{2, 0}));
  EXPECT_TRUE(same(s.wall_pairs.history[0], touching(7.0)));
  EXPECT_TRUE(same(s.wall_pairs.history[1], touching(8.0)));
}

TEST(ContactStore, RenumberPermutationSwapsBodiesAndFlipsVectors) {
  // Permutation 0 <-> 1 of two particles: pair (0,1) becomes (1,0) -> stored as (0,1) with
  // bodies 1 and 2 exchanged, so the normal (from body 1 to body 2) and the shear force on
  // body 2 change sign (the force on the new body 2 is minus the force on the old body 2).
  ContactStore s;
  ContactHistory h = touching(1.5);
  h.normal = Vec3(0.6, 0.8, 0.0);
  set_pairs(s.particle_pairs, {0}, {1}, {h});
  s.renumber_particles({1, 0});
  ASSERT_EQ(s.particle_pairs.size(), 1u);
  EXPECT_EQ(s.particle_pairs.first[0], 0u);
  EXPECT_EQ(s.particle_pairs.second[0], 1u);
  EXPECT_EQ(s.particle_pairs.history[0].normal, Vec3(-0.6, -0.8, 0.0));
  EXPECT_EQ(s.particle_pairs.history[0].shear_force, -h.shear_force);
  EXPECT_EQ(s.particle_pairs.history[0].normal_force, h.normal_force);  // scalar, unchanged
}

TEST(InstallBonds, BondsTouchingPairsWithinGap) {
  const PhysicsSettings ph = resting_spheres(1e-4);
  World w = three_spheres_on_x();
  Stepper st(ph);
  st.prepare(w);
  ASSERT_EQ(w.contacts.particle_pairs.size(), 2u);  // (0,1), (1,2) within the skin
  // gap 0: only the overlapping pair.
  {
    World w0 = w;
    EXPECT_EQ(install_bonds(w0, st, 0.0), 1u);
    EXPECT_EQ(w0.contacts.bonded_contacts(), 1u);
    EXPECT_EQ(w0.contacts.particle_pairs.history[0].bonded, 1);
    EXPECT_EQ(w0.contacts.particle_pairs.history[1].bonded, 0);
    // Installing again adds nothing.
    EXPECT_EQ(install_bonds(w0, st, 0.0), 0u);
  }
  // gap 3 um >= 2 um: both; the gapped pair becomes a touching bonded contact with n = +x.
  EXPECT_EQ(install_bonds(w, st, 3e-6), 2u);
  EXPECT_EQ(w.contacts.particle_pairs.history[1].touching, 1);
  EXPECT_EQ(w.contacts.particle_pairs.history[1].bonded, 1);
  EXPECT_NEAR((w.contacts.particle_pairs.history[1].normal - Vec3::UnitX()).norm(), 0.0, 1e-15);
}

TEST(InstallBonds, FindsPairsThatCameWithinTheGapSinceTheLastNeighbourBuild) {
  // Two spheres R = 1 mm, 0.6 mm apart when the candidate list is built (skin 0.5 mm: not a
  // candidate). Sphere 1 then moves 0.2 mm closer, less than skin/2, so no step would rebuild
  // the list: the pair, now 0.4 mm apart, is within a bond gap of 0.45 mm but not a candidate.
  // Bonds are installed from a fresh list, so it is bonded all the same (before the fix it
  // was missed: which pairs got bonds depended on the skin and on when the list was built).
  const PhysicsSettings ph = resting_spheres(0.5e-3);
  const double R = 1e-3;
  World w;
  w.particles.add(Vec3(0, 0, 0), R, 1000.0);
  w.particles.add(Vec3(2 * R + 0.6e-3, 0, 0), R, 1000.0);
  Stepper st(ph);
  st.prepare(w);
  ASSERT_EQ(w.contacts.particle_pairs.size(), 0u);
  w.particles.position[1].x() -= 0.2e-3;
  ASSERT_FALSE(st.neighbours().needs_rebuild(w.particles, w.walls));
  EXPECT_EQ(install_bonds(w, st, 0.45e-3), 1u);
  ASSERT_EQ(w.contacts.particle_pairs.size(), 1u);
  EXPECT_EQ(w.contacts.particle_pairs.history[0].bonded, 1);
  EXPECT_EQ(w.contacts.particle_pairs.history[0].touching, 1);
}

TEST(InstallBonds, ANewContactLowersTheTimeStepAtOnce) {
  // three_spheres_on_x (0-1 overlap, 1-2 are 2 um apart), with an automatic dt evaluated
  // every 1000 steps only. prepare() counts the overlapping pair: sphere 1 has one contact.
  // Bonding with a 3 um gap makes both pairs contacts: sphere 1 then has two, so its k_i
  // (and k_i^shear) doubles and the critical step sqrt(m / k_i) (here the
  // rotational sqrt(I / (k_i^shear R^2)), I = 0.4 m R^2, the smaller of the two) drops by
  // sqrt(2). The step in use must drop with it, not 999 steps later.
  PhysicsSettings ph = resting_spheres(1e-4);
  ph.time_step.automatic = true;
  ph.time_step.recompute_interval = 1000;
  World w = three_spheres_on_x();
  Stepper st(ph);
  st.prepare(w);
  const double dt_one_contact = w.dt;
  ASSERT_EQ(install_bonds(w, st, 3e-6), 2u);
  EXPECT_NEAR(w.dt / dt_one_contact, 1.0 / std::sqrt(2.0), 1e-12);
  // Bonds put on pairs already touching make no new contact: dt is left alone.
  World again = w;
  for (ContactHistory& h : again.contacts.particle_pairs.history) h.bonded = 0;
  again.dt = 1e-9;
  EXPECT_EQ(install_bonds(again, st, 3e-6), 2u);
  EXPECT_EQ(again.dt, 1e-9);
}

TEST(InstallBonds, RefusesAGapAsWideAsTheSkin) {
  // A pair as far apart as the skin may not be a candidate even in a fresh list, so such a
  // gap cannot be honoured (the config check names contact.bond_gap before a run starts).
  World w;
  w.particles.add(Vec3(0, 0, 0), 1e-3, 1000.0);
  Stepper st(resting_spheres(0.5e-3));
  st.prepare(w);
  EXPECT_THROW(install_bonds(w, st, 0.5e-3), std::invalid_argument);
  // A gap a hair above the skin prints as a different number (15 digits, not 6).
  try {
    install_bonds(w, st, 0.50000001e-3);
    ADD_FAILURE() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "bond gap 0.00050000001 m is not below the Verlet skin 0.0005 m");
  }
}

TEST(DiscardAbove, RemovesSpheresAndTheirContacts) {
  // Column of 3 touching spheres (R = 1 mm) on z, centres at ~1, 3, 5 mm, tops at ~2, 4, 6 mm;
  // discard those whose top z + R > 4.5 mm: sphere 2 goes, its contact with sphere 1 goes too.
  const PhysicsSettings ph = resting_spheres(1e-4);  // no step is taken: gravity plays no part
  const double R = 1e-3;
  World w;
  for (int i = 0; i < 3; ++i) w.particles.add(Vec3(0, 0, R + i * (2 * R - 1e-6)), R, 1000.0);
  Stepper st(ph);
  st.prepare(w);
  install_bonds(w, st, 0.0);
  ASSERT_EQ(w.contacts.bonded_contacts(), 2u);
  EXPECT_EQ(discard_above(w, st, 4.5e-3), 1u);
  EXPECT_EQ(w.particles.size(), 2u);
  ASSERT_EQ(w.contacts.particle_pairs.size(), 1u);
  EXPECT_EQ(w.contacts.particle_pairs.first[0], 0u);
  EXPECT_EQ(w.contacts.particle_pairs.second[0], 1u);
  EXPECT_EQ(w.contacts.bonded_contacts(), 1u);
}
