// Closed forms for the contact mechanisms beyond the baseline (physics.md section 7), run
// through the Stepper's generic tier: Hertz contact time and restitution, viscous
// restitution, the elasto-plastic law's restitution and plastic overlap, the rolling spring's
// oscillation and the rolling stop, load-induced cohesion's onset and strength, the slots'
// state across a swap of bodies, and the energy balance of every combination.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "contact/generic_law.hpp"
#include "contact/slot_registry.hpp"
#include "contact/slot_state.hpp"
#include "engine/stepper.hpp"

using namespace colza;

namespace {


constexpr double kRadius = 3e-3;   // m, the paper's seeds
constexpr double kDensity = 1250.0;  // kg/m^3
constexpr double kYoung = 5e7;     // Pa
constexpr double kPoisson = 0.3;   // -

PhysicsSettings settings(const ContactModel& model, double dt, double friction = 0.5) {
  PhysicsSettings s;
  s.particle_materials = {{"seed", kDensity, 437e3, 100e3, friction, kYoung, kPoisson}};
  s.wall_materials = {{"wall", 4000e3, 1000e3, friction, kYoung, kPoisson}};
  s.stiffness_rule = StiffnessRule::kSeries;
  s.model = model;
  s.integrator.damping = 0.0;
  s.integrator.gravity = Vec3::Zero();
  s.time_step.automatic = false;
  s.time_step.fixed_dt = dt;
  s.skin = 1e-4;
  return s;
}

struct Collision {
  double contact_time = 0.0;  // s
  double max_overlap = 0.0;   // m
  double restitution = 0.0;   // exit over entry closing speed
  double plastic_overlap = 0.0;  // Walton-Braun's d0 at the end of contact (m)
  EnergyLedger ledger;
  double kinetic_in = 0.0, kinetic_out = 0.0;
};

// Two equal spheres approaching head-on along x at closing speed v (m/s), run until apart.
Collision head_on(const ContactModel& model, double v, double dt) {
  Stepper st(settings(model, dt));
  World w;
  w.particles.add(Vec3(-kRadius - 1e-5, 0, 0), kRadius, kDensity, 0, Vec3(0.5 * v, 0, 0));
  w.particles.add(Vec3(kRadius + 1e-5, 0, 0), kRadius, kDensity, 0, Vec3(-0.5 * v, 0, 0));
  st.prepare(w);
  Collision r;
  r.kinetic_in = st.energy(w).kinetic;
  long touching_steps = 0, after = 0;
  bool seen = false;
  for (long n = 0; n < 10000000 && after < 50; ++n) {
    st.step(w, [&](const World& s) {
      const auto& pp = s.contacts.particle_pairs;
      const bool touching = pp.size() > 0 && pp.history[0].touching;
      if (touching) {
        ++touching_steps;
        seen = true;
        const double overlap = 2 * kRadius - (s.particles.position[1] - s.particles.position[0]).norm();
        r.max_overlap = std::max(r.max_overlap, overlap);
        if (pp.slot_state.size() >= 1 && std::holds_alternative<WaltonBraunNormal>(model.normal))
          r.plastic_overlap = (1.0 - 1.0 / std::get<WaltonBraunNormal>(model.normal).unloading_stiffness_ratio) *
                              pp.slot_state[0];
      } else if (seen) {
        ++after;
      }
    });
  }
  r.contact_time = touching_steps * dt;
  r.restitution = (w.particles.velocity[1].x() - w.particles.velocity[0].x()) / v;
  r.kinetic_out = st.energy(w).kinetic;
  r.ledger = st.ledger();
  return r;
}

double sphere_mass() { return kDensity * 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius; }

ContactModel model_with(NormalSlot normal, TangentialSlot tangential = CoulombTangential{},
                        DampingSlot damping = NoDamping{}, RollingSlot rolling = NoRolling{},
                        BondSlot bond = NoBond{}) {
  ContactModel m;
  m.normal = normal;
  m.tangential = tangential;
  m.damping = damping;
  m.rolling = rolling;
  m.bond = bond;
  return m;
}

// Restitution of a linear spring-dashpot whose force is clamped at zero (never attractive):
// with x(t) = (v/wd) e^(-g t) sin(wd t), g = zeta w0, wd = w0 sqrt(1 - zeta^2), the force
// w0^2 x + 2 g x' vanishes at tan(wd t*) = -2 g wd / (w0^2 - 2 g^2), t* in (pi/2, pi) / wd for
// zeta < 1/sqrt(2); the spheres leave with the speed x'(t*), and e = -x'(t*) / v (Schwager &
// Poeschel 2007, Granular Matter 9:465). The unclamped oscillator's exp(-pi zeta / sqrt(1 -
// zeta^2)) is lower: its attractive tail brakes the separation.
double clamped_restitution(double zeta) {
  const double w0 = 1.0, g = zeta * w0, wd = w0 * std::sqrt(1.0 - zeta * zeta);
  const double t = (std::numbers::pi + std::atan(-2.0 * g * wd / (w0 * w0 - 2.0 * g * g))) / wd;
  const double speed = std::exp(-g * t) * (std::cos(wd * t) - g / wd * std::sin(wd * t));
  return -speed;
}

}  // namespace

