// Energy bookkeeping with damping off (physics.md sections 2-3, engine/energy.hpp):
//   E = kinetic + gravitational + elastic_normal + elastic_shear   (Stepper::energy)
//     + slip_dissipated + damping_dissipated + bond_break_lost + shear_break_released - wall_work   (ledger)
// must stay constant.
//
// Tolerance derivation.
// (1) Mid-step velocities. Stepper::energy() evaluates the kinetic energy with the stored
//     leapfrog velocities v(t - dt/2) but positions/forces at t. Against the on-step kinetic
//     energy (v(t) = v(t - dt/2) + dt/2 a(t)) this is an offset KE_mid - KE_on =
//     -dt/2 sum F(t) . v(t) + O(dt^2): FIRST order in dt while forces do work. We therefore
//     evaluate E with the on-step kinetic energy (computed here from v(t - dt/2), F(t), T(t),
//     m, I); leapfrog conserves that to O((omega dt)^2) relative, omega the contact frequency.
//     Where no force acts (free flight, no gravity) the two coincide, and Stepper::energy() is
//     checked as it is.
// (2) Slip bookkeeping. Over one step the contact force on the bodies changes from F_old (the
//     stored shear force carried into the new tangent plane) to F_c (after the Coulomb cap or a
//     bond break), while the relative tangential displacement is ds = (F_old - F_trial) / Ks.
//     Leapfrog's on-step energy changes by the trapezoidal work (F_old + F_c)/2 . ds, so the
//     energy that leaves the system in that step is exactly
//        D = (F_old + F_c) . (F_trial - F_c) / (2 Ks)
//     (= stored-energy drop (|F_trial|^2 - |F_c|^2)/(2 Ks) minus the extra work, see the algebra
//     at `consistent_dissipation`). colza books (F_trial - F_c) . F_c / Ks (YADE's formula,
//     slots.hpp), which differs from D by (F_old - F_c) . (F_trial - F_c) / (2 Ks): O(dt^2) per
//     step while sliding, hence O(dt) over a sliding phase, and O(1) at a shear bond break or when
//     the cap collapses as Fn -> 0. The tests recompute the trial force from the spec (physics.md
//     step 2-3) for every contact, accumulate D, and
//       (a) require E_on + ledger + (sum D - booked slip) to be constant to (omega dt)^2 E0;
//       (b) require the code's own ledger to be constant to that plus |sum D - booked slip|.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "engine/stepper.hpp"
#include "scenario/bonds.hpp"

using namespace colza;

namespace {

constexpr double kR = 5e-3, kRho = 1000.0, kK = 1e5;  // entity kn = ks = 1e5 -> Kn = Ks = 5e4 (series)

PhysicsSettings settings(double mu, double dt, const Vec3& g, double damping = 0.0) {
  PhysicsSettings s;
  s.particle_materials = {{"seed", kRho, kK, kK, mu}};
  s.wall_materials = {{"wall", kK, kK, mu}};
  s.stiffness_rule = StiffnessRule::kSeries;
  s.integrator.damping = damping;
  s.integrator.gravity = g;
  s.time_step.automatic = false;
  s.time_step.fixed_dt = dt;
  s.skin = 1e-4;
  return s;
}

double ledger_total(const EnergyLedger& l) {
  return l.slip_dissipated + l.damping_dissipated + l.bond_break_lost + l.shear_break_released - l.wall_work;
}

double kinetic_mid(const World& w) {
  const ParticleArrays& p = w.particles;
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    e += 0.5 * p.mass[i] * p.velocity[i].squaredNorm() + 0.5 * p.inertia[i] * p.angular_velocity[i].squaredNorm();
  return e;
}

// On-step estimate v + dt/2 a (damping off; fixed particles move at their prescribed velocity).
double kinetic_on_step(const World& w, const Vec3& g) {
  const ParticleArrays& p = w.particles;
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    Vec3 v = p.velocity[i], om = p.angular_velocity[i];
    if (!p.fixed[i]) {
      v += 0.5 * w.dt * (p.force[i] / p.mass[i] + g);
      om += 0.5 * w.dt * p.torque[i] / p.inertia[i];
    }
    e += 0.5 * p.mass[i] * v.squaredNorm() + 0.5 * p.inertia[i] * om.squaredNorm();
  }
  return e;
}

