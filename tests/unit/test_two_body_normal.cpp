// Head-on elastic collisions (physics.md section 2 step 1, section 3 leapfrog), no gravity,
// no damping, fixed dt.
//
// Closed form: while touching, the overlap un obeys m_red un'' = -Kn un (linear spring), a
// harmonic oscillator with omega = sqrt(Kn / m_red). Entering with closing speed v_rel at
// un = 0, it leaves at un = 0 after half a period,
//   t_contact = pi / omega = pi sqrt(m_red / Kn),
// with the maximum overlap un_max = v_rel / omega and the exit speed equal to the entry speed
// (restitution 1). Two equal spheres: m_red = m/2; series rule, equal entities: Kn = kn/2.
// Sphere on a fixed wall: m_red = m, Kn = kn_p kn_w / (kn_p + kn_w).
//
// Discrete-time errors (documented tolerances): the contact is "on" in the steps whose time
// t_k = k dt falls in an interval of length t_contact, so the number of contact steps is
// t_contact/dt within +-1; leapfrog shifts the oscillator frequency by a relative
// (omega dt)^2 / 24 and the amplitude by O((omega dt)^2); the force is continuous at un = 0
// (only its slope jumps), so the exit speed is exact to O((omega dt)^2).
#include <gtest/gtest.h>

#include <cmath>

#include "engine/stepper.hpp"

using namespace colza;

namespace {

struct CollisionResult {
  long contact_steps = 0;
  double max_overlap = 0.0;
  Vec3 v0_exit, v1_exit, w0_exit, w1_exit;
  long rebuilds = 0;
};

PhysicsSettings settings(double kn_p, double kn_w, double rho, double dt, StiffnessRule rule) {
  PhysicsSettings s;
  s.particle_materials = {{"seed", rho, kn_p, kn_p, 0.5}};
  s.wall_materials = {{"wall", kn_w, kn_w, 0.5}};
  s.stiffness_rule = rule;
  s.integrator.damping = 0.0;
  s.integrator.gravity = Vec3::Zero();
  s.time_step.automatic = false;
  s.time_step.fixed_dt = dt;
  s.skin = 1e-4;
  return s;
}

// Runs until the bodies have touched and separated again (plus a margin).
CollisionResult run(World& w, Stepper& st, bool wall) {
  CollisionResult r;
  bool seen = false;
  long after = 0;
  st.prepare(w);
  for (long n = 0; n < 2000000 && after < 100; ++n) {
    st.step(w, [&](const World& s) {
      const ContactHistory* h = nullptr;
      if (wall) {
        if (s.contacts.wall_pairs.size() > 0) h = &s.contacts.wall_pairs.history[0];
      } else if (s.contacts.particle_pairs.size() > 0) {
        h = &s.contacts.particle_pairs.history[0];
      }
      const bool touching = h && h->touching;
      if (touching) {
        ++r.contact_steps;
        seen = true;
        const double un = wall ? s.particles.radius[0] - s.particles.position[0].x()
                               : 2 * s.particles.radius[0] - (s.particles.position[1] - s.particles.position[0]).norm();
        r.max_overlap = std::max(r.max_overlap, un);
      } else if (seen) {
        ++after;
      }
    });
  }
  r.v0_exit = w.particles.velocity[0];
  r.w0_exit = w.particles.angular_velocity[0];
  if (!wall) {
    r.v1_exit = w.particles.velocity[1];
    r.w1_exit = w.particles.angular_velocity[1];
  }
  return r;
}

}  // namespace

TEST(TwoBodyNormal, EqualSpheresContactDurationAndRestitution) {
  // R = 5 mm, rho = 1000: m = 5.236e-4 kg; kn = 1e5 N/m -> Kn = 5e4 N/m, m_red = m/2,
  // t_contact = pi sqrt(m / kn) = 2.273e-4 s; dt = 5e-8 s -> 4546.6 steps, omega dt = 6.9e-4.
  const double R = 5e-3, rho = 1000.0, kn = 1e5, v0 = 0.05, dt = 5e-8, gap = 1e-6;
  World w;
  w.particles.add(Vec3(-R - gap / 2, 0, 0), R, rho, 0, Vec3(v0, 0, 0));
  w.particles.add(Vec3(R + gap / 2, 0, 0), R, rho, 0, Vec3(-v0, 0, 0));
  Stepper st(settings(kn, kn, rho, dt, StiffnessRule::kSeries));
  const double m = w.particles.mass[0];
  ASSERT_NEAR(m, rho * 4.0 / 3.0 * kPi * R * R * R, 1e-18);
  const double m_red = m / 2, Kn = kn / 2, omega = std::sqrt(Kn / m_red);
  const double t_contact = kPi * std::sqrt(m_red / Kn);
  const CollisionResult r = run(w, st, false);

  EXPECT_NEAR(static_cast<double>(r.contact_steps), t_contact / dt, 2.0);
  // un_max = v_rel / omega; sampling the peak at most dt/2 away loses (omega dt/2)^2/2 ~ 6e-8,
  // leapfrog amplitude error O((omega dt)^2) ~ 5e-7: relative tolerance 1e-5.
  EXPECT_NEAR(r.max_overlap, 2 * v0 / omega, 1e-5 * 2 * v0 / omega);
  // Restitution 1: exit speed = entry speed (relative (omega dt)^2 ~ 5e-7 -> 1e-6), reversed.
  EXPECT_NEAR(r.v0_exit.x(), -v0, 1e-6 * v0);
  EXPECT_NEAR(r.v1_exit.x(), v0, 1e-6 * v0);
  // Momentum: equal and opposite forces, equal masses.
  EXPECT_NEAR(r.v0_exit.x() + r.v1_exit.x(), 0.0, 1e-15);
  // Head-on: no tangential force, no spin, no sideways motion.
  EXPECT_EQ(r.v0_exit.y(), 0.0);
  EXPECT_EQ(r.v0_exit.z(), 0.0);
  EXPECT_EQ(r.w0_exit, Vec3::Zero());
  EXPECT_EQ(r.w1_exit, Vec3::Zero());
}