// Hertz head-on (physics.md 7.2): t_c = 2.8683 (m*^2 / (R* E*^2 v))^(1/5) (Johnson 1985,
// section 11.4; the constant 2 I (15/16)^(2/5) with I = int_0^1 dx / sqrt(1 - x^(5/2)), printed
// by tests/unit/hertz_contact_time_reference.py) and un_max = (15 m* v^2 / (16 E*
// sqrt(R*)))^(2/5); restitution 1 without damping. dt = 1e-8 s is about t_c / 2000, so the
// step count is within 1 step (0.05 %) and leapfrog's error O((w dt)^2) ~ 1e-6.
TEST(Mechanisms, HertzCollisionTimeOverlapAndRestitution) {
  const double v = 0.5;
  const Collision r = head_on(model_with(HertzNormal{}, MindlinTangential{}), v, 1e-8);
  const double m_eff = 0.5 * sphere_mass(), r_eff = 0.5 * kRadius;
  const double e_eff = 1.0 / (2.0 * (1.0 - kPoisson * kPoisson) / kYoung);
  const double t_c = 2.8683 * std::pow(m_eff * m_eff / (r_eff * e_eff * e_eff * v), 0.2);
  const double max_overlap = std::pow(15.0 * m_eff * v * v / (16.0 * e_eff * std::sqrt(r_eff)), 0.4);
  EXPECT_NEAR(r.contact_time, t_c, 1e-3 * t_c);
  EXPECT_NEAR(r.max_overlap, max_overlap, 1e-4 * max_overlap);
  EXPECT_NEAR(r.restitution, 1.0, 1e-5);
}

// Viscous damping, linear law: the clamped spring-dashpot's restitution (above) at zeta 0.1,
// 0.3, 0.5. dt = 5e-8 s is w0 dt = 2.8e-3: the dashpot acts on mid-step velocities, a
// first-order error of about zeta w0 dt / 2 < 1e-3 in e. The energy the dashpot booked,
// -(Fd . vn) dt with mid-step velocities, meets the kinetic energy lost to first order in
// dt: its error halves with dt (measured 1.3e-3 of the entry energy at zeta 0.5 and 5e-8 s).
TEST(Mechanisms, ViscousLinearRestitutionMatchesTheClampedOscillator) {
  for (const double zeta : {0.1, 0.3, 0.5}) {
    const ContactModel model = model_with(LinearNormal{}, CoulombTangential{}, ViscousDamping{zeta, 0.0});
    const Collision r = head_on(model, 0.5, 5e-8);
    const Collision fine = head_on(model, 0.5, 2.5e-8);
    EXPECT_NEAR(r.restitution, clamped_restitution(zeta), 1e-3) << "zeta " << zeta;
    const double error = std::abs(r.ledger.viscous_dissipated - (r.kinetic_in - r.kinetic_out)) / r.kinetic_in;
    const double fine_error =
        std::abs(fine.ledger.viscous_dissipated - (fine.kinetic_in - fine.kinetic_out)) / fine.kinetic_in;
    EXPECT_LT(error, 3e-3) << "zeta " << zeta;
    EXPECT_LT(fine_error, 0.6 * error) << "zeta " << zeta;
  }
}