// D = (F_old + F_c) . (F_trial - F_c) / (2 Ks), with F_old the stored shear force carried into
// the new tangent plane (physics.md step 2) and F_trial = F_old - Ks dus (step 3).
// Algebra: the step's relative tangential displacement is ds = (F_old - F_trial)/Ks, the
// trapezoidal work on the bodies W = (F_old + F_c)/2 . ds, the stored-energy change
// (|F_c|^2 - |F_old|^2)/(2 Ks); D = -W - dE_stored = (F_old + F_c).(F_trial - F_c)/(2 Ks).
double consistent_dissipation(const Vec3& f_old, const Vec3& f_trial, const Vec3& f_c, double ks) {
  return (f_old + f_c).dot(f_trial - f_c) / (2.0 * ks);
}

// Tracks sum D over all contacts, step by step.
class SlipAudit {
 public:
  void observe(const World& w, const PairTable& pairs) {
    const ParticleArrays& p = w.particles;
    const double dt = w.dt;
    std::map<std::pair<long, long>, ContactHistory> now;
    const auto& pp = w.contacts.particle_pairs;
    for (std::size_t c = 0; c < pp.size(); ++c) {
      const ContactHistory& h = pp.history[c];
      if (!h.touching) continue;
      const Index i = pp.first[c], j = pp.second[c];
      const Vec3 d = p.position[j] - p.position[i];
      const Vec3 n = d.normalized();
      const double un = p.radius[i] + p.radius[j] - d.norm();
      const Vec3 pt = p.position[i] + (p.radius[i] - 0.5 * un) * n;
      const Vec3 vr = (p.velocity[j] + p.angular_velocity[j].cross(pt - p.position[j])) -
                      (p.velocity[i] + p.angular_velocity[i].cross(pt - p.position[i]));
      const double twist = 0.5 * dt * (p.angular_velocity[i] + p.angular_velocity[j]).dot(n);
      add({static_cast<long>(i), static_cast<long>(j)}, h, n, (vr - vr.dot(n) * n) * dt, twist,
          pairs.particle_particle(p.material[i], p.material[j]).ks);
      now[{static_cast<long>(i), static_cast<long>(j)}] = h;
    }
    const auto& pw = w.contacts.wall_pairs;
    for (std::size_t c = 0; c < pw.size(); ++c) {
      const ContactHistory& h = pw.history[c];
      if (!h.touching) continue;
      const Wall& wall = w.walls[pw.wall[c]];
      const Index i = pw.particle[c];
      const WallContactGeometry g = wall_sphere_geometry(wall, p.position[i], p.radius[i]);
      const Vec3 vr = p.velocity[i] + p.angular_velocity[i].cross(g.point - p.position[i]) - wall.velocity;
      const double twist = 0.5 * dt * p.angular_velocity[i].dot(g.normal);
      const std::pair<long, long> key{-1 - static_cast<long>(pw.wall[c]), static_cast<long>(i)};
      add(key, h, g.normal, (vr - vr.dot(g.normal) * g.normal) * dt, twist,
          pairs.particle_wall(p.material[i], wall.material).ks);
      now[key] = h;
    }
    previous_ = std::move(now);
  }
  double total() const { return sum_; }

 private:
  void add(const std::pair<long, long>& key, const ContactHistory& h, const Vec3& n, const Vec3& dus, double twist,
           double ks) {
    Vec3 f_old = Vec3::Zero();
    if (auto it = previous_.find(key); it != previous_.end()) {
      f_old = it->second.shear_force;
      f_old -= f_old.cross(it->second.normal.cross(n));
      f_old -= f_old.cross(twist * n);
    }
    const Vec3 f_trial = f_old - ks * dus;
    sum_ += consistent_dissipation(f_old, f_trial, h.shear_force, ks);
  }
  std::map<std::pair<long, long>, ContactHistory> previous_;
  double sum_ = 0.0;
};

struct EnergyRun {
  double e0 = 0.0;              // on-step total at the first step
  double dev_code = 0.0;        // max |E_on + ledger - e0|
  double dev_consistent = 0.0;  // max |E_on + ledger + (sum D - booked slip) - e0|
  double max_correction = 0.0;  // max |sum D - booked slip|
  double end_dev_mid = 0.0;     // Stepper::energy() + ledger - e0 at the last step
  double max_dev_mid = 0.0;
  double slip = 0.0;
  std::uint64_t broken_shear = 0;
};

