// One step of the contact law on hand-made kinematics (contact/contact_law.hpp,
// physics.md section 2, steps 1-6). Numbers are powers of two where possible so that the
// expected forces are exact in floating point.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/contact_law.hpp"

using namespace colza;

namespace {

// Kn = 1024 N/m, Ks = 512 N/m, mu = 0.5; bond Cn = 1 N, Cs = 2 N.
const PairParameters kPair{1024.0, 512.0, 0.5};
const ContactBond kBond{1.0, 2.0};
const LinearNormal kNormal{};
const CoulombTangential kTangential{};

ContactKinematics kin(double overlap, const Vec3& dus = Vec3::Zero(), const Vec3& n = Vec3::UnitZ(),
                      double twist = 0.0) {
  return ContactKinematics{n, overlap, dus, twist};
}

ContactHistory existing(bool bonded, const Vec3& fs = Vec3::Zero(), const Vec3& n = Vec3::UnitZ()) {
  ContactHistory h;
  h.touching = 1;
  h.bonded = bonded ? 1 : 0;
  h.shear_force = fs;
  h.normal = n;
  return h;
}

template <class Bond>
ContactOutcome eval(const Bond& bond, const ContactKinematics& k, ContactHistory& h, bool bond_new = false) {
  return evaluate_contact(kNormal, kTangential, bond, kPair, k, h, bond_new);
}

}  // namespace

// ---- unbonded contacts --------------------------------------------------------------

TEST(ContactLaw, NewContactStartsWithZeroShear) {
  // Step 1: Fn = Kn un = 1024 * 2^-10 = 1 N; a new contact starts with Fs = 0, so
  // Fs = -Ks dus = -512 * 2^-12 ex = -0.125 ex (below mu Fn = 0.5).
  ContactHistory h;
  const ContactOutcome o = eval(NoBond{}, kin(1.0 / 1024, Vec3(1.0 / 4096, 0, 0)), h);
  EXPECT_EQ(o.event, ContactEvent::kCreated);
  EXPECT_TRUE(o.carries_force);
  EXPECT_EQ(o.force_on_2, Vec3(-0.125, 0, 1.0));
  EXPECT_EQ(h.touching, 1);
  EXPECT_EQ(h.bonded, 0);
  EXPECT_EQ(h.normal_force, 1.0);
  EXPECT_EQ(o.slip_dissipation, 0.0);
}

TEST(ContactLaw, NoContactWithoutOverlap) {
  ContactHistory h;
  const ContactOutcome o = eval(NoBond{}, kin(-1e-9), h);
  EXPECT_FALSE(o.carries_force);
  EXPECT_EQ(o.event, ContactEvent::kNone);
  EXPECT_EQ(h.touching, 0);
}

TEST(ContactLaw, UnbondedSeparationRemovesContact) {
  // Step 4: un < 0 -> no force, contact removed.
  ContactHistory h = existing(false, Vec3(0.25, 0, 0));
  const ContactOutcome o = eval(NoBond{}, kin(-1e-9), h);
  EXPECT_FALSE(o.carries_force);
  EXPECT_EQ(o.event, ContactEvent::kSeparated);
  EXPECT_EQ(h.touching, 0);
  EXPECT_EQ(h.shear_force, Vec3::Zero());
  // The same under a ContactBond slot for an unbonded contact.
  ContactHistory g = existing(false, Vec3(0.25, 0, 0));
  EXPECT_EQ(eval(kBond, kin(-1e-9), g).event, ContactEvent::kSeparated);
}

TEST(ContactLaw, CoulombCapAndSlipDissipation) {
  // Fn = 1024 * 2^-9 = 2 N, limit mu Fn = 1 N. Stored Fs = (0.75, 0, 0), dus = -(2^-9) ex:
  // trial Fs = 0.75 + 512 * 2^-9 = 1.75 N > 1 N -> scaled to 1 N along +x.
  // Dissipation (trial - capped) . capped / Ks = 0.75 * 1 / 512 J.
  ContactHistory h = existing(false, Vec3(0.75, 0, 0));
  const ContactOutcome o = eval(NoBond{}, kin(2.0 / 1024, Vec3(-1.0 / 512, 0, 0)), h);
  EXPECT_TRUE(o.carries_force);
  EXPECT_EQ(o.event, ContactEvent::kNone);
  EXPECT_EQ(o.force_on_2, Vec3(1.0, 0, 2.0));
  EXPECT_EQ(h.shear_force, Vec3(1.0, 0, 0));
  EXPECT_DOUBLE_EQ(o.slip_dissipation, 0.75 / 512);
  // Oblique trial (3, 4, 0)/4 = |1.25|: capped to length 1 along (0.6, 0.8).
  ContactHistory g = existing(false, Vec3(0.75, 1.0, 0));
  eval(NoBond{}, kin(2.0 / 1024), g);
  EXPECT_NEAR((g.shear_force - Vec3(0.6, 0.8, 0)).norm(), 0.0, 1e-15);
}

