// Contact bonds through the whole step (Stepper): installation, tension break at Cn, shear
// break at Cs continuing as a frictional contact (physics.md section 2, step 5).
//
// Common numbers: spheres R = 5 mm, rho = 1000 kg/m^3 (m = 4/3 pi R^3 rho = 5.236e-4 kg), entity
// kn = ks = 1e5 N/m, series rule -> contact Kn = Ks = 5e4 N/m. No gravity, no damping.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/stepper.hpp"
#include "scenario/bonds.hpp"

using namespace colza;

namespace {

constexpr double kR = 5e-3, kRho = 1000.0, kEntityK = 1e5, kKn = 5e4, kKs = 5e4;

PhysicsSettings bond_settings(double cn, double cs, double mu, double dt, BondInstallMoment moment) {
  PhysicsSettings s;
  s.particle_materials = {{"seed", kRho, kEntityK, kEntityK, mu}};
  s.stiffness_rule = StiffnessRule::kSeries;
  s.model.bond = ContactBond{cn, cs};
  s.model.bond_install = moment;
  s.integrator.damping = 0.0;
  s.integrator.gravity = Vec3::Zero();
  s.time_step.automatic = false;
  s.time_step.fixed_dt = dt;
  s.skin = 1e-3;
  return s;
}

// The history of pair (0, 1), or nullptr if the pair is not in the candidate list.
const ContactHistory* pair01(const World& w) {
  const auto& l = w.contacts.particle_pairs;
  for (std::size_t c = 0; c < l.size(); ++c)
    if (l.first[c] == 0 && l.second[c] == 1) return &l.history[c];
  return nullptr;
}

double overlap01(const World& w) {
  return 2 * kR - (w.particles.position[1] - w.particles.position[0]).norm();
}

}  // namespace

TEST(Bonds, SeriesStiffnessOfTheTestMaterial) {
  const PairTable t({{"seed", kRho, kEntityK, kEntityK, 0.3}}, {}, StiffnessRule::kSeries);
  EXPECT_DOUBLE_EQ(t.particle_particle(0, 0).kn, kKn);
  EXPECT_DOUBLE_EQ(t.particle_particle(0, 0).ks, kKs);
}

// Pulling a bonded pair apart with prescribed motion (both spheres fixed = 1, sphere 1 moving
// away at v along the normal): un(t) = un0 - v t, Fn = Kn un each step (tension allowed), and the
// bond breaks on the first step with -Kn un > Cn. The last tension carried therefore lies in
// (Cn - Kn v dt, Cn]; the contact disappears with the bond and carries no force from then on.
TEST(Bonds, TensionBreakAtCnUnderPrescribedPull) {
  const double cn = 0.5, v = 0.01, dt = 1e-6, un0 = 1e-6;
  World w;
  w.particles.add(Vec3::Zero(), kR, kRho);
  w.particles.add(Vec3(2 * kR - un0, 0, 0), kR, kRho, 0, Vec3(v, 0, 0));
  w.particles.fixed[0] = w.particles.fixed[1] = 1;
  Stepper st(bond_settings(cn, 100.0, 0.3, dt, BondInstallMoment::kBeforeLoading));
  st.prepare(w);
  ASSERT_EQ(install_bonds(w, st, 0.0), 1u);

  double max_tension = 0.0, last_fn = 0.0;
  long break_step = -1;
  for (long n = 0; n < 3000; ++n) {
    st.step(w, [&](const World& s) {
      const ContactHistory* h = pair01(s);
      ASSERT_NE(h, nullptr);
      const double un = overlap01(s);
      if (break_step < 0 && h->touching) {
        // Step 1 of the law, tension included: Fn = Kn un.
        ASSERT_NEAR(h->normal_force, kKn * un, 1e-12) << "step " << n;
        ASSERT_EQ(h->bonded, 1);
        ASSERT_LE(-h->normal_force, cn) << "tension above Cn carried at step " << n;
        max_tension = std::max(max_tension, -h->normal_force);
        last_fn = h->normal_force;
        // Force on sphere 1 = Fn n, n = +x (bond pulls it back while in tension).
        ASSERT_NEAR((s.particles.force[1] - Vec3(h->normal_force, 0, 0)).norm(), 0.0, 1e-12);
      } else if (break_step < 0) {
        break_step = n;
        EXPECT_GT(-kKn * un, cn) << "broke although -Kn un <= Cn";
        EXPECT_EQ(h->bonded, 0);
        EXPECT_EQ(s.particles.force[1], Vec3::Zero()) << "no force in the breaking step";
      } else {
        EXPECT_EQ(h->touching, 0);
        EXPECT_EQ(s.particles.force[1], Vec3::Zero());
      }
    });
  }
  ASSERT_GE(break_step, 0) << "bond never broke";
  EXPECT_LE(max_tension, cn);
  EXPECT_GT(max_tension, cn - kKn * v * dt);  // Kn v dt = 5e-4 N
  // Break time: un0 - v t_b = -Cn/Kn -> t_b = (un0 + Cn/Kn) / v = 1.1e-3 s = 1100 steps
  // (the step index n counts from 0 at t = 0; allow one step for rounding at the threshold).
  EXPECT_NEAR(static_cast<double>(break_step), (un0 + cn / kKn) / v / dt, 1.0);
  EXPECT_EQ(st.events().bonds_broken_tension, 1u);
  EXPECT_EQ(st.events().bonds_broken_shear, 0u);
  EXPECT_EQ(w.contacts.bonded_contacts(), 0u);
  // The elastic energy of the last loaded state, 1/2 Fn^2 / Kn, is booked as released.
  EXPECT_NEAR(st.ledger().bond_break_lost, 0.5 * last_fn * last_fn / kKn, 1e-18);
}

