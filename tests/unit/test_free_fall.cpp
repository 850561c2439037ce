// Leapfrog free fall (physics.md section 3): exact discrete solution.
//
// Leapfrog with constant acceleration -g (damping 0), state x_k = x(t_k), v_{k-1/2} = v(t_k - dt/2):
//   v_{k+1/2} = v_{k-1/2} - g dt,      x_{k+1} = x_k + dt v_{k+1/2}.
// Starting convention v_{-1/2} = 0 (the particle's stored velocity at t_0 is the mid-step
// value v(t_0 - dt/2) = 0):  v_{k+1/2} = -(k+1) g dt, so
//   x_n = x_0 + dt sum_{k=0}^{n-1} v_{k+1/2} = x_0 - g dt^2 sum_{j=1}^{n} j = x_0 - g dt^2 n (n+1) / 2,
//   v_{n-1/2} = -n g dt.
// (The continuous solution from rest is x_0 - g t^2 / 2 with t = n dt; leapfrog with this start
// convention is ahead by g dt^2 n / 2, the price of v(-dt/2) = 0 instead of v(-dt/2) = +g dt/2.)
#include <gtest/gtest.h>

#include <cmath>

#include "engine/stepper.hpp"
#include "integrate/integrator.hpp"

using namespace colza;

namespace {
constexpr double kG = 9.81;
constexpr double kDt = 1e-4;
constexpr int kSteps = 1000;
}  // namespace

TEST(FreeFall, IntegrateStepMatchesDiscreteSolution) {
  ParticleArrays p;
  p.add(Vec3(0.1, -0.2, 0.0), 3e-3, 1250.0);
  IntegratorSettings s;
  s.damping = 0.0;
  s.gravity = Vec3(0.0, 0.0, -kG);
  for (int n = 1; n <= kSteps; ++n) {
    p.clear_forces();
    integrate_step(p, s, kDt);
    // z_n = -g dt^2 n (n+1)/2 (x_0 = 0 in z), v_{n-1/2} = -n g dt.
    const double z_expected = -kG * kDt * kDt * n * (n + 1) / 2.0;
    ASSERT_NEAR(p.position[0].z(), z_expected, 1e-12 * std::abs(z_expected)) << "step " << n;
    ASSERT_NEAR(p.velocity[0].z(), -n * kG * kDt, 1e-12 * n * kG * kDt) << "step " << n;
  }
  // Horizontal motion untouched.
  EXPECT_EQ(p.position[0].x(), 0.1);
  EXPECT_EQ(p.position[0].y(), -0.2);
}

TEST(FreeFall, StepperMatchesDiscreteSolution) {
  PhysicsSettings s;
  s.particle_materials = {{"seed", 1250.0, 437e3, 100e3, 0.2}};
  s.integrator.damping = 0.0;
  s.integrator.gravity = Vec3(0.0, 0.0, -kG);
  s.time_step.automatic = false;
  s.time_step.fixed_dt = kDt;
  s.skin = 1e-3;
  World w;
  w.particles.add(Vec3::Zero(), 3e-3, 1250.0);
  Stepper stepper(s);
  stepper.prepare(w);
  ASSERT_EQ(w.dt, kDt);
  stepper.run(w, kSteps);
  const int n = kSteps;
  // z_n = -g dt^2 n (n+1)/2 = -9.81e-8 * 1000 * 1001 / 2 = -0.04909905 m.
  const double z_expected = -kG * kDt * kDt * n * (n + 1) / 2.0;
  EXPECT_NEAR(w.particles.position[0].z(), z_expected, 1e-12 * std::abs(z_expected));
  EXPECT_NEAR(w.particles.velocity[0].z(), -n * kG * kDt, 1e-12 * n * kG * kDt);
  EXPECT_EQ(w.step, static_cast<std::uint64_t>(n));
  EXPECT_NEAR(w.time, n * kDt, 1e-12 * n * kDt);
  // The unbalanced force of a free particle is its weight m g.
  const double m = 1250.0 * 4.0 / 3.0 * kPi * 27e-9;
  EXPECT_NEAR(stepper.last_integration().mean_unbalanced_force, m * kG, 1e-12 * m * kG);
}

TEST(FreeFall, FixedParticleMovesWithPrescribedVelocity) {
  // fixed = 1: not integrated, x_{k+1} = x_k + dt v with v unchanged, gravity and forces ignored.
  ParticleArrays p;
  p.add(Vec3::Zero(), 3e-3, 1250.0, 0, Vec3(0.5, 0.0, -0.25));
  p.fixed[0] = 1;
  p.force[0] = Vec3(100.0, 100.0, 100.0);
  IntegratorSettings s;
  s.damping = 0.7;
  for (int n = 0; n < 100; ++n) integrate_step(p, s, kDt);
  EXPECT_NEAR(p.position[0].x(), 100 * kDt * 0.5, 1e-15);
  EXPECT_NEAR(p.position[0].z(), -100 * kDt * 0.25, 1e-15);
  EXPECT_EQ(p.velocity[0], Vec3(0.5, 0.0, -0.25));
}
