// A motion that blows up stops with a clear error (core/unstable_motion.hpp: a non-finite
// position; engine/motion_limits.hpp: a particle moving a radius in a step, an overlap beyond
// the smaller radius), and spheres
// far apart do not make the neighbour grid ask for more cells than memory holds.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "core/unstable_motion.hpp"
#include "engine/stepper.hpp"

using namespace colza;

namespace {

PhysicsSettings fixed_step_physics(double dt) {
  PhysicsSettings s;
  s.particle_materials = {{"seed", 1250.0, 437e3, 100e3, 0.2}};
  s.integrator.gravity = Vec3(0.0, 0.0, -9.81);
  s.time_step.automatic = false;
  s.time_step.fixed_dt = dt;
  s.skin = 5e-4;
  return s;
}

// Two spheres of 3 mm on the z axis, the second at height z2 (m); a stepper prepared on
// them and run for `steps` steps at dt = 1 us.
struct TwoSpheres {
  World world;
  Stepper stepper{fixed_step_physics(1e-6)};
  TwoSpheres(double z2, int steps) {
    world.particles.add(Vec3(0.0, 0.0, 0.0), 3e-3, 1250.0);
    world.particles.add(Vec3(0.0, 0.0, z2), 3e-3, 1250.0);
    stepper.prepare(world);
    stepper.run(world, static_cast<std::uint64_t>(steps));
  }
};

}  // namespace

TEST(UnstableMotion, FirstNonFinitePositionIsFound) {
  ParticleArrays p;
  for (int i = 0; i < 100; ++i) p.add(Vec3(1e300 * (i % 2), 0.01 * i, 0.0), 3e-3, 1250.0);  // huge but finite
  EXPECT_FALSE(first_non_finite_position(p).has_value());
  p.position[37].y() = std::numeric_limits<double>::quiet_NaN();
  p.position[64].z() = std::numeric_limits<double>::infinity();
  ASSERT_TRUE(first_non_finite_position(p).has_value());
  EXPECT_EQ(*first_non_finite_position(p), 37u);
}

TEST(UnstableMotion, ANaNPositionStopsTheRunWithinACheckIntervalNamingTheTimeStep) {
  // A NaN never asks for a neighbour rebuild (every comparison with it is false), so the
  // stepper checks the positions every kFiniteCheckInterval steps. (The spheres are apart,
  // so the NaN stays in sphere 1 instead of reaching sphere 0 through a contact.)
  TwoSpheres s(0.1, 5);
  s.world.particles.position[1].x() = std::numeric_limits<double>::quiet_NaN();
  try {
    s.stepper.run(s.world, Stepper::kFiniteCheckInterval);
    ADD_FAILURE() << "a NaN position went unnoticed for " << Stepper::kFiniteCheckInterval << " steps";
  } catch (const UnstableMotion& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("particle 1 has a non-finite position at step 100"), std::string::npos) << m;
    EXPECT_NE(m.find("fixed by integration.time_step"), std::string::npos) << m;
    EXPECT_NE(m.find("critical estimate of"), std::string::npos) << m;
  }
}

TEST(UnstableMotion, AnInfinitePositionStopsTheRunBeforeTheNeighbourGridIndexesIt) {
  TwoSpheres s(0.0059, 3);
  s.world.particles.position[0].z() = -std::numeric_limits<double>::infinity();  // asks for a rebuild at once
  EXPECT_THROW(s.stepper.step(s.world), UnstableMotion);
}

// Sphere 1 at `z2` above sphere 0 (3 mm radii), moving along x at `speed`; the stepper
// prepared (dt = 1 us unless given) and one step taken. Returns the UnstableMotion message,
// or "".
std::string one_step_moving(double z2, double speed, double dt = 1e-6) {
  World w;
  w.particles.add(Vec3(0.0, 0.0, 0.0), 3e-3, 1250.0);
  w.particles.add(Vec3(0.0, 0.0, z2), 3e-3, 1250.0);
  w.particles.velocity[1] = Vec3(speed, 0.0, 0.0);
  Stepper stepper(fixed_step_physics(dt));
  stepper.prepare(w);
  try {
    stepper.step(w);
  } catch (const UnstableMotion& e) {
    return e.what();
  }
  return "";
}