// Viscous damping with Hertz: the restitution falls with zeta and stays below 1.
TEST(Mechanisms, ViscousHertzRestitutionDecreasesWithTheDampingRatio) {
  double previous = 1.0 + 1e-9;
  for (const double zeta : {0.0, 0.1, 0.3, 0.5}) {
    const Collision r = head_on(model_with(HertzNormal{}, MindlinTangential{}, ViscousDamping{zeta, 0.0}), 0.5, 1e-8);
    EXPECT_LT(r.restitution, previous) << "zeta " << zeta;
    previous = r.restitution;
  }
  EXPECT_LT(previous, 0.8);
}

// Walton-Braun (physics.md 7.4): restitution sqrt(k1/k2); the largest overlap v / w1 with
// w1 = sqrt(k1 / m*); the plastic overlap (1 - k1/k2) dmax; the kinetic energy lost is the
// plastic channel's. k1 = Kn = 218.5 kN/m (series rule), k2 = 4 k1: e = 0.5.
TEST(Mechanisms, WaltonBraunRestitutionAndPlasticOverlap) {
  const double v = 0.5, ratio = 4.0;
  const Collision r = head_on(model_with(WaltonBraunNormal{ratio}), v, 1e-7);
  const double k1 = 437e3 / 2.0, m_eff = 0.5 * sphere_mass();
  const double dmax = v / std::sqrt(k1 / m_eff);
  EXPECT_NEAR(r.restitution, std::sqrt(1.0 / ratio), 1e-3);
  EXPECT_NEAR(r.max_overlap, dmax, 1e-3 * dmax);
  EXPECT_NEAR(r.plastic_overlap, (1.0 - 1.0 / ratio) * dmax, 1e-3 * dmax);
  EXPECT_NEAR(r.ledger.plastic_dissipated, r.kinetic_in - r.kinetic_out, 1e-3 * r.kinetic_in);
}

namespace {

// A sphere resting on a plane wall (z = 0) under gravity at its equilibrium overlap m g / Kn,
// with rolling resistance at walls.
struct OnPlane {
  World world;
  Stepper stepper;
};
OnPlane sphere_on_plane(const ContactModel& model, double dt, double friction, const Vec3& v, const Vec3& w) {
  PhysicsSettings s = settings(model, dt, friction);
  s.integrator.gravity = Vec3(0, 0, -9.81);
  OnPlane o{World{}, Stepper(s)};
  const double kn = 437e3 * 4000e3 / (437e3 + 4000e3);
  const double sink = sphere_mass() * 9.81 / kn;
  o.world.walls.push_back(Wall::plane("floor", Vec3::Zero(), Vec3::UnitZ()));
  o.world.particles.add(Vec3(0, 0, kRadius - sink), kRadius, kDensity, 0, v, w);
  o.stepper.prepare(o.world);
  return o;
}

}  // namespace

