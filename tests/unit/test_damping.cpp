// Local (non-viscous, Cundall) damping, both forms, on a single body (physics.md section 3).
//   PFC:  a = (F - alpha |F| sign(v)) / m,  v = stored mid-step velocity v(t - dt/2), sign(0) = 0;
//   YADE: a = F/m (1 - alpha sign(F/m (v + dt/2 F/m))).
// Then v' = v + dt a, x' = x + dt v'. Per component, for forces and torques alike; gravity is part of F.
#include <gtest/gtest.h>

#include <cmath>

#include "integrate/integrator.hpp"

using namespace colza;

namespace {

constexpr double kAlpha = 0.7;
constexpr double kDt = 1e-5;
constexpr double kForce = 2.0;  // N

ParticleArrays one_body(const Vec3& v = Vec3::Zero(), const Vec3& w = Vec3::Zero()) {
  ParticleArrays p;
  p.add(Vec3::Zero(), 3e-3, 1250.0, 0, v, w);
  return p;
}

IntegratorSettings settings(DampingForm form) {
  IntegratorSettings s;
  s.damping = kAlpha;
  s.damping_form = form;
  s.gravity = Vec3::Zero();
  return s;
}

// Relative comparison helper for exact-arithmetic expectations (a few roundings only).
void expect_close(double got, double expected, const char* what) {
  EXPECT_NEAR(got, expected, 1e-13 * std::max(std::abs(expected), 1e-300)) << what;
}

}  // namespace

TEST(LocalDamping, PfcConstantForceFromRest) {
  ParticleArrays p = one_body();
  const double m = p.mass[0], u = kForce * kDt / m;  // u = velocity gained in one undamped step
  p.force[0] = Vec3(kForce, 0, 0);
  const IntegratorSettings s = settings(DampingForm::kPfc);
  // Step 1: v = 0, sign(0) = 0 -> no damping: v_1 = u.
  const IntegrationReport r1 = integrate_step(p, s, kDt);
  expect_close(p.velocity[0].x(), u, "v_1");
  EXPECT_EQ(r1.damping_work, 0.0);
  // Step 2: v_1 > 0 along F -> Fd = -alpha F: v_2 = u + (1 - alpha) u.
  const IntegrationReport r2 = integrate_step(p, s, kDt);
  expect_close(p.velocity[0].x(), u * (2.0 - kAlpha), "v_2");
  // Damping work of step 2: -Fd (v_1 + v_2)/2 dt = alpha F dt u (3 - alpha)/2  (> 0, removed energy).
  expect_close(r2.damping_work, kAlpha * kForce * kDt * u * (3.0 - kAlpha) / 2.0, "damping work step 2");
  // General: v_n = u (1 + (n - 1)(1 - alpha)).
  for (int n = 3; n <= 20; ++n) integrate_step(p, s, kDt);
  expect_close(p.velocity[0].x(), u * (1.0 + 19.0 * (1.0 - kAlpha)), "v_20");
  // Mean unbalanced force: |F| (no gravity).
  EXPECT_DOUBLE_EQ(r2.mean_unbalanced_force, kForce);
}

TEST(LocalDamping, YadeConstantForceFromRest) {
  ParticleArrays p = one_body();
  const double m = p.mass[0], u = kForce * kDt / m;
  p.force[0] = Vec3(kForce, 0, 0);
  const IntegratorSettings s = settings(DampingForm::kYade);
  // Step 1: a = F/m, a (0 + dt/2 a) > 0 -> a (1 - alpha): v_1 = (1 - alpha) u.
  integrate_step(p, s, kDt);
  expect_close(p.velocity[0].x(), (1.0 - kAlpha) * u, "v_1");
  // Every later step the same: v_n = n (1 - alpha) u.
  for (int n = 2; n <= 20; ++n) integrate_step(p, s, kDt);
  expect_close(p.velocity[0].x(), 20.0 * (1.0 - kAlpha) * u, "v_20");
}

TEST(LocalDamping, BothFormsAmplifyDecelerationWhenMovingAgainstTheForce) {
  // v = -V with V >> u: PFC sign(v) = -1 -> Fd = +alpha F; YADE a (v + dt/2 a) < 0 -> a (1 + alpha).
  // Both: v_1 = -V + (1 + alpha) u.
  for (DampingForm form : {DampingForm::kPfc, DampingForm::kYade}) {
    ParticleArrays p = one_body(Vec3(-1.0, 0, 0));
    const double u = kForce * kDt / p.mass[0];
    p.force[0] = Vec3(kForce, 0, 0);
    integrate_step(p, settings(form), kDt);
    expect_close(p.velocity[0].x(), -1.0 + (1.0 + kAlpha) * u, to_string(form));
    // Position uses the new mid-step velocity: x_1 = dt v_1.
    expect_close(p.position[0].x(), kDt * (-1.0 + (1.0 + kAlpha) * u), to_string(form));
  }
}