TEST(TwoBodyNormal, ContactRuleUsesKnDirectly) {
  // "contact" rule: Kn = kn = 1e5 N/m for the pair -> t_contact = pi sqrt(m_red / kn), shorter by
  // sqrt 2 than with the series rule. Head-on collision along a diagonal direction (the law must
  // not depend on the axes): n = (1, 2, 2)/3.
  const double R = 3e-3, rho = 1250.0, kn = 1e5, v0 = 0.1, dt = 2e-8, gap = 1e-6;
  const Vec3 n = Vec3(1, 2, 2) / 3.0;
  World w;
  w.particles.add(-(R + gap / 2) * n, R, rho, 0, v0 * n);
  w.particles.add((R + gap / 2) * n, R, rho, 0, -v0 * n);
  Stepper st(settings(kn, kn, rho, dt, StiffnessRule::kContact));
  const double m_red = w.particles.mass[0] / 2;
  const double t_contact = kPi * std::sqrt(m_red / kn);  // m_red = 7.07e-5 kg: 8.35e-5 s, ~4180 steps
  const CollisionResult r = run(w, st, false);
  EXPECT_NEAR(static_cast<double>(r.contact_steps), t_contact / dt, 2.0);
  EXPECT_NEAR(r.v0_exit.dot(n), -v0, 1e-6 * v0);
  EXPECT_NEAR(r.v1_exit.dot(n), v0, 1e-6 * v0);
  EXPECT_NEAR((r.v0_exit - r.v0_exit.dot(n) * n).norm(), 0.0, 1e-12 * v0);
  EXPECT_NEAR(r.max_overlap, 2 * v0 / std::sqrt(kn / m_red), 1e-5 * 2 * v0 / std::sqrt(kn / m_red));
}

TEST(TwoBodyNormal, SphereOnWallSeriesOfUnequalEntities) {
  // Sphere (kn_p = 437e3) hits a plane wall (kn_w = 4000e3) at x = 0 head-on: Kn = 393.96e3 N/m,
  // m_red = m (the wall does not move). R = 3 mm, rho = 1250: m = 1.4137e-4 kg,
  // t_contact = pi sqrt(m / Kn) = 5.95e-5 s; dt = 1e-8 s -> ~5950 steps.
  const double R = 3e-3, rho = 1250.0, kn_p = 437e3, kn_w = 4000e3, v = 0.2, dt = 1e-8, gap = 1e-6;
  World w;
  w.particles.add(Vec3(R + gap, 0, 0), R, rho, 0, Vec3(-v, 0, 0));
  w.walls.push_back(Wall::plane("wall", Vec3::Zero(), Vec3::UnitX()));
  Stepper st(settings(kn_p, kn_w, rho, dt, StiffnessRule::kSeries));
  const double m = w.particles.mass[0], Kn = kn_p * kn_w / (kn_p + kn_w);
  const CollisionResult r = run(w, st, true);
  EXPECT_NEAR(static_cast<double>(r.contact_steps), kPi * std::sqrt(m / Kn) / dt, 2.0);
  EXPECT_NEAR(r.max_overlap, v / std::sqrt(Kn / m), 1e-5 * v / std::sqrt(Kn / m));
  EXPECT_NEAR(r.v0_exit.x(), v, 1e-6 * v);
  EXPECT_EQ(r.w0_exit, Vec3::Zero());
}

TEST(TwoBodyNormal, ContactDurationConvergesWithDt) {
  // Halving dt: the count doubles (to +-2 steps), the measured duration stays within 2 dt of
  // pi sqrt(m_red / Kn) at both resolutions.
  const double R = 5e-3, rho = 1000.0, kn = 1e5, v0 = 0.05;
  const double t_contact = kPi * std::sqrt(rho * 4.0 / 3.0 * kPi * R * R * R / 2 / (kn / 2));
  for (double dt : {4e-7, 2e-7}) {
    World w;
    w.particles.add(Vec3(-R - 5e-7, 0, 0), R, rho, 0, Vec3(v0, 0, 0));
    w.particles.add(Vec3(R + 5e-7, 0, 0), R, rho, 0, Vec3(-v0, 0, 0));
    Stepper st(settings(kn, kn, rho, dt, StiffnessRule::kSeries));
    const CollisionResult r = run(w, st, false);
    EXPECT_NEAR(r.contact_steps * dt, t_contact, 2 * dt) << "dt = " << dt;
    // Restitution error is O((omega dt)^2): omega dt = 5.5e-3 / 2.8e-3 -> 3e-5 / 8e-6.
    const double wdt = std::sqrt(kn / 2 / (rho * 4.0 / 3.0 * kPi * R * R * R / 2)) * dt;
    EXPECT_NEAR(r.v1_exit.x(), v0, wdt * wdt * v0) << "dt = " << dt;
  }
}