// A small rolling oscillation: with no friction (mu = 0, no tangential force) a sphere spun
// about a horizontal axis rocks in place on its rolling spring, I theta'' = -kr theta, period
// 2 pi sqrt(I / kr), kr = beta Ks R^2 at a wall (Ks = 90.9 kN/m, the series rule of the
// particle's 100 and the wall's 1000 kN/m). dt = 1e-7 s puts ~2200 steps in a period, so each
// zero crossing is found within 0.05 % of it. The spin's amplitude keeps the moment below
// the cap (mu_r R m g).
TEST(Mechanisms, RollingSpringOscillatesWithThePeriodOfKrAndTheInertia) {
  const double beta = 0.5, omega0 = 0.02;  // rad/s
  const ContactModel model =
      model_with(LinearNormal{}, CoulombTangential{}, NoDamping{}, ElasticPlasticRolling{beta, 1.0, RollingForm::kYade, true});
  OnPlane o = sphere_on_plane(model, 1e-7, 0.0, Vec3::Zero(), Vec3(omega0, 0, 0));
  const double ks = 100e3 * 1000e3 / (100e3 + 1000e3);
  const double kr = beta * ks * kRadius * kRadius;
  const double inertia = 0.4 * sphere_mass() * kRadius * kRadius;
  const double period = 2.0 * std::numbers::pi * std::sqrt(inertia / kr);
  // Zero crossings of the spin from + to -, then back: one period.
  double previous = omega0, first_down = -1.0, second_down = -1.0;
  for (long n = 0; n < 2000000 && second_down < 0.0; ++n) {
    o.stepper.step(o.world);
    const double wx = o.world.particles.angular_velocity[0].x();
    if (previous > 0.0 && wx <= 0.0) (first_down < 0.0 ? first_down : second_down) = o.world.time;
    previous = wx;
  }
  ASSERT_GT(second_down, 0.0);
  EXPECT_NEAR(second_down - first_down, period, 2e-3 * period);
  EXPECT_LT(kr * omega0 / std::sqrt(kr / inertia), 1.0 * kRadius * sphere_mass() * 9.81);  // below the cap
}

// The rolling dashpot (Ai et al. 2011's type C): the same rocking as above, damped. Its
// coefficient Cr = 2 eta_r sqrt(I_r kr) takes the inertia about the contact, I_r = I + m R^2 =
// 7/2 I at a wall, while the sphere rocks about its centre with inertia I: the rocking's
// damping ratio is zeta = Cr / (2 sqrt(I kr)) = eta_r sqrt(7/2). A damped oscillator's spin
// peaks one period T_d = 2 pi / (w0 sqrt(1 - zeta^2)) apart fall by exp(-zeta w0 T_d). At a
// peak the spin's acceleration is zero, so the spring holds the dashpot's moment, kr theta =
// -Cr w: the energy there is 1/2 I w^2 + (Cr w)^2 / (2 kr) = 1/2 I w^2 (1 + 4 zeta^2), and the
// dashpot dissipates its drop between two peaks. Explicit time stepping shifts each by
// O(zeta w0 dt) ~ 3e-4.
TEST(Mechanisms, RollingDashpotDampsTheRockingByItsRatio) {
  const double beta = 0.5, eta = 0.1, omega0 = 0.02;  // -, -, rad/s
  const ContactModel model = model_with(LinearNormal{}, CoulombTangential{}, NoDamping{},
                                        ElasticPlasticRolling{beta, 1.0, RollingForm::kYade, true, eta});
  OnPlane o = sphere_on_plane(model, 1e-7, 0.0, Vec3::Zero(), Vec3(omega0, 0, 0));
  const double ks = 100e3 * 1000e3 / (100e3 + 1000e3);
  const double kr = beta * ks * kRadius * kRadius;
  const double inertia = 0.4 * sphere_mass() * kRadius * kRadius;
  const double w0 = std::sqrt(kr / inertia), zeta = eta * std::sqrt(3.5);
  const double damped_period = 2.0 * std::numbers::pi / (w0 * std::sqrt(1.0 - zeta * zeta));
  // The spin's peaks (wx at a local maximum) and their times.
  std::vector<double> peaks, times, dissipated;
  double before = omega0, now = omega0;
  for (long n = 0; n < 4000000 && peaks.size() < 3; ++n) {
    const double dissipated_now = o.stepper.ledger().rolling_dissipated;
    o.stepper.step(o.world);
    const double next = o.world.particles.angular_velocity[0].x();
    if (n > 1 && now > before && now >= next && now > 0.0) {
      peaks.push_back(now);
      times.push_back(o.world.time);
      dissipated.push_back(dissipated_now);  // the ledger when the spin was `now`
    }
    before = now;
    now = next;
  }
  ASSERT_EQ(peaks.size(), 3u);
  EXPECT_NEAR(times[2] - times[1], damped_period, 2e-3 * damped_period);
  EXPECT_NEAR(peaks[2] / peaks[1], std::exp(-zeta * w0 * damped_period), 2e-3);
  const double lost = 0.5 * inertia * (1.0 + 4.0 * zeta * zeta) * (peaks[1] * peaks[1] - peaks[2] * peaks[2]);
  EXPECT_NEAR(dissipated[2] - dissipated[1], lost, 1e-2 * lost);
  EXPECT_LT(kr * omega0 / w0, 1.0 * kRadius * sphere_mass() * 9.81);  // below the cap: the dashpot acts throughout
}