TEST(UnstableMotion, AParticleMovingMoreThanItsRadiusInAStepStopsTheRun) {
  // 3 mm in one step of 1 us is 3000 m/s. Sphere 1, 0.2 mm from sphere 0 (a candidate pair:
  // the skin is 0.5 mm), at 3100 m/s along x: the check at step 0 names it.
  const std::string m = one_step_moving(6.2e-3, 3100.0);
  EXPECT_NE(m.find("particle 1 moves 3.1e+03 m/s, 1.03 times its radius in one step, at step 0"), std::string::npos)
      << m;
  // 2900 m/s, 0.97 radii a step, passes.
  EXPECT_EQ(one_step_moving(6.2e-3, 2900.0), "");
  // A sphere alone, far from anything, has nothing to pass through: one that left the
  // container and falls passes at the speeds a free fall gives, below |g| t + 10 m/s (here,
  // at the stage's start, 10 m/s: 9 m/s with dt = 1 ms is 3 radii a step and passes), but not
  // at the speeds of a sample blown apart.
  EXPECT_EQ(one_step_moving(0.1, 9.0, 1e-3), "");
  EXPECT_NE(one_step_moving(0.1, 3100.0).find("particle 1 moves 3.1e+03 m/s"), std::string::npos);
}

TEST(UnstableMotion, AnOverlapBeyondTheSmallerRadiusStopsTheRun) {
  // Two fixed spheres of 3 mm whose centres are 2.9 mm apart overlap by 3.1 mm, 1.03 radii
  // (Fn / Kn with the series rule's Kn = 437e3 / 2): the check at step 100 names the pair. At
  // 3.1 mm apart (0.97 radii) it passes.
  for (const double distance : {2.9e-3, 3.1e-3}) {
    World w;
    w.particles.add(Vec3(0.0, 0.0, 0.0), 3e-3, 1250.0);
    w.particles.add(Vec3(0.0, 0.0, distance), 3e-3, 1250.0);
    w.particles.fixed[0] = w.particles.fixed[1] = 1;
    Stepper stepper(fixed_step_physics(1e-6));
    stepper.prepare(w);
    stepper.run(w, Stepper::kFiniteCheckInterval);  // steps 0-99; the check of step 100 follows
    if (distance < 3e-3) {
      try {
        stepper.step(w);
        ADD_FAILURE() << "an overlap of 1.03 radii went unnoticed";
      } catch (const UnstableMotion& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("particles 0 and 1 overlap by 0.0031 m, 103 % of the smaller radius, at step 100"),
                  std::string::npos)
            << m;
        // The time step's advice, then the remedy for soft contacts.
        EXPECT_NE(m.find("lower integration.time_step below the critical estimate; or raise the stiffnesses"),
                  std::string::npos)
            << m;
      }
    } else {
      EXPECT_NO_THROW(stepper.step(w));
    }
  }
}

TEST(NeighbourGrid, SpheresFarApartNeedNoHugeGrid) {
  // Two touching spheres and two strays a kilometre away on two axes: with cells of one
  // diameter plus skin the grid would have ~10^11 cells. The cell size grows instead; the
  // list is the same (partners are sorted), here the one touching pair.
  World w;
  w.particles.add(Vec3(0.0, 0.0, 0.0), 3e-3, 1250.0);
  w.particles.add(Vec3(0.0, 0.0, 0.0059), 3e-3, 1250.0);
  w.particles.add(Vec3(1000.0, 0.0, 0.0), 3e-3, 1250.0);
  w.particles.add(Vec3(0.0, 1000.0, 1000.0), 3e-3, 1250.0);
  Stepper stepper(fixed_step_physics(1e-6));
  stepper.prepare(w);
  const auto& pairs = w.contacts.particle_pairs;
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs.first[0], 0u);
  EXPECT_EQ(pairs.second[0], 1u);
}
