// Contact stiffness from entity stiffnesses (physics.md section 2, "Stiffness"), friction
// rules, and the critical time step estimate built on them (physics.md section 3).
#include <gtest/gtest.h>

#include <cmath>

#include "core/materials.hpp"
#include "core/particles.hpp"
#include "engine/stepper.hpp"
#include "integrate/time_step.hpp"
#include "scenario/bonds.hpp"

using namespace colza;

namespace {

ParticleMaterial seed_material(double kn, double ks, double mu) { return {"seed", 1250.0, kn, ks, mu}; }
WallMaterial wall_material(double kn, double ks, double mu) { return {"wall", kn, ks, mu}; }

}  // namespace

// physics.md: "two particles with kn = 437 kN/m touch with Kn = 218.5 kN/m; particle (437)
// on wall (4000) gives 393.96 kN/m".
TEST(StiffnessRule, SeriesEqualEntitiesHalve) {
  // Kn = k k / (k + k) = k / 2 = 437e3 / 2 = 218.5e3 N/m.
  EXPECT_NEAR(combine_stiffness(437e3, 437e3, StiffnessRule::kSeries), 218.5e3, 218.5e3 * 1e-14);
}

TEST(StiffnessRule, SeriesParticleOnWall) {
  // Kn = 437e3 * 4000e3 / 4437e3 = 1748000/4437 kN/m = 393.9599...e3 N/m; the design file
  // quotes 393.96 kN/m, i.e. to +-5 N/m (half a unit of the last quoted digit).
  const double k = combine_stiffness(437e3, 4000e3, StiffnessRule::kSeries);
  EXPECT_NEAR(k, 393.96e3, 5.0);
  // And exactly the rational number 1748000/4437 kN/m (to rounding).
  EXPECT_NEAR(k, 1748000.0 / 4437.0 * 1e3, 1e-9);
  // Symmetric in its arguments.
  EXPECT_DOUBLE_EQ(k, combine_stiffness(4000e3, 437e3, StiffnessRule::kSeries));
}

TEST(StiffnessRule, ContactRuleUsesNumbersDirectly) {
  // "contact": the configured numbers are the contact stiffnesses.
  EXPECT_EQ(combine_stiffness(437e3, 437e3, StiffnessRule::kContact), 437e3);
  const ParticleMaterial p = seed_material(437e3, 100e3, 0.2);
  const WallMaterial w = wall_material(4000e3, 1000e3, 0.23);
  const PairParameters pp = particle_pair(p, p, StiffnessRule::kContact);
  EXPECT_EQ(pp.kn, 437e3);
  EXPECT_EQ(pp.ks, 100e3);
  // Particle-wall: the wall's numbers are the contact's (materials.cpp / materials.hpp).
  const PairParameters pw = particle_wall_pair(p, w, StiffnessRule::kContact);
  EXPECT_EQ(pw.kn, 4000e3);
  EXPECT_EQ(pw.ks, 1000e3);
  EXPECT_EQ(pw.friction, 0.23);
}