// Rolling stop: a sphere rolling without slip at v0 on a plane with the moment at its cap
// M = mu_r R m g (YADE form at a wall: min(R, R) = R) loses its kinetic energy 7/10 m v0^2 to
// M ds / R: it stops after s = 7 v0^2 / (10 mu_r g), in t = 7 v0 / (5 mu_r g). The rolling
// spring's elastic start (M reaches the cap within ~mu_r R m g / (kr w0) s) and the shear
// spring's compliance shift both by well under 1 %.
TEST(Mechanisms, RollingResistanceStopsASphereAfterTheDistanceTheCapGives) {
  const double v0 = 0.05, mu_r = 0.05, g = 9.81;
  const ContactModel model =
      model_with(LinearNormal{}, CoulombTangential{}, NoDamping{}, ElasticPlasticRolling{1.0, mu_r, RollingForm::kYade, true});
  OnPlane o = sphere_on_plane(model, 1e-6, 0.8, Vec3(v0, 0, 0), Vec3(0, v0 / kRadius, 0));
  const double x0 = o.world.particles.position[0].x();
  double stop_time = -1.0;
  for (long n = 0; n < 2000000 && stop_time < 0.0; ++n) {
    o.stepper.step(o.world);
    if (o.world.particles.velocity[0].x() <= 0.0) stop_time = o.world.time;
  }
  ASSERT_GT(stop_time, 0.0);
  const double distance = o.world.particles.position[0].x() - x0;
  EXPECT_NEAR(distance, 7.0 * v0 * v0 / (10.0 * mu_r * g), 1e-2 * 7.0 * v0 * v0 / (10.0 * mu_r * g));
  EXPECT_NEAR(stop_time, 7.0 * v0 / (5.0 * mu_r * g), 1e-2 * 7.0 * v0 / (5.0 * mu_r * g));
  EXPECT_GT(o.stepper.ledger().rolling_dissipated, 0.0);
}

// Load-induced cohesion (physics.md 7.5) through the generic law alone: a contact pressed
// in steps of overlap is bonded the step its normal force first exceeds F_on, its strengths
// follow the largest force carried, and pulled apart it holds tension up to a_n Fmax.
TEST(Mechanisms, LoadInducedBondFormsAtTheOnsetForceAndBreaksAtItsGrownStrength) {
  const LoadInducedBond bond{2.0, 0.1, 0.2};  // F_on 2 N, a_n 0.1, a_s 0.2
  const ContactModel m = model_with(LinearNormal{}, CoulombTangential{}, NoDamping{}, NoRolling{}, bond);
  const SlotStateLayout layout = slot_state_layout(m);
  ASSERT_EQ(layout.stride, 2u);
  const PairParameters q{1000.0, 500.0, 0.3};
  const PairContext c{q, kRadius, kRadius, 0.5 * kRadius, 1e-4, 1e-6, false};
  ContactHistory h;
  std::vector<double> state(layout.stride, 0.0);
  const auto at = [&](double overlap) {
    ContactKinematics k{Vec3::UnitX(), overlap, Vec3::Zero(), 0.0};
    return evaluate_contact_generic(m, layout, c, k, h, state.data(), false);
  };
  at(1e-3);  // Fn = 1 N
  EXPECT_FALSE(h.bonded);
  at(2e-3);  // 2 N: not above F_on
  EXPECT_FALSE(h.bonded);
  at(2.5e-3);  // 2.5 N
  EXPECT_TRUE(h.bonded);
  at(10e-3);  // 10 N: strengths 1 N and 2 N
  EXPECT_DOUBLE_EQ(state[0], 10.0);
  EXPECT_TRUE(at(-0.9e-3).carries_force);  // -0.9 N of tension: held
  EXPECT_TRUE(h.bonded);
  const ContactOutcome broken = at(-1.1e-3);  // -1.1 N: past a_n Fmax = 1 N
  EXPECT_EQ(broken.event, ContactEvent::kBondBrokeTension);
  EXPECT_FALSE(h.bonded);
  at(20e-3);  // a new contact: a bond forms again only once per contact; this one is new
  EXPECT_TRUE(h.bonded);
}