// Shearing a bonded, compressed pair with prescribed motion: sphere 1 on top of sphere 0
// (normal +z, overlap un0 -> Fn = Kn un0 = 0.5 N) moves along +x at v. Each step adds
// Ks v dt = 5e-4 N to |Fs| (v is tangential; the normal tilts by < 1e-3 rad, which changes
// |Fs| by O(theta^2) ~ 1e-6 relative), opposing the motion: |Fs_n| = n Ks v dt.
//  * While bonded there is no friction cap: |Fs| exceeds mu Fn = 0.15 N and stays <= Cs.
//  * The bond breaks on the first step with n Ks v dt > Cs, i.e. n = floor(Cs / (Ks v dt)) + 1
//    = floor(800.4) + 1 = 801 for Cs = 0.4002 N, and in that step |Fs| = mu Fn.
//  * The contact lives on: touching, unbonded, sliding with |Fs| = mu Fn every later step.
TEST(Bonds, ShearBreakAtCsThenFrictionalContact) {
  const double cs = 0.4002, mu = 0.3, v = 0.01, dt = 1e-6, un0 = 1e-5;
  World w;
  w.particles.add(Vec3::Zero(), kR, kRho);
  w.particles.add(Vec3(0, 0, 2 * kR - un0), kR, kRho, 0, Vec3(v, 0, 0));
  w.particles.fixed[0] = w.particles.fixed[1] = 1;
  Stepper st(bond_settings(100.0, cs, mu, dt, BondInstallMoment::kBeforeLoading));
  st.prepare(w);
  ASSERT_EQ(install_bonds(w, st, 0.0), 1u);

  long break_step = -1;
  bool exceeded_friction_while_bonded = false;
  for (long n = 1; n <= 1000; ++n) {
    st.step(w, [&](const World& s) {
      const ContactHistory* h = pair01(s);
      ASSERT_NE(h, nullptr);
      ASSERT_EQ(h->touching, 1) << "step " << n;
      const double un = overlap01(s);
      const double fn = kKn * un;
      ASSERT_NEAR(h->normal_force, fn, 1e-12);
      const double fs = h->shear_force.norm();
      // Fs lies in the tangent plane and opposes the motion of sphere 1 (+x).
      const Vec3 nrm = (s.particles.position[1] - s.particles.position[0]).normalized();
      ASSERT_NEAR(h->shear_force.dot(nrm), 0.0, 1e-6 * fs + 1e-15);
      ASSERT_LT(h->shear_force.x(), 0.0);
      // Force on sphere 1 = Fn n + Fs.
      ASSERT_NEAR((s.particles.force[1] - (fn * nrm + h->shear_force)).norm(), 0.0, 1e-9);
      if (h->bonded) {
        ASSERT_LT(break_step, 0) << "re-bonded";
        ASSERT_LE(fs, cs);
        EXPECT_NEAR(fs, n * kKs * v * dt, 1e-5 * n * kKs * v * dt) << "step " << n;
        if (fs > mu * fn * (1 + 1e-6)) exceeded_friction_while_bonded = true;
      } else {
        if (break_step < 0) {
          break_step = n;
          EXPECT_EQ(st.events().bonds_broken_shear, 1u);
        }
        // Coulomb limit from the breaking step on (sliding: the motion goes on).
        EXPECT_NEAR(fs, mu * fn, 1e-12 * mu * fn) << "step " << n;
      }
    });
  }
  EXPECT_TRUE(exceeded_friction_while_bonded) << "test does not exercise 'no friction cap while bonded'";
  EXPECT_EQ(break_step, 801);
  EXPECT_EQ(st.events().bonds_broken_shear, 1u);
  EXPECT_EQ(st.events().bonds_broken_tension, 0u);
  EXPECT_EQ(w.contacts.touching_particle_contacts(), 1u);
  EXPECT_EQ(w.contacts.bonded_contacts(), 0u);
}