TEST(StiffnessRule, PairTableSeriesAndFriction) {
  // Table 1: kn_p 437, ks_p 100, kn_w 4000, ks_w 1000 kN/m; mu_pp 0.20, mu_pw 0.23.
  const std::vector<ParticleMaterial> ps = {seed_material(437e3, 100e3, 0.20), seed_material(384e3, 100e3, 0.34)};
  const std::vector<WallMaterial> ws = {wall_material(4000e3, 1000e3, 0.23), wall_material(1311e3, 300e3, 0.5)};
  const PairTable t(ps, ws, StiffnessRule::kSeries);
  EXPECT_EQ(t.rule(), StiffnessRule::kSeries);
  // pp 0-0: 437/2 = 218.5 kN/m, ks 100/2 = 50 kN/m, mu = 0.20.
  EXPECT_NEAR(t.particle_particle(0, 0).kn, 218.5e3, 1e-9);
  EXPECT_NEAR(t.particle_particle(0, 0).ks, 50e3, 1e-9);
  EXPECT_EQ(t.particle_particle(0, 0).friction, 0.20);
  // pp 0-1: 437*384/821 kN/m, ks 50 kN/m; friction min(0.20, 0.34) = 0.20 (PFC's rule), symmetric.
  EXPECT_NEAR(t.particle_particle(0, 1).kn, 437.0 * 384.0 / 821.0 * 1e3, 1e-9);
  EXPECT_NEAR(t.particle_particle(1, 0).kn, 437.0 * 384.0 / 821.0 * 1e3, 1e-9);
  EXPECT_EQ(t.particle_particle(0, 1).friction, 0.20);
  EXPECT_EQ(t.particle_particle(1, 0).friction, 0.20);
  // pw 0-0: Kn 393.96 kN/m, Ks = 100*1000/1100 kN/m = 90.909 kN/m, mu = mu_pw = 0.23
  // (not min(mu_pp, mu_pw) = 0.20: physics.md says no min rule for walls).
  EXPECT_NEAR(t.particle_wall(0, 0).kn, 393.96e3, 5.0);
  EXPECT_NEAR(t.particle_wall(0, 0).ks, 1e5 * 1e6 / 1.1e6, 1e-9);
  EXPECT_EQ(t.particle_wall(0, 0).friction, 0.23);
  // pw 1-1: Kn = 384*1311/1695 kN/m; mu = 0.5 (larger than mu_pp = 0.34: still the wall's).
  EXPECT_NEAR(t.particle_wall(1, 1).kn, 384.0 * 1311.0 / 1695.0 * 1e3, 1e-9);
  EXPECT_EQ(t.particle_wall(1, 1).friction, 0.5);
  EXPECT_EQ(t.particle_wall(0, 1).friction, 0.5);
  // contact.wall_friction = "min": PFC3D 4's rule at walls too, min(mu_pp, mu_pw); the
  // stiffnesses do not change.
  const PairTable m(ps, ws, StiffnessRule::kSeries, WallFrictionRule::kMinimum);
  EXPECT_EQ(m.particle_wall(0, 0).friction, 0.20);  // Table 1: min(0.20, 0.23)
  EXPECT_EQ(m.particle_wall(1, 1).friction, 0.34);  // min(0.34, 0.5)
  EXPECT_EQ(m.particle_wall(0, 1).friction, 0.20);
  EXPECT_EQ(m.particle_wall(1, 0).friction, 0.23);  // min(0.34, 0.23): the wall's is smaller
  EXPECT_EQ(m.particle_wall(0, 0).kn, t.particle_wall(0, 0).kn);
  EXPECT_EQ(particle_wall_pair(ps[0], ws[0], StiffnessRule::kContact, WallFrictionRule::kMinimum).friction, 0.20);
  // The stepper builds its table with the settings' rule.
  PhysicsSettings settings;
  settings.particle_materials = ps;
  settings.wall_materials = ws;
  settings.wall_friction = WallFrictionRule::kMinimum;
  EXPECT_EQ(Stepper(settings).pairs().particle_wall(0, 0).friction, 0.20);
  settings.wall_friction = WallFrictionRule::kOwn;
  EXPECT_EQ(Stepper(settings).pairs().particle_wall(0, 0).friction, 0.23);
}

// ---- critical time step (physics.md section 3, time_step.hpp) ----------------------

TEST(CriticalTimeStep, LoneSphereCountsOneContactWithItsOwnMaterial) {
  // No contacts: one contact with a body of its own material, series rule:
  // Kn = kn/2, Ks = ks/2. dt = min(sqrt(m / (Kn + Ks)), sqrt(I / (Ks R^2))).
  const double kn = 437e3, ks = 100e3, R = 3e-3, rho = 1250.0;
  const PairTable t({seed_material(kn, ks, 0.2)}, {}, StiffnessRule::kSeries);
  ParticleArrays p;
  p.add(Vec3::Zero(), R, rho);
  const double m = rho * 4.0 / 3.0 * kPi * R * R * R, I = 0.4 * m * R * R;
  const double dt_trans = std::sqrt(m / (kn / 2 + ks / 2));  // = sqrt(m / 268.5e3)
  const double dt_rot = std::sqrt(I / (ks / 2 * R * R));     // = sqrt(0.4 m / 50e3) = sqrt(m / 125e3)
  ASSERT_LT(dt_trans, dt_rot);  // translational limit is the smaller one here
  EXPECT_NEAR(critical_time_step(p, {}, ContactStore{}, t), dt_trans, dt_trans * 1e-14);

  // A very stiff shear spring makes the rotational limit the smaller one:
  // Ks = 10 Kn: sqrt(0.4 m / Ks) < sqrt(m / (Kn + Ks)) since 0.4 (Kn + Ks) = 4.4 Kn < Ks = 10 Kn.
  const PairTable t2({seed_material(kn, 10 * kn, 0.2)}, {}, StiffnessRule::kSeries);
  const double dt_rot2 = std::sqrt(I / (10 * kn / 2 * R * R));
  EXPECT_NEAR(critical_time_step(p, {}, ContactStore{}, t2), dt_rot2, dt_rot2 * 1e-14);
}