// The slots' state flips as each slot declares when a pair's bodies swap (a renumbering that
// reverses their order): the rolling moment on body 2 changes sign, the largest overlap and
// the load-induced bond's Fmax do not.
TEST(Mechanisms, SlotStateFollowsASwapOfBodiesAsEachSlotDeclares) {
  const ContactModel m = model_with(WaltonBraunNormal{2.0}, CoulombTangential{}, NoDamping{},
                                    ElasticPlasticRolling{1.0, 0.1, RollingForm::kYade, false},
                                    LoadInducedBond{1.0, 0.1, 0.1});
  const SlotStateLayout layout = slot_state_layout(m);
  ASSERT_EQ(layout.stride, 6u);
  ContactStore store;
  store.set_slot_state_layout(layout);
  store.adopt_particle_pairs({0}, {1});
  const std::vector<double> row = {1e-4, 0.1, -0.2, 0.3, 5.0, 1.0};  // dmax | Mr | Fmax, formed
  store.particle_pairs.slot_state = row;
  store.particle_pairs.history[0].touching = 1;
  store.renumber_particles({1, 0});  // particle 0 becomes 1 and 1 becomes 0
  const std::vector<double> expected = {1e-4, -0.1, 0.2, -0.3, 5.0, 1.0};
  EXPECT_EQ(store.particle_pairs.slot_state, expected);
  // A rebuild that keeps the pair keeps its row; a new pair starts at zero.
  store.adopt_particle_pairs({0, 0}, {1, 2});
  ASSERT_EQ(store.particle_pairs.slot_state.size(), 12u);
  EXPECT_EQ(std::vector<double>(store.particle_pairs.slot_state.begin(), store.particle_pairs.slot_state.begin() + 6),
            expected);
  EXPECT_EQ(std::vector<double>(store.particle_pairs.slot_state.begin() + 6, store.particle_pairs.slot_state.end()),
            std::vector<double>(6, 0.0));
}

namespace {

// Five spheres dropped in a box of planes (local damping off), colliding with each other and
// the walls for 0.04 s: the change of stored energy plus every ledger channel, over the
// initial gravitational and kinetic energy (J / J).
double balance_drift(const ContactModel& model, double dt) {
  PhysicsSettings s = settings(model, dt, 0.4);
  s.integrator.gravity = Vec3(0, 0, -9.81);
  Stepper st(s);
  World w;
  const double box = 0.02;  // m
  for (int a = 0; a < 3; ++a) {
    Vec3 n = Vec3::Zero();
    n[a] = 1.0;
    w.walls.push_back(Wall::plane("low", Vec3::Zero(), n));
    if (a < 2) w.walls.push_back(Wall::plane("high", box * n, -n));
  }
  const Vec3 spots[] = {{0.005, 0.005, 0.004}, {0.013, 0.006, 0.005}, {0.006, 0.014, 0.006},
                        {0.014, 0.014, 0.007}, {0.010, 0.010, 0.013}};  // >= 8 mm apart
  for (int k = 0; k < 5; ++k)
    w.particles.add(spots[k], kRadius, kDensity, 0, Vec3(0.1 * (k % 2) - 0.05, 0.03 * k, 0.0),
                    Vec3(0.0, 20.0 * (k % 3), 10.0 * k));
  st.prepare(w);
  const double start = energy_balance(st.energy(w), st.ledger());
  const double scale = st.energy(w).gravitational + st.energy(w).kinetic;  // J, above the floor
  const long steps = std::lround(0.04 / dt);
  for (long n = 0; n < steps; ++n) st.step(w);
  return (energy_balance(st.energy(w), st.ledger()) - start) / scale;
}

}  // namespace

