// Coulomb sliding limit of a sphere on a plane wall (physics.md section 2, steps 3-4):
// |Fs| <= mu_pw Fn always, = mu_pw Fn while sliding, < mu_pw Fn while sticking.
//
// Common numbers: R = 5 mm, rho = 1000 (m = 5.236e-4 kg, I = 2/5 m R^2), particle and wall entity
// kn = ks = 1e5 N/m, series -> Kn = Ks = 5e4 N/m; no damping. The sphere starts at rest at its
// static overlap un = m g_n / Kn (g_n the normal component of gravity), so Fn = m g_n from the
// first step with no normal oscillation (gravity and the spring balance exactly up to rounding).
// Lever arm of the contact force: R' = R - un/2 (contact point in the middle of the overlap).
#include <gtest/gtest.h>

#include <cmath>

#include "engine/stepper.hpp"

using namespace colza;

namespace {

constexpr double kR = 5e-3, kRho = 1000.0, kK = 1e5, kKn = 5e4, kKs = 5e4, kG = 9.81;

PhysicsSettings settings(double mu_pw, double dt, const Vec3& g) {
  PhysicsSettings s;
  s.particle_materials = {{"seed", kRho, kK, kK, 0.9 /* mu_pp: unused here, must not matter */}};
  s.wall_materials = {{"floor", kK, kK, mu_pw}};
  s.stiffness_rule = StiffnessRule::kSeries;
  s.integrator.damping = 0.0;
  s.integrator.gravity = g;
  s.time_step.automatic = false;
  s.time_step.fixed_dt = dt;
  s.skin = 1e-3;
  return s;
}

double mass() { return kRho * 4.0 / 3.0 * kPi * kR * kR * kR; }

struct Sample {
  double fn, fs, fs_x;
  Vec3 v, w;
  Vec3 wall_force;
  bool touching;
};

}  // namespace