TEST(ContactLaw, BelowTheLimitTheShearSpringIsElastic) {
  // Trial |Fs| = 0.5 + 0.25 = 0.75 <= mu Fn = 1: kept as is, no dissipation.
  ContactHistory h = existing(false, Vec3(0.5, 0, 0));
  const ContactOutcome o = eval(NoBond{}, kin(2.0 / 1024, Vec3(-1.0 / 2048, 0, 0)), h);
  EXPECT_EQ(h.shear_force, Vec3(0.75, 0, 0));
  EXPECT_EQ(o.slip_dissipation, 0.0);
}

TEST(ContactLaw, ShearForceIsCarriedIntoTheNewTangentPlane) {
  // Step 2 with n_old = ez, n_new = (s, 0, c): n_old x n_new = s ey,
  // Fs = ex - ex x (s ey) = ex - s ez = (1, 0, -s); no twist, no increment.
  const double a = 1e-3, s = std::sin(a), c = std::cos(a);
  ContactHistory h = existing(false, Vec3(1.0, 0, 0));
  eval(NoBond{}, kin(4.0 / 1024, Vec3::Zero(), Vec3(s, 0, c)), h);
  EXPECT_NEAR((h.shear_force - Vec3(1.0, 0, -s)).norm(), 0.0, 1e-15);
  // Twist phi about n = ez: Fs = ex - ex x (phi ez) = ex + phi ey.
  const double phi = 2e-3;
  ContactHistory g = existing(false, Vec3(1.0, 0, 0));
  eval(NoBond{}, kin(4.0 / 1024, Vec3::Zero(), Vec3::UnitZ(), phi), g);
  EXPECT_NEAR((g.shear_force - Vec3(1.0, phi, 0)).norm(), 0.0, 1e-15);
}

// ---- contact bond -------------------------------------------------------------------

TEST(ContactLaw, BondAllowsTensionUpToCn) {
  // un = -2^-10 m -> Fn = -1 N = -Cn exactly: -Fn > Cn is false, the bond holds and pulls body 2
  // back towards body 1: force on 2 = Fn n = -ez.
  ContactHistory h = existing(true);
  const ContactOutcome o = eval(kBond, kin(-1.0 / 1024), h);
  EXPECT_TRUE(o.carries_force);
  EXPECT_EQ(o.event, ContactEvent::kNone);
  EXPECT_EQ(o.force_on_2, Vec3(0, 0, -1.0));
  EXPECT_EQ(h.bonded, 1);
  EXPECT_EQ(h.normal_force, -1.0);
}

TEST(ContactLaw, TensionBreakJustAboveCn) {
  // un = -2^-10 (1 + 2^-20): -Fn = 1 + 2^-20 > Cn = 1 -> bond and contact removed, no force.
  ContactHistory h = existing(true, Vec3(0.5, 0, 0));
  const ContactOutcome o = eval(kBond, kin(-(1.0 + std::ldexp(1.0, -20)) / 1024), h);
  EXPECT_FALSE(o.carries_force);
  EXPECT_EQ(o.event, ContactEvent::kBondBrokeTension);
  EXPECT_EQ(o.force_on_2, Vec3::Zero());
  EXPECT_EQ(h.touching, 0);
  EXPECT_EQ(h.bonded, 0);
}

TEST(ContactLaw, TensionIsCheckedBeforeShear) {
  // Both strengths exceeded: tension wins (contact removed, not continued frictional).
  ContactHistory h = existing(true, Vec3(1.9, 0, 0));
  const ContactOutcome o = eval(kBond, kin(-2.0 / 1024, Vec3(-1.0 / 512, 0, 0)), h);
  EXPECT_EQ(o.event, ContactEvent::kBondBrokeTension);
  EXPECT_FALSE(o.carries_force);
}

TEST(ContactLaw, WhileBondedNoFrictionCap) {
  // Fn = 2 N, mu Fn = 1 N, trial Fs = 1.5 N < Cs = 2 N: kept at 1.5 N (no Coulomb cap), no slip.
  ContactHistory h = existing(true, Vec3(1.0, 0, 0));
  const ContactOutcome o = eval(kBond, kin(2.0 / 1024, Vec3(-1.0 / 1024, 0, 0)), h);
  EXPECT_EQ(o.event, ContactEvent::kNone);
  EXPECT_EQ(h.shear_force, Vec3(1.5, 0, 0));
  EXPECT_EQ(o.force_on_2, Vec3(1.5, 0, 2.0));
  EXPECT_EQ(o.slip_dissipation, 0.0);
  EXPECT_EQ(h.bonded, 1);
  // Exactly at Cs (|Fs| = 2 = Cs, not > Cs): still bonded, still uncapped.
  ContactHistory g = existing(true, Vec3(1.5, 0, 0));
  eval(kBond, kin(2.0 / 1024, Vec3(-1.0 / 1024, 0, 0)), g);
  EXPECT_EQ(g.shear_force, Vec3(2.0, 0, 0));
  EXPECT_EQ(g.bonded, 1);
}