namespace {

// One instance of every implementation of every slot, with parameters that make it act
// (the energy test runs every combination of them). SlotListsCoverTheRegistry checks that
// every name registered in contact/slot_registry.cpp has an entry, so a new row cannot be
// left out of the generic tests.
const std::vector<NormalSlot> kNormals = {LinearNormal{}, HertzNormal{}, WaltonBraunNormal{2.0}};
const std::vector<TangentialSlot> kTangentials = {CoulombTangential{}, MindlinTangential{}};
const std::vector<DampingSlot> kDampings = {NoDamping{}, ViscousDamping{0.2, 0.2}};
const std::vector<RollingSlot> kRollings = {NoRolling{}, ElasticPlasticRolling{0.5, 0.1, RollingForm::kYade, true},
                                            ElasticPlasticRolling{0.5, 0.1, RollingForm::kPfc, false, 0.3}};
const std::vector<BondSlot> kBonds = {NoBond{}, ContactBond{0.5, 0.5}, LoadInducedBond{0.05, 0.5, 0.5}};

template <class Slot>
std::set<std::string> names_in(const std::vector<Slot>& list) {
  std::set<std::string> names;
  for (const Slot& s : list) std::visit([&](const auto& impl) { names.insert(impl.kName); }, s);
  return names;
}
std::set<std::string> as_set(const std::vector<std::string>& v) { return {v.begin(), v.end()}; }

}  // namespace

TEST(Mechanisms, SlotListsCoverTheRegistry) {
  EXPECT_EQ(names_in(kNormals), as_set(normal_slot_names()));
  EXPECT_EQ(names_in(kTangentials), as_set(tangential_slot_names()));
  EXPECT_EQ(names_in(kDampings), as_set(damping_slot_names()));
  EXPECT_EQ(names_in(kRollings), as_set(rolling_slot_names()));
  EXPECT_EQ(names_in(kBonds), as_set(bond_slot_names()));
}

// Every combination of the slots' lists: each double of the layout gets the sign its slot
// declares (the rolling moment -1, all others +1), and the stride is the sum of the slots'.
TEST(Mechanisms, EveryCombinationsLayoutHasItsSlotsDoublesAndSigns) {
  for (const auto& normal : kNormals)
    for (const auto& tangential : kTangentials)
      for (const auto& rolling : kRollings)
        for (const auto& bond : kBonds) {
          const ContactModel m = model_with(normal, tangential, NoDamping{}, rolling, bond);
          const SlotStateLayout l = slot_state_layout(m);
          const auto doubles = [](const auto& slot) {
            return std::visit([](const auto& impl) { return static_cast<std::size_t>(impl.kStateDoubles); }, slot);
          };
          ASSERT_EQ(l.stride, doubles(normal) + doubles(tangential) + doubles(rolling) + doubles(bond));
          for (std::size_t d = 0; d < l.stride; ++d)
            EXPECT_EQ(l.swap_sign[d], d >= l.rolling && d < l.bond ? -1.0 : 1.0) << describe(m) << ", double " << d;
        }
}

