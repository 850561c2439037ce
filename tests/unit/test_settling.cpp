// Settling (scenario/settling.hpp): the mean unbalanced force alone does not say a sample is
// at rest; a sample still falling is not settled, whatever the criterion.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/stepper.hpp"
#include "io/progress.hpp"
#include "scenario/settling.hpp"
#include "walls/wall.hpp"

using namespace colza;

namespace {

constexpr double kR = 3e-3, kRho = 1250.0, kG = 9.81, kDt = 1e-5;

PhysicsSettings falling_physics() {
  PhysicsSettings s;
  s.particle_materials = {{"seed", kRho, 437e3, 100e3, 0.2}};
  s.wall_materials = {{"wall", 4000e3, 1000e3, 0.23}};
  s.integrator.damping = 0.7;
  s.integrator.gravity = Vec3(0.0, 0.0, -kG);
  s.time_step.automatic = false;
  s.time_step.fixed_dt = kDt;
  s.skin = 5e-4;
  return s;
}

// Ten spheres side by side (1 cm apart: they never touch each other), their bottoms 1 to
// 10 mm above a floor, settled to a criterion of 1 N, far above a sphere's weight
// (1.4e-3 N): the mean unbalanced force meets it from the first check on, in flight. Checked
// every 100 steps (1 ms).
SettleResult settle_ten_falling_spheres(World& w, double max_time) {
  for (int k = 0; k < 10; ++k) w.particles.add(Vec3(0.01 * k, 0.0, kR + 1e-3 * (k + 1)), kR, kRho);
  w.walls.push_back(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  Stepper stepper(falling_physics());
  stepper.prepare(w);
  stepper.set_integration_sums({.unbalanced = true, .damping_work = false});
  Progress quiet = Progress::quiet();
  return settle(w, stepper, /*threshold=*/1.0, max_time, /*check_interval=*/100, quiet);
}

}  // namespace

TEST(Settling, ASampleStillFallingIsNotAtRest) {
  // Settling must go on until at most 10 % of the spheres touch nothing: until the ninth has
  // landed. With the PFC damping 0.7 a sphere falls at 0.3 g, so the one 9 mm up lands after
  // sqrt(2 x 9e-3 / (0.3 x 9.81)) = 0.078 s.
  World w;
  const SettleResult r = settle_ten_falling_spheres(w, /*max_time=*/1.0);
  ASSERT_TRUE(r.converged);
  EXPECT_LE(r.share_touching_nothing, kMaxShareTouchingNothing);
  const double t_ninth = std::sqrt(2.0 * 9e-3 / (0.3 * kG));
  EXPECT_GT(r.simulated_time, t_ninth - 2e-3) << "stopped while spheres were in flight";
  int landed = 0;
  for (std::size_t i = 0; i < w.particles.size(); ++i) landed += w.particles.position[i].z() - kR < 1e-4;
  EXPECT_GE(landed, 9);
}

TEST(Settling, AShortMaxTimeEndsUnconvergedAndSaysWhy) {
  // Settling may last 20 ms: the criterion is met, but none has landed (the lowest, 1 mm up,
  // lands after sqrt(2 x 1e-3 / (0.3 x 9.81)) = 26 ms), so it does not converge, and the
  // result carries the share touching nothing for the warning.
  World w;
  const SettleResult r = settle_ten_falling_spheres(w, /*max_time=*/0.02);
  EXPECT_FALSE(r.converged);
  EXPECT_LT(r.mean_unbalanced_force, 1.0);
  EXPECT_EQ(r.share_touching_nothing, 1.0);
}