EnergyRun run_energy(World& w, Stepper& st, long steps, bool install = false) {
  EnergyRun r;
  const Vec3 g = st.physics().integrator.gravity;
  st.prepare(w);
  if (install) install_bonds(w, st, 0.0);
  SlipAudit audit;
  for (long n = 0; n < steps; ++n) {
    st.step(w, [&](const World& s) {
      audit.observe(s, st.pairs());
      const double mid = st.energy(s).total_stored() + ledger_total(st.ledger());
      const double on = mid - kinetic_mid(s) + kinetic_on_step(s, g);
      const double correction = audit.total() - st.ledger().slip_dissipated - st.ledger().shear_break_released;
      if (n == 0) r.e0 = on;
      r.dev_code = std::max(r.dev_code, std::abs(on - r.e0));
      r.dev_consistent = std::max(r.dev_consistent, std::abs(on + correction - r.e0));
      r.max_correction = std::max(r.max_correction, std::abs(correction));
      r.max_dev_mid = std::max(r.max_dev_mid, std::abs(mid - r.e0));
      r.end_dev_mid = mid - r.e0;
    });
  }
  r.slip = st.ledger().slip_dissipated;
  r.broken_shear = st.events().bonds_broken_shear;
  return r;
}

double sphere_mass() { return kRho * 4.0 / 3.0 * kPi * kR * kR * kR; }

// Contact frequency of two equal spheres: omega = sqrt(Kn / (m/2)), Kn = kK/2.
double omega_pair() { return std::sqrt(kK / 2 / (sphere_mass() / 2)); }

// Oblique collision of two free spheres, no gravity: impact parameter b = R, so the normal is at
// 30 deg to the approach velocity (tangential 0.05 m/s, normal 0.087 m/s); shear forces spin them.
EnergyRun oblique(double dt, double mu, const ContactModel& model = {}, bool install = false) {
  const double v0 = 0.05, gap = 2e-7;
  World w;
  const double x1 = std::sqrt((2 * kR + gap) * (2 * kR + gap) - kR * kR);
  w.particles.add(Vec3::Zero(), kR, kRho, 0, Vec3(v0, 0, 0));
  w.particles.add(Vec3(x1, kR, 0), kR, kRho, 0, Vec3(-v0, 0, 0));
  PhysicsSettings s = settings(mu, dt, Vec3::Zero());
  s.model = model;
  Stepper st(s);
  // Contact lasts pi sqrt(m_red / Kn) = 2.3e-4 s; run 3.2e-4 s including the approach.
  return run_energy(w, st, static_cast<long>(3.2e-4 / dt), install);
}

void check_oblique(double mu, double dt) {
  const EnergyRun a = oblique(dt, mu), b = oblique(dt / 2, mu);
  const double e0 = sphere_mass() * 0.05 * 0.05;  // 2 x 1/2 m v0^2
  EXPECT_NEAR(a.e0, e0, 1e-12 * e0);
  for (const EnergyRun* r : {&a, &b}) {
    const double h = (r == &a) ? dt : dt / 2;
    const double tol = std::pow(omega_pair() * h, 2) * e0;
    SCOPED_TRACE("dt = " + std::to_string(h));
    // (a) the contact law itself conserves energy to second order,
    EXPECT_LT(r->dev_consistent, tol);
    // (b) the code's ledger differs only by its slip formula's first-order term,
    EXPECT_LT(r->dev_code, tol + r->max_correction);
    // and after separation Stepper::energy() (mid-step) agrees with that.
    EXPECT_LT(std::abs(r->end_dev_mid), tol + r->max_correction);
  }
  // Second order: halving dt divides the consistent error by ~4 (the kink of the force at
  // contact onset makes the constant phase dependent). The bound 2.5 lies between a first-order
  // error's ratio (2) and 4, so it tells the orders apart without asking for the exact 4.
  EXPECT_GT(a.dev_consistent / b.dev_consistent, 2.5) << a.dev_consistent << " " << b.dev_consistent;
  // (c) The slip the ledger books converges to the exact dissipation at first order: halving
  // dt halves their difference (measured 0.51 sticking, 0.50 sliding). The band 0.5 +- 0.1
  // excludes second order (0.25) and no convergence (1). (b) alone follows from (a) and could
  // not catch a ledger that booked too little or too much slip.
  ASSERT_GT(a.max_correction, 0.0);
  EXPECT_NEAR(b.max_correction / a.max_correction, 0.5, 0.1) << a.max_correction << " " << b.max_correction;
  // Recorded in the XML report (--gtest_output=xml) for inspection of the margins.
  char buf[160];
  std::snprintf(buf, sizeof buf, "dt: code %.3e consistent %.3e; dt/2: code %.3e consistent %.3e; E0 %.3e", a.dev_code,
                a.dev_consistent, b.dev_code, b.dev_consistent, e0);
  ::testing::Test::RecordProperty("energy_deviation", buf);
}

}  // namespace