TEST(LocalDamping, FormsDifferWhenVelocityChangesSign) {
  // v_0 = -u/4 (against F, but reversed within the step):
  // PFC: sign(v_0) = -1 -> a = (1 + alpha) F/m: v_1 = -u/4 + (1 + alpha) u = 1.45 u.
  // YADE: v_0 + dt/2 a = (-1/4 + 1/2) u > 0 -> a = (1 - alpha) F/m: v_1 = -u/4 + (1 - alpha) u = 0.05 u.
  ParticleArrays p_pfc = one_body(), p_yade = one_body();
  const double u = kForce * kDt / p_pfc.mass[0];
  for (ParticleArrays* p : {&p_pfc, &p_yade}) {
    p->velocity[0] = Vec3(-0.25 * u, 0, 0);
    p->force[0] = Vec3(kForce, 0, 0);
  }
  integrate_step(p_pfc, settings(DampingForm::kPfc), kDt);
  integrate_step(p_yade, settings(DampingForm::kYade), kDt);
  expect_close(p_pfc.velocity[0].x(), -0.25 * u + (1.0 + kAlpha) * u, "pfc");
  expect_close(p_yade.velocity[0].x(), -0.25 * u + (1.0 - kAlpha) * u, "yade");
}

TEST(LocalDamping, GravityIsPartOfTheDampedForce) {
  // Falling body, v = -1 m/s, only gravity: load = -m g along v, both forms reduce it to
  // -(1 - alpha) m g: v_1 = -1 - (1 - alpha) g dt.
  const double g = 9.81;
  for (DampingForm form : {DampingForm::kPfc, DampingForm::kYade}) {
    ParticleArrays p = one_body(Vec3(0, 0, -1.0));
    IntegratorSettings s = settings(form);
    s.gravity = Vec3(0, 0, -g);
    const IntegrationReport r = integrate_step(p, s, kDt);
    expect_close(p.velocity[0].z(), -1.0 - (1.0 - kAlpha) * g * kDt, to_string(form));
    // Unbalanced force = |m g|.
    expect_close(r.mean_unbalanced_force, p.mass[0] * g, "unbalanced");
  }
}

TEST(LocalDamping, PerComponentAndRotation) {
  // Force (F, 0, -F), velocity (0, V, V), torque (0, 0, T) from rest, PFC form:
  //   x: v = 0 -> undamped, v_x = u;   y: F_y = 0 -> v_y = V unchanged;
  //   z: v_z = V > 0 against -F -> (1 + alpha): v_z = V - (1 + alpha) u;
  //   rotation z from rest: undamped first step w_z = T dt / I, then (1 - alpha) per step.
  const double V = 0.1, T = 1e-3;
  ParticleArrays p = one_body(Vec3(0, V, V));
  const double m = p.mass[0], I = p.inertia[0], u = kForce * kDt / m, q = T * kDt / I;
  // I = 2/5 m R^2 (physics.md section 1).
  expect_close(I, 0.4 * m * 9e-6, "inertia");
  p.force[0] = Vec3(kForce, 0, -kForce);
  p.torque[0] = Vec3(0, 0, T);
  integrate_step(p, settings(DampingForm::kPfc), kDt);
  expect_close(p.velocity[0].x(), u, "v_x");
  EXPECT_EQ(p.velocity[0].y(), V);
  expect_close(p.velocity[0].z(), V - (1.0 + kAlpha) * u, "v_z");
  expect_close(p.angular_velocity[0].z(), q, "w_z step 1");
  integrate_step(p, settings(DampingForm::kPfc), kDt);
  expect_close(p.angular_velocity[0].z(), q * (2.0 - kAlpha), "w_z step 2");
  EXPECT_EQ(p.angular_velocity[0].x(), 0.0);
}

TEST(LocalDamping, ZeroAlphaIsPlainLeapfrog) {
  for (DampingForm form : {DampingForm::kPfc, DampingForm::kYade}) {
    ParticleArrays p = one_body(Vec3(-0.3, 0, 0));
    const double u = kForce * kDt / p.mass[0];
    p.force[0] = Vec3(kForce, 0, 0);
    IntegratorSettings s = settings(form);
    s.damping = 0.0;
    const IntegrationReport r = integrate_step(p, s, kDt);
    expect_close(p.velocity[0].x(), -0.3 + u, to_string(form));
    EXPECT_EQ(r.damping_work, 0.0);
  }
}