TEST(ContactLaw, ShearBreakJustAboveCsCapsToCoulombInTheSameStep) {
  // Fn = 2 N; stored Fs = 1.75 ex, dus = -(2^-9 + 2^-20) ex -> trial = 2.75 + 2^-11 > Cs = 2:
  // bond broken, Fs capped to mu max(Fn, 0) = 1 N along +x in the same step; the contact
  // continues (touching, unbonded) and carries Fn n + Fs.
  const double dus = -(1.0 / 512 + std::ldexp(1.0, -20));
  ContactHistory h = existing(true, Vec3(1.75, 0, 0));
  const ContactOutcome o = eval(kBond, kin(2.0 / 1024, Vec3(dus, 0, 0)), h);
  EXPECT_EQ(o.event, ContactEvent::kBondBrokeShear);
  EXPECT_TRUE(o.carries_force);
  EXPECT_EQ(h.bonded, 0);
  EXPECT_EQ(h.touching, 1);
  // (scaling 2.75... by 1/2.75... rounds: equal to 1 within an ulp or two)
  EXPECT_NEAR((h.shear_force - Vec3(1.0, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((o.force_on_2 - Vec3(1.0, 0, 2.0)).norm(), 0.0, 1e-15);
  // The capping step's energy drop is the bond break's, not slip:
  // (F_carried + F_capped) . (F_trial - F_capped) / (2 Ks) with carried 1.75, capped 1.
  const double trial = 1.75 - 512 * dus;
  EXPECT_EQ(o.slip_dissipation, 0.0);
  EXPECT_DOUBLE_EQ(o.bond_break_energy, (1.75 + 1.0) * (trial - 1.0) / (2 * 512));

  // Just above Cs: stored Fs = 2 - 2^-10 N plus an increment of 2^-10 + 2^-20 N gives the
  // trial 2 + 2^-20 N > Cs: breaks; capped to mu Fn = 1 N.
  ContactHistory g = existing(true, Vec3(2.0 - 1.0 / 1024, 0, 0));
  const double d2 = -(1.0 / 1024 + std::ldexp(1.0, -20)) / 512;
  EXPECT_EQ(eval(kBond, kin(2.0 / 1024, Vec3(d2, 0, 0)), g).event, ContactEvent::kBondBrokeShear);
  EXPECT_NEAR((g.shear_force - Vec3(1.0, 0, 0)).norm(), 0.0, 1e-15);

  // The next step is an ordinary frictional contact: capped at mu Fn, no bond event.
  const ContactOutcome next = eval(kBond, kin(2.0 / 1024, Vec3(-1.0 / 512, 0, 0)), g);
  EXPECT_EQ(next.event, ContactEvent::kNone);
  EXPECT_NEAR((g.shear_force - Vec3(1.0, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_EQ(g.bonded, 0);
}

TEST(ContactLaw, ShearBreakUnderTensionLeavesNoShearForce) {
  // Fn = -0.5 N (tension below Cn) and |Fs| trial = 2.5 > Cs: the cap is mu max(Fn, 0) = 0.
  ContactHistory h = existing(true, Vec3(2.25, 0, 0));
  const ContactOutcome o = eval(kBond, kin(-0.5 / 1024, Vec3(-1.0 / 2048, 0, 0)), h);
  EXPECT_EQ(o.event, ContactEvent::kBondBrokeShear);
  EXPECT_EQ(h.shear_force, Vec3::Zero());
  EXPECT_EQ(h.bonded, 0);
}

TEST(ContactLaw, BondOnNewContactsInstallMoment) {
  // bond_new_contacts: a contact created this step starts bonded (and can then take tension).
  ContactHistory h;
  const ContactOutcome o = eval(kBond, kin(1e-6), h, /*bond_new=*/true);
  EXPECT_EQ(o.event, ContactEvent::kCreated);
  EXPECT_EQ(h.bonded, 1);
  const ContactOutcome t = eval(kBond, kin(-0.5 / 1024), h, true);
  EXPECT_TRUE(t.carries_force);
  EXPECT_EQ(t.force_on_2, Vec3(0, 0, -0.5));
  // Without it the new contact is unbonded, and the NoBond slot never bonds.
  ContactHistory g;
  eval(kBond, kin(1e-6), g, false);
  EXPECT_EQ(g.bonded, 0);
  ContactHistory f;
  eval(NoBond{}, kin(1e-6), f, true);
  EXPECT_EQ(f.bonded, 0);
}