// Install moment "on_new_contacts": two free spheres collide head-on; the contact is bonded the
// step it forms, so after the rebound the bond holds in tension until -Fn > Cn.
// Undamped oscillator with reduced mass m/2 and Kn: the overlap swings to -un_max =
// -v_rel / omega, omega = sqrt(Kn / (m/2)); the tension would reach Kn un_max = 0.362 N > Cn = 0.2 N,
// so the bond breaks. Energy: 1/2 m_red v_rel^2 = 1/2 m_red v'^2 + 1/2 F_b^2 / Kn (the elastic
// energy of the last loaded state is lost with the contact), F_b in (Cn - Kn dun_max, Cn] with
// dun_max = v_rel dt the largest overlap change per step (tolerances derived at the assertions).
TEST(Bonds, OnNewContactsBondBreaksInTensionAfterRebound) {
  const double cn = 0.2, v0 = 0.05, dt = 5e-8, gap0 = 1e-7;
  World w;
  w.particles.add(Vec3(-kR - gap0 / 2, 0, 0), kR, kRho, 0, Vec3(v0, 0, 0));
  w.particles.add(Vec3(kR + gap0 / 2, 0, 0), kR, kRho, 0, Vec3(-v0, 0, 0));
  Stepper st(bond_settings(cn, 100.0, 0.3, dt, BondInstallMoment::kOnNewContacts));
  st.prepare(w);
  const double m = w.particles.mass[0], m_red = m / 2, v_rel = 2 * v0;
  ASSERT_GT(kKn * v_rel / std::sqrt(kKn / m_red), cn);  // the tension would exceed Cn

  bool was_bonded = false, broke = false;
  double max_tension = 0.0, last_fn = 0.0;
  for (int n = 0; n < 12000; ++n) {
    st.step(w, [&](const World& s) {
      const ContactHistory* h = pair01(s);
      if (!h || !h->touching) {
        if (was_bonded) broke = true;
        return;
      }
      ASSERT_FALSE(broke) << "contact re-formed";
      ASSERT_EQ(h->bonded, 1) << "a new contact must be bonded at once";
      was_bonded = true;
      ASSERT_LE(-h->normal_force, cn);
      max_tension = std::max(max_tension, -h->normal_force);
      last_fn = h->normal_force;
    });
  }
  ASSERT_TRUE(broke);
  EXPECT_EQ(st.events().bonds_broken_tension, 1u);
  EXPECT_LE(max_tension, cn);
  EXPECT_GT(max_tension, cn - kKn * v_rel * dt);
  EXPECT_NEAR(st.ledger().bond_break_lost, 0.5 * last_fn * last_fn / kKn, 1e-18);
  // Exit: momentum conserved (equal and opposite forces), relative speed from the energy balance.
  const double v1 = w.particles.velocity[1].x(), v0_after = w.particles.velocity[0].x();
  EXPECT_NEAR(v1 + v0_after, 0.0, 1e-12);
  const double v_exit = v1 - v0_after;  // separating: > 0
  const double expected = std::sqrt(v_rel * v_rel - cn * cn / (kKn * m_red));
  // Tolerances: (a) F_b's range: d v' = F_b dF / (Kn m_red v') with dF = Kn v_rel dt;
  // (b) the force jumps from -F_b to 0 between two steps, so where inside that step the break
  // "happens" is undetermined: an impulse of up to F_b dt (one kick), i.e. d v' <= F_b dt / m_red
  // (0.2 * 5e-8 / 2.6e-4 = 3.8e-5 m/s; smooth parts contribute only O((omega dt)^2) ~ 5e-7).
  const double tol_range = cn * kKn * v_rel * dt / (kKn * m_red * expected);
  const double tol_kick = cn * dt / m_red;
  EXPECT_NEAR(v_exit, expected, tol_range + tol_kick);
  // With the measured F_b only the kick ambiguity remains.
  EXPECT_NEAR(v_exit, std::sqrt(v_rel * v_rel - last_fn * last_fn / (kKn * m_red)), tol_kick);
}