TEST(CriticalTimeStep, SafetyFactorAppliedByStepper) {
  PhysicsSettings s;
  s.particle_materials = {seed_material(437e3, 100e3, 0.2)};
  s.time_step.automatic = true;
  s.time_step.safety_factor = 0.8;
  Stepper stepper(s);
  World w;
  const double R = 3e-3;
  w.particles.add(Vec3::Zero(), R, 1250.0);
  stepper.prepare(w);
  const double m = 1250.0 * 4.0 / 3.0 * kPi * R * R * R;
  // dt = 0.8 sqrt(m / (218.5e3 + 50e3)).
  EXPECT_NEAR(w.dt, 0.8 * std::sqrt(m / 268.5e3), 1e-18);
  // Fixed time step: used as given.
  s.time_step.automatic = false;
  s.time_step.fixed_dt = 1.25e-7;
  Stepper fixed(s);
  fixed.prepare(w);
  EXPECT_EQ(w.dt, 1.25e-7);
}

TEST(CriticalTimeStep, TwoTouchingSpheres) {
  // Each body of a touching pair has k = Kn + Ks of that contact (one contact each).
  const double kn = 437e3, ks = 100e3, R = 3e-3, rho = 1250.0;
  const PairTable t({seed_material(kn, ks, 0.2)}, {}, StiffnessRule::kContact);
  ParticleArrays p;
  p.add(Vec3::Zero(), R, rho);
  p.add(Vec3(2 * R - 1e-6, 0, 0), R, rho);
  ContactStore c;
  c.particle_pairs.first = {0};
  c.particle_pairs.second = {1};
  c.particle_pairs.history.resize(1);
  c.particle_pairs.history[0].touching = 1;
  const double m = rho * 4.0 / 3.0 * kPi * R * R * R;
  // "contact" rule: Kn = 437e3, Ks = 100e3 used directly; dt = sqrt(m / 537e3)
  // (rotational: sqrt(0.4 m / 100e3) = sqrt(m / 250e3) is larger).
  EXPECT_NEAR(critical_time_step(p, {}, c, t), std::sqrt(m / 537e3), 1e-18);
}

TEST(CriticalTimeStep, WallContactUsesTheWallsMaterial) {
  // Two walls with different materials; the sphere touches wall 0, whose material is 1
  // (stiff). Contact rule "contact": the wall's numbers are the contact's, so
  // k = kn_w1 + ks_w1 = 4e6 + 1e6 and dt = sqrt(m / 5e6).
  const double R = 3e-3, rho = 1250.0;
  PhysicsSettings s;
  s.particle_materials = {seed_material(437e3, 100e3, 0.2)};
  s.wall_materials = {wall_material(1e4, 1e4, 0.2), wall_material(4e6, 1e6, 0.2)};
  s.stiffness_rule = StiffnessRule::kContact;
  s.skin = 1e-3;
  s.time_step.automatic = true;
  s.time_step.safety_factor = 1.0;
  s.integrator.gravity = Vec3::Zero();
  World w;
  w.particles.add(Vec3(0, 0, R - 1e-6), R, rho);  // resting on the plane z = 0 (overlap 1 um)
  w.walls.push_back(Wall::plane("bottom", Vec3::Zero(), Vec3::UnitZ()));
  w.walls[0].material = 1;
  w.walls.push_back(Wall::plane("far", Vec3(0, 0, 1.0), -Vec3::UnitZ()));
  w.walls[1].material = 0;
  Stepper stepper(s);
  stepper.prepare(w);
  stepper.step(w);  // contact with wall 0 now touching
  ASSERT_EQ(w.contacts.touching_wall_contacts(), 1u);
  const double m = rho * 4.0 / 3.0 * kPi * R * R * R;
  const double expected = std::sqrt(m / 5e6);  // rotational: sqrt(0.4 m / 1e6) is larger
  // (Regression: the lookup once used the wall's index pw.wall[c] as its material index, which
  // read the wrong row here and past the end of the table with 3 walls and 1 material.)
  const double got = critical_time_step(w.particles, w.walls, w.contacts, stepper.pairs());
  EXPECT_NEAR(got, expected, 1e-12 * expected);
}