// Energy balance with local damping off, for every combination of the slots (108): stored
// energy (the slots' own springs) plus every ledger channel is constant to first order in dt.
// Each channel's booking is first-order accurate under leapfrog (the slip and cap formulas,
// the plastic work booked on the loading branch, the dashpots on mid-step velocities, the
// Mindlin spring's stiffness change), so the drift at dt/2 must be at most 0.75 of the drift
// at dt (first order halves it; the five spheres' paths differ between the two steps, which
// measured ratios up to 0.72), above a floor of 2e-4 of the energy for combinations already
// that close, and below 5 % at dt = 4e-7 s (w dt ~ 0.02 for the stiffest wall contact).
// Measured at 2e-7 s: the paper's law 4.5e-4, Hertz-Mindlin 1e-4, Walton-Braun with bonds
// 1e-3, a linear normal law with Mindlin's shear spring 2.2e-2 (its kt ~ 100 N/m at the
// linear law's small overlaps makes the slip booking's first-order term large); in a single
// oblique collision that last one halves exactly with dt (1.3e-2, 5.4e-3, 2.5e-3 at 1e-7,
// 5e-8, 2.5e-8 s).
TEST(Mechanisms, EnergyBalancesForEveryCombinationOfSlots) {
  const auto& normals = kNormals;
  const auto& tangentials = kTangentials;
  const auto& dampings = kDampings;
  const auto& rollings = kRollings;
  const auto& bonds = kBonds;
  int combinations = 0;
  for (const auto& normal : normals)
    for (const auto& tangential : tangentials)
      for (const auto& damping : dampings)
        for (const auto& rolling : rollings)
          for (const auto& bond : bonds) {
            ContactModel model = model_with(normal, tangential, damping, rolling, bond);
            if (std::holds_alternative<ContactBond>(bond)) model.bond_install = BondInstallMoment::kOnNewContacts;
            const double coarse = balance_drift(model, 4e-7), fine = balance_drift(model, 2e-7);
            EXPECT_LT(std::abs(coarse), 5e-2) << describe(model);
            EXPECT_LE(std::abs(fine), 0.75 * std::abs(coarse) + 2e-4) << describe(model) << ": " << coarse << " at 4e-7 s";
            if (std::getenv("COLZA_PRINT_DRIFT")) std::printf("%.3e %.3e %s\n", coarse, fine, describe(model).c_str());
            ++combinations;
          }
  EXPECT_EQ(combinations, 108);
}

// Every normal law's force is the derivative of its stored energy: F = dE/dun by central
// differences, for each alternative of the normal slot (on the unloading branch for
// Walton-Braun, where its energy is the recoverable part). Step h = 1e-4 un: the central
// difference's error is O(h^2 F'''), below 1e-6 of F here.
TEST(Mechanisms, EveryNormalLawsForceIsTheDerivativeOfItsEnergy) {
  const PairParameters q{2e5, 1e5, 0.3, 2.7e7, 1.1e7};
  const PairContext c{q, kRadius, 0.8 * kRadius, 0.8 * kRadius / 1.8, 1e-4, 1e-6, false};
  for (std::size_t alternative = 0; alternative < std::variant_size_v<NormalSlot>; ++alternative) {
    NormalSlot slot;
    if (alternative == 0) slot = LinearNormal{};
    if (alternative == 1) slot = HertzNormal{};
    if (alternative == 2) slot = WaltonBraunNormal{3.0};
    ASSERT_EQ(slot.index(), alternative);
    for (const double overlap : {2e-6, 2e-5, 1e-4}) {
      double state[1] = {2e-4};  // Walton-Braun: unloaded from dmax = 0.2 mm (d0 = 0.133 mm)
      const double un = std::holds_alternative<WaltonBraunNormal>(slot) ? 1.4e-4 + overlap * 0.1 : overlap;
      const double h = 1e-4 * un;
      const auto energy_at = [&](double x) {
        return std::visit([&](const auto& n) { return n.energy(c, n.force(c, x, state, false).force, state); }, slot);
      };
      const double force = std::visit([&](const auto& n) { return n.force(c, un, state, false).force; }, slot);
      const double derivative = (energy_at(un + h) - energy_at(un - h)) / (2.0 * h);
      EXPECT_NEAR(derivative, force, 1e-6 * force) << "alternative " << alternative << ", un " << un;
      // The overlap the law reads back from its force is the overlap.
      const double back = std::visit([&](const auto& n) { return n.overlap(c, force, state); }, slot);
      EXPECT_NEAR(back, un, 1e-9 * un) << "alternative " << alternative;
    }
  }
}