// A plane wall moving tangentially (+x at U) under a sphere resting on it (gravity -z).
// The shear spring loads by Ks U dt per step until |Fs| = mu Fn = mu m g, then the contact
// slides with friction mu m g on the sphere (+x) and -mu m g on the wall. Sliding
// accelerates the sphere at a = mu g and spins it (torque R' mu m g), so the contact point's
// velocity v_c = v + omega R' grows at mu g (1 + m R'^2 / I) until it reaches U:
//   t_slip = U / (mu g (1 + m R'^2 / I)),   v(t_slip) = mu g t_slip.
// Energy: the wall's work mu m g U t_slip = KE + slip + shear-spring energy.
TEST(CoulombSliding, MovingWallDragsSphereAtTheFrictionLimit) {
  const double mu = 0.3, U = 0.01, dt = 1e-6;
  const double m = mass(), I = 0.4 * m * kR * kR, un = m * kG / kKn, Rp = kR - un / 2;
  World w;
  w.particles.add(Vec3(0, 0, kR - un), kR, kRho);
  w.walls.push_back(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  w.walls[0].velocity = Vec3(U, 0, 0);
  Stepper st(settings(mu, dt, Vec3(0, 0, -kG)));
  st.prepare(w);

  const double fn0 = m * kG;
  const double t_slip = U / (mu * kG * (1 + m * Rp * Rp / I));  // = U / (3.5 mu g) = 9.7e-4 s
  const long n_load = static_cast<long>(std::ceil(mu * fn0 / (kKs * U * dt)));  // 4 steps to load the spring
  long slip_end = -1;
  double v_at_slip_end = 0.0, work_at_slip_end = 0.0, slip_at_slip_end = 0.0;
  for (long n = 0; n < 3000; ++n) {
    st.step(w, [&](const World& s) {
      ASSERT_EQ(s.contacts.touching_wall_contacts(), 1u);
      const ContactHistory& h = s.contacts.wall_pairs.history[0];
      const double fn = h.normal_force, fs = h.shear_force.norm();
      // Static normal load: Fn = m g (spring and gravity balance; Fs is tangential).
      ASSERT_NEAR(fn, fn0, 1e-9 * fn0) << "step " << n;
      // Never above the Coulomb limit.
      ASSERT_LE(fs, mu * fn * (1 + 1e-12)) << "step " << n;
      // The wall feels the opposite of the contact force on the sphere.
      ASSERT_NEAR((s.walls[0].force + (fn * Vec3::UnitZ() + h.shear_force)).norm(), 0.0, 1e-15);
      if (n >= n_load && slip_end < 0) {
        if (fs >= mu * fn * (1 - 1e-12)) {
          // Sliding: exactly at the limit, friction on the sphere along the wall's motion (+x).
          ASSERT_NEAR(fs, mu * fn, 1e-12 * mu * fn) << "step " << n;
          ASSERT_GT(h.shear_force.x(), 0.0);
          ASSERT_NEAR(h.shear_force.y(), 0.0, 1e-15);
        } else {
          slip_end = n;  // the contact point caught up with the wall: sticking from here on
          v_at_slip_end = s.particles.velocity[0].x();
          work_at_slip_end = st.ledger().wall_work;
          slip_at_slip_end = st.ledger().slip_dissipated;
        }
      }
    });
  }
  ASSERT_GT(slip_end, 0) << "never stopped sliding";
  // Slip ends at t_slip, up to the loading steps and one step of detection.
  EXPECT_NEAR(slip_end * dt, t_slip, (n_load + 2) * dt);
  // v(t_slip) = mu g t_slip = U / (1 + m R'^2 / I) ~ U / 3.5: within the velocity change of
  // (n_load + 2) steps, mu g dt each.
  EXPECT_NEAR(v_at_slip_end, mu * kG * t_slip, (n_load + 2) * mu * kG * dt);
  // Wall work up to then: mu m g U t_slip (= m U^2 / (1 + m R'^2 / I) ~ m U^2 / 3.5), same tolerance
  // in time; slip dissipation = work - kinetic energy at t_slip - stored shear energy, with
  // v = mu g t_slip and omega R' = U - v (contact point moving with the wall):
  //   KE = 1/2 m v^2 + 1/2 I ((U - v) / R')^2,  shear spring 1/2 (mu m g)^2 / Ks.
  EXPECT_NEAR(work_at_slip_end, mu * fn0 * U * t_slip, (n_load + 2) * mu * fn0 * U * dt);
  const double v = mu * kG * t_slip, om = (U - v) / Rp;
  const double ke = 0.5 * m * v * v + 0.5 * I * om * om;
  const double spring = 0.5 * (mu * fn0) * (mu * fn0) / kKs;
  EXPECT_NEAR(slip_at_slip_end, mu * fn0 * U * t_slip - ke - spring, (n_load + 2) * mu * fn0 * U * dt);
  // After sticking the sphere rolls on the wall; nothing slides any more (the shear spring
  // oscillates with amplitude <= mu m g, checked above to never exceed the limit).
}

// Tilted gravity = a sphere on an incline of angle theta (normal load m g cos(theta),
// downhill pull m g sin(theta) along +x). Rolling without slip needs the friction
// f = m g sin(theta) / (1 + m R'^2 / I) = 2/7 m g sin(theta) (R' = R) and gives
// a = g sin(theta) / (1 + I / (m R'^2)) = 5/7 g sin(theta). Starting from Fs = 0, the undamped
// shear spring overshoots to 2 f, so it never slips if 2 f < mu m g cos(theta), i.e.
// tan(theta) < 7/4 mu. tan(theta) = 0.2, mu = 0.3: 2 f / (mu Fn) = 0.38 -> sticks throughout.
TEST(CoulombSliding, BelowTheLimitTheSphereRollsWithoutSlip) {
  const double mu = 0.3, dt = 1e-6, theta = std::atan(0.2);
  const double m = mass(), I = 0.4 * m * kR * kR;
  const double fn0 = m * kG * std::cos(theta), un = fn0 / kKn, Rp = kR - un / 2;
  const Vec3 g(kG * std::sin(theta), 0, -kG * std::cos(theta));
  World w;
  w.particles.add(Vec3(0, 0, kR - un), kR, kRho);
  w.walls.push_back(Wall::plane("incline", Vec3::Zero(), Vec3::UnitZ()));
  Stepper st(settings(mu, dt, g));
  st.prepare(w);
  const long steps = 20000;  // 0.02 s
  double max_ratio = 0.0;
  for (long n = 0; n < steps; ++n) {
    st.step(w, [&](const World& s) {
      const ContactHistory& h = s.contacts.wall_pairs.history[0];
      ASSERT_NEAR(h.normal_force, fn0, 1e-9 * fn0);
      max_ratio = std::max(max_ratio, h.shear_force.norm() / (mu * h.normal_force));
    });
  }
  EXPECT_LT(max_ratio, 1.0);
  // The discrete peak differs from the continuous 2 f by the leapfrog's phase error and by
  // sampling the peak once a step, both O((omega_t dt)^2) relative, omega_t = sqrt(Ks (1 + m R'^2
  // / I) / m) = 1.83e4 rad/s the shear spring's frequency against the rolling sphere: 3.3e-4
  // (measured 2.1e-5).
  const double expected = 2 * m * kG * std::sin(theta) / (1 + m * Rp * Rp / I) / (mu * fn0);
  const double omega_t = std::sqrt(kKs * (1 + m * Rp * Rp / I) / m);
  EXPECT_NEAR(max_ratio, expected, std::pow(omega_t * dt, 2) * expected);
  EXPECT_EQ(st.ledger().slip_dissipated, 0.0);
  // Mean acceleration 5/7 g sin(theta): x_n = 1/2 a (n dt)^2, up to the spring's stretch
  // (|Fs - f| / Ks <= f / Ks = 5.7e-9 m) and the leapfrog start offset a dt^2 n / 2.
  const double a = kG * std::sin(theta) / (1 + I / (m * Rp * Rp));
  const double f = m * kG * std::sin(theta) - m * a;
  const double T = steps * dt;
  EXPECT_NEAR(w.particles.position[0].x(), 0.5 * a * T * T, f / kKs + a * dt * T / 2 + 1e-12);
  // Rolling: contact point at rest, v = omega R' (omega about +y for motion along +x), up to the
  // spring's oscillation velocity f/Ks * omega_t, omega_t = sqrt(Ks (1 + m R'^2 / I) / m).
  const double osc = f / kKs * std::sqrt(kKs * (1 + m * Rp * Rp / I) / m);
  EXPECT_NEAR(w.particles.velocity[0].x(), w.particles.angular_velocity[0].y() * Rp, 2 * osc);
}

// tan(theta) = 1.5 > 7/2 mu = 1.05: the sphere slides from the start. After the few steps that
// load the spring, friction = mu m g cos(theta) exactly, and the centre accelerates at
// a = g (sin(theta) - mu cos(theta)); the spin grows at mu m g cos(theta) R' / I.
TEST(CoulombSliding, AboveTheLimitTheSphereSlidesWithFrictionMuFn) {
  const double mu = 0.3, dt = 1e-6, theta = std::atan(1.5);
  const double m = mass(), I = 0.4 * m * kR * kR;
  const double fn0 = m * kG * std::cos(theta), un = fn0 / kKn, Rp = kR - un / 2;
  const Vec3 g(kG * std::sin(theta), 0, -kG * std::cos(theta));
  World w;
  w.particles.add(Vec3(0, 0, kR - un), kR, kRho);
  w.walls.push_back(Wall::plane("incline", Vec3::Zero(), Vec3::UnitZ()));
  Stepper st(settings(mu, dt, g));
  st.prepare(w);
  const long steps = 10000;
  long sliding_steps = 0;
  for (long n = 0; n < steps; ++n) {
    st.step(w, [&](const World& s) {
      const ContactHistory& h = s.contacts.wall_pairs.history[0];
      const double fs = h.shear_force.norm(), lim = mu * h.normal_force;
      ASSERT_LE(fs, lim * (1 + 1e-12));
      ASSERT_LE(h.shear_force.x(), 0.0);  // uphill, against the sliding
      if (fs >= lim * (1 - 1e-12)) ++sliding_steps;
    });
  }
  // Spring loading: the contact point accelerates downhill at a_cp >= a = g (sin - mu cos) while
  // |Fs| < mu Fn, so |Fs| = Ks a_cp t^2 / 2 reaches mu Fn within t_load <= sqrt(2 mu Fn / (Ks a))
  // = 7.2e-5 s, i.e. n_load <= 73 steps; every later step slides.
  const double a = kG * (std::sin(theta) - mu * std::cos(theta));
  const long n_load = static_cast<long>(std::ceil(std::sqrt(2 * mu * fn0 / (kKs * a)) / dt)) + 1;
  EXPECT_GE(sliding_steps, steps - n_load);
  const double T = steps * dt;
  // v = a T up to the loading phase, during which the friction was below mu Fn (at most
  // mu g cos(theta) dt per step of extra acceleration, n_load steps); the spin likewise.
  EXPECT_NEAR(w.particles.velocity[0].x(), a * T, n_load * mu * kG * std::cos(theta) * dt);
  EXPECT_NEAR(w.particles.angular_velocity[0].y(), mu * fn0 * Rp / I * T, n_load * mu * fn0 * Rp / I * dt);
  EXPECT_GT(st.ledger().slip_dissipated, 0.0);
}