TEST(CriticalTimeStep, OedometerLikeThreeWallsOneMaterial) {
  // Bottom, envelope and piston share wall material 0 (as in scenario/oedometer.cpp). A sphere
  // touching the piston (wall 2) gets k = Kn_pw + Ks_pw, series rule with Table 1 numbers:
  // Kn = 437*4000/4437 kN/m, Ks = 100*1000/1100 kN/m; dt = sqrt(m / (Kn + Ks)) (the rotational
  // limit sqrt(0.4 m / Ks) is larger).
  const double R = 3e-3, rho = 1250.0;
  const PairTable t({seed_material(437e3, 100e3, 0.2)}, {wall_material(4000e3, 1000e3, 0.23)}, StiffnessRule::kSeries);
  ParticleArrays p;
  p.add(Vec3(0, 0, 0.05), R, rho);
  std::vector<Wall> walls = {Wall::plane("bottom", Vec3::Zero(), Vec3::UnitZ()),
                             Wall::cylinder("envelope", Vec3::Zero(), Vec3::UnitZ(), 0.05, 0.0, 0.08),
                             Wall::plane("piston", Vec3(0, 0, 0.05 + R - 1e-6), -Vec3::UnitZ())};
  ContactStore c;
  c.wall_pairs.wall = {2};
  c.wall_pairs.particle = {0};
  c.wall_pairs.history.resize(1);
  c.wall_pairs.history[0].touching = 1;
  const double m = rho * 4.0 / 3.0 * kPi * R * R * R;
  const double kn = 437e3 * 4000e3 / 4437e3, ks = 100e3 * 1000e3 / 1100e3;
  EXPECT_NEAR(critical_time_step(p, walls, c, t), std::sqrt(m / (kn + ks)), 1e-18);
}

TEST(CriticalTimeStep, PrepareCountsTheOverlapsOfAStateNoForcePassHasSeen) {
  // A packing read from a file, or a sample placed in a new container, has no touching flags
  // until its first force pass. Three spheres in a row on the plane y = 0, every neighbour
  // pair and every sphere-plane pair overlapping by 1 um, contact rule: the middle sphere has
  // two particle contacts and one wall contact, k = 2 (kn + ks) + (kn_w + ks_w) = 6.074e6 N/m
  // and dt = f sqrt(m / k) (rotational: sqrt(0.4 m / (2 ks + ks_w)) = sqrt(m / 3e6) is
  // larger). prepare() must give that at once. By the flags alone every sphere counts one
  // contact with its own material, sqrt(m / (kn + ks)), 3.4x larger: before session 21 the
  // first recompute_interval steps of a run from a packing ran with that.
  const double R = 3e-3, rho = 1250.0, kn = 437e3, ks = 100e3, knw = 4000e3, ksw = 1000e3, f = 0.8;
  PhysicsSettings s;
  s.particle_materials = {seed_material(kn, ks, 0.2)};
  s.wall_materials = {wall_material(knw, ksw, 0.2)};
  s.stiffness_rule = StiffnessRule::kContact;
  s.skin = 1e-4;
  s.time_step.automatic = true;
  s.time_step.safety_factor = f;
  s.time_step.recompute_interval = 1;  // re-evaluated from the flags at every step but the first
  s.integrator.gravity = Vec3::Zero();
  World w;
  for (double x : {-(2 * R - 1e-6), 0.0, 2 * R - 1e-6}) w.particles.add(Vec3(x, R - 1e-6, 0), R, rho);
  w.walls.push_back(Wall::plane("floor", Vec3::Zero(), Vec3::UnitY()));
  Stepper stepper(s);
  stepper.prepare(w);
  const double m = rho * 4.0 / 3.0 * kPi * R * R * R;
  const double expected = f * std::sqrt(m / (2 * (kn + ks) + knw + ksw));
  EXPECT_NEAR(w.dt, expected, 1e-12 * expected);
  const double by_flags = critical_time_step(w.particles, w.walls, w.contacts, stepper.pairs());
  EXPECT_NEAR(by_flags, std::sqrt(m / (kn + ks)), 1e-12 * by_flags);
  // Bonds installed on that state make its particle pairs contacts; the wall pairs, still
  // unflagged, must stay counted (before session 21 the re-evaluation left them out).
  {
    World bonded = w;
    Stepper bonding(s);
    bonding.prepare(bonded);
    ASSERT_EQ(install_bonds(bonded, bonding, 0.0), 2u);
    EXPECT_NEAR(bonded.dt, expected, 1e-12 * expected);
  }
  // The first force pass marks the same contacts touching. Its own step keeps prepare()'s dt
  // (the re-evaluation due at step 0 is skipped: from the flags alone it would be 3.4x larger);
  // the next step's estimate, from the flags, is the same number.
  stepper.step(w);
  EXPECT_NEAR(w.dt, expected, 1e-12 * expected);
  ASSERT_EQ(w.contacts.touching_particle_contacts(), 2u);
  ASSERT_EQ(w.contacts.touching_wall_contacts(), 3u);
  stepper.step(w);
  EXPECT_NEAR(w.dt, expected, 1e-9 * expected);  // the spheres moved apart a little, not out of contact
}