TEST(Energy, ObliqueStickingCollision) {
  // mu = 10: the shear spring sticks except at the very end, when Fn -> 0 and the cap collapses.
  // omega dt = 1.38e4 * 8e-7 = 1.1e-2 -> tolerance (omega dt)^2 E0 = 1.6e-10 J (E0 = 1.3e-6 J).
  check_oblique(10.0, 8e-7);
}

TEST(Energy, ObliqueSlidingCollisionBooksSlip) {
  // mu = 0.1: the contact slides for most of the collision.
  check_oblique(0.1, 8e-7);
  const EnergyRun a = oblique(8e-7, 0.1);
  EXPECT_GT(a.slip, 0.01 * sphere_mass() * 0.05 * 0.05) << "test does not slide";
  // The booked slip is the exact dissipation within 1 % at this dt (measured 0.5 %: 4.6e-10
  // of 9.0e-8 J).
  EXPECT_LT(a.max_correction, 0.01 * a.slip) << a.max_correction << " " << a.slip;
}

namespace {

// Sphere dropped from 1 mm above the plane z = 0 (v(-dt/2) = 0) with horizontal velocity vx and
// spin wy, bouncing a few times.
EnergyRun bounce(double dt, double mu, double vx, double wy, double T) {
  World w;
  w.particles.add(Vec3(0, 0, kR + 1e-3), kR, kRho, 0, Vec3(vx, 0, 0), Vec3(0, wy, 0));
  w.walls.push_back(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  Stepper st(settings(mu, dt, Vec3(0, 0, -9.81)));
  return run_energy(w, st, static_cast<long>(T / dt));
}

}  // namespace

TEST(Energy, BouncingOnAPlaneUnderGravity) {
  // Sphere-wall Kn = 5e4 N/m, m = 5.236e-4 kg: omega = 9.77e3 1/s, contact 3.2e-4 s; flight
  // between bounces 2 sqrt(2 h / g) = 28.6 ms; 0.09 s = three bounces. Tolerance
  // (omega dt)^2 m g h: 2e-9 J at dt = 2e-6 (m g h = 5.1e-6 J).
  const double m = sphere_mass(), mgh = m * 9.81 * 1e-3, omega = std::sqrt(kK / 2 / m);
  for (double dt : {2e-6, 1e-6}) {
    const EnergyRun r = bounce(dt, 0.3, 0.0, 0.0, 0.09);
    const double tol = std::pow(omega * dt, 2) * mgh;
    EXPECT_LT(r.dev_code, tol) << "dt = " << dt;
    EXPECT_EQ(r.slip, 0.0);  // head-on: no tangential force
    // Stepper::energy() itself (mid-step kinetic energy) is off by up to dt/2 |F . v|, F the
    // contact force: F v <= Kn un_max v / 2 = Kn v^2 / (2 omega) (v = sqrt(2 g h) = 0.14 m/s), plus
    // m g v in flight. The bound is first order in dt; x 1.05 leaves room for the next order,
    // a relative omega dt = 0.01-0.02 here.
    const double v = std::sqrt(2 * 9.81 * 1e-3);
    EXPECT_LT(r.max_dev_mid, tol + dt / 2 * (kK / 2 * v * v / (2 * omega) + m * 9.81 * v) * 1.05) << "dt = " << dt;
  }
}

TEST(Energy, ObliqueBounceWithFrictionOnAPlane) {
  // Horizontal velocity 0.05 m/s and backspin 20 rad/s: the contact slides (mu = 0.1) and the
  // wall's shear spring is exercised; no wall work (wall at rest).
  const double m = sphere_mass(), mgh = m * 9.81 * 1e-3, omega = std::sqrt(kK / 2 / m);
  const double e_kin = 0.5 * m * 0.05 * 0.05 + 0.5 * 0.4 * m * kR * kR * 400.0;
  std::vector<double> correction;
  for (double dt : {2e-6, 1e-6}) {
    const EnergyRun r = bounce(dt, 0.1, 0.05, 20.0, 0.06);
    const double tol = std::pow(omega * dt, 2) * (mgh + e_kin);
    EXPECT_GT(r.slip, 0.0);
    EXPECT_LT(r.dev_consistent, tol) << "dt = " << dt;
    correction.push_back(r.max_correction);
  }
  // The booked slip converges to the exact dissipation at first order (see check_oblique;
  // measured 2.06e-9 and 1.02e-9 J of 1.83e-7 J slip).
  ASSERT_GT(correction[0], 0.0);
  EXPECT_NEAR(correction[1] / correction[0], 0.5, 0.1) << correction[0] << " " << correction[1];
}

TEST(Energy, DampingWorkIsBooked) {
  // The same drop with local damping 0.7 (PFC form): the sphere comes to rest on the plane and
  // the damping work in the ledger closes the balance. At rest the mid-step and on-step kinetic
  // energies agree, so Stepper::energy() + ledger is compared directly. Tolerance: each damped
  // step books -Fd . (v_old + v_new)/2 dt; where Fd jumps (sign changes of v) that is off by
  // O(|Fd| |a| dt^2); summed over the run we allow 1e-4 m g h (observed ~3e-5).
  const double dt = 2e-6;
  World w;
  w.particles.add(Vec3(0, 0, kR + 1e-3), kR, kRho);
  w.walls.push_back(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  Stepper st(settings(0.3, dt, Vec3(0, 0, -9.81), 0.7));
  st.prepare(w);
  const double e0 = st.energy(w).total_stored();  // at rest: 0 kinetic, m g z0
  st.run(w, static_cast<long>(0.1 / dt));
  const double mgh = sphere_mass() * 9.81 * 1e-3;
  // At rest: at 1e-3 m/s the kinetic energy, m v^2 / 2 = 2.6e-10 J, is half the tolerance
  // 1e-4 m g h = 5.1e-10 J. The drop's m g h then went into damping, less the elastic energy
  // at rest, (m g)^2 / (2 Kn) = 2.6e-10 J, and no slip (head-on): at least 0.9 m g h shows the
  // ledger's damping term, not another, carries the balance.
  EXPECT_LT(w.particles.velocity[0].norm(), 1e-3) << "not at rest";
  const double e1 = st.energy(w).total_stored() + ledger_total(st.ledger());
  EXPECT_GT(st.ledger().damping_dissipated, 0.9 * mgh);
  EXPECT_NEAR(e1, e0, 1e-4 * mgh);
}

TEST(Energy, ShearBondBreakReleasedEnergyIsBooked) {
  // Bonded oblique collision (install moment on_new_contacts, Cn large, Cs = 0.05 N, mu = 0.1):
  // the shear bond breaks during the collision and Fs drops from ~Cs to mu Fn in one step. The
  // shear spring's energy above the Coulomb limit, about (Cs - mu Fn)^2 / (2 Ks) ~ 2e-8 J
  // (1.5% of E0), leaves the contact in that step; the ledger must book it (slip or
  // bond_break_lost). Tolerance as in the other oblique tests.
  ContactModel model;
  model.bond = ContactBond{100.0, 0.05};
  model.bond_install = BondInstallMoment::kOnNewContacts;
  const double dt = 8e-7, e0 = sphere_mass() * 0.05 * 0.05;
  const EnergyRun r = oblique(dt, 0.1, model);
  ASSERT_EQ(r.broken_shear, 1u);
  const double tol = std::pow(omega_pair() * dt, 2) * e0;
  // The contact law itself is consistent (energy leaves through D only):
  EXPECT_LT(r.dev_consistent, tol);
  // The ledger: first-order slip term allowed, but not an O(1) unbooked release.
  const EnergyRun unbonded = oblique(dt, 0.1);
  const double allowed = tol + 2 * unbonded.max_correction;
  EXPECT_LT(r.dev_code, allowed) << "ledger total off by " << r.dev_code / e0 * 100 << "% of E0";
}

namespace {

// A fixed sphere (moved at a prescribed 0.1 m/s; no friction, so the contact forces do no
// work on it) pressed 0.1 mm into `walls` for 40 ms; the energy balance from the first force
// pass on, and what the ledger booked.
struct CarriedSphere {
  double spring = 0.0;  // J, Kn un^2 / 2 after the first force pass
  double drift = 0.0;   // J, |(stored + ledger) at the end - at the start|
  double booked = 0.0;  // J, bond_break_lost
  std::size_t touching_at_end = 0;
};

CarriedSphere carry(const Vec3& start, const Vec3& velocity, std::vector<Wall> walls) {
  World w;
  w.particles.add(start, kR, kRho, 0, velocity);
  w.particles.fixed[0] = 1;
  w.walls = std::move(walls);
  Stepper st(settings(0.0, 1e-6, Vec3::Zero()));
  st.prepare(w);
  st.step(w);  // the first force pass loads the spring
  CarriedSphere r;
  r.spring = st.energy(w).elastic_normal;
  const double e0 = st.energy(w).total_stored() + ledger_total(st.ledger());
  st.run(w, 40000);
  r.drift = std::abs(st.energy(w).total_stored() + ledger_total(st.ledger()) - e0);
  r.booked = st.ledger().bond_break_lost;
  r.touching_at_end = w.contacts.touching_wall_contacts();
  return r;
}

}  // namespace

TEST(Energy, AContactLeavingAWallsRangeBooksWhatVanishes) {
  // Kn = 5e4 N/m (series of two 1e5), un = 0.1 mm: Kn un^2 / 2 = 2.5e-4 J.
  const double un = 1e-4, spring = 0.5 * (kK / 2) * un * un;
  // Past a cylinder's end (z = 0; the centre crosses it at 20 ms) the contact vanishes with
  // its normal spring loaded: that energy goes to bond_break_lost and the balance holds.
  // Before it was booked, the balance was short by it.
  const double rc = 0.05;
  const CarriedSphere cylinder =
      carry(Vec3(rc - kR + un, 0.0, -2e-3), Vec3(0.0, 0.0, 0.1),
            {Wall::cylinder("sleeve", Vec3::Zero(), Vec3::UnitZ(), rc, -0.05, 0.0)});
  EXPECT_NEAR(cylinder.spring, spring, 1e-9 * spring);
  EXPECT_EQ(cylinder.touching_at_end, 0u);
  EXPECT_NEAR(cylinder.booked, spring, 1e-9 * spring);
  EXPECT_LT(cylinder.drift, 1e-9 * spring);
  // Over a seam of two coplanar plates (x = 0; each gives no contact beyond it): the second
  // plate takes the sphere at the same overlap, so the normal spring's energy carries on and
  // nothing is booked (frictionless: no shear spring to lose).
  Wall left = Wall::rectangle("left", Vec3(-0.05, 0.0, 0.0), Vec3::UnitZ(), Vec3::UnitX(), 0.05, 0.05);
  Wall right = Wall::rectangle("right", Vec3(0.05, 0.0, 0.0), Vec3::UnitZ(), Vec3::UnitX(), 0.05, 0.05);
  set_edge_contact(left, Vec3(0.0, 0.0, 0.0), EdgeContact::kNone);
  set_edge_contact(right, Vec3(0.0, 0.0, 0.0), EdgeContact::kNone);
  const CarriedSphere seam = carry(Vec3(-2e-3, 0.0, kR - un), Vec3(0.1, 0.0, 0.0), {left, right});
  EXPECT_NEAR(seam.spring, spring, 1e-9 * spring);
  EXPECT_EQ(seam.touching_at_end, 1u);
  EXPECT_EQ(seam.booked, 0.0);
  EXPECT_LT(seam.drift, 1e-9 * spring);
}
