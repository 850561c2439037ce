// Load-unload analysis of an oedometer curve (analysis/oedometer_cycles.hpp) on synthetic
// piecewise-linear curves whose moduli, permanent strains, loop areas and lateral pressure
// ratios are known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "analysis/oedometer_cycles.hpp"
#include "core/types.hpp"

using namespace colza;

namespace {

// Sample height H = 0.1 m in a cylinder of D = 0.1 m (A = pi D^2 / 4). The curve, in strain
// eps = s / H and piston stress sigma_v (Pa), rows every 1e-4 of strain:
//   1. virgin loading  sigma = M1 eps,                 M1 =  5 MPa, 0     -> 0.020 (100 kPa)
//   2. unloading       sigma = 100e3 - M2 (0.020-eps), M2 = 20 MPa, 0.020 -> 0.015 (0)
//   3. reloading       sigma = M3 (eps - 0.015),       M3 = 10 MPa, 0.015 -> 0.025 (100 kPa)
//   4. unloading       sigma = 100e3 - M2 (0.025-eps),              0.025 -> 0.020 (0)
// Lateral stress: sigma_h = 0.4 sigma_v on the loadings (K0 = 0.4); on the unloadings it falls
// ten times slower than sigma_v: sigma_h = 40e3 - 0.1 (100e3 - sigma_v), so K = 0.1 + 30e3 /
// sigma_v (0.7 at 50 kPa, 0.4 at the turn). The radial force is sigma_h pi D (H - s).
// Work per unit volume, integral sigma d eps (the segments are straight, so trapezoids over
// rows that include the turns are exact):
//   1: 100e3 x 0.020 / 2 = 1000 J/m^3;  2: -100e3 x 0.005 / 2 = -250;
//   3: 100e3 x 0.010 / 2 = 500;         4: -250.
// Loop areas: cycle 1 = 1000 - 250 = 750 J/m^3, cycle 2 = 500 - 250 = 250 J/m^3.
// Permanent strains: 0.015 and 0.020; rebound strains 0.005 and 0.005.
constexpr double kH = 0.1, kD = 0.1;
const double kArea = kPi * kD * kD / 4.0;

struct Curve {
  std::vector<double> travel, force, radial;
};

void add_row(Curve& c, double eps, double sigma_v, double sigma_h) {
  const double s = eps * kH;
  c.travel.push_back(s);
  c.force.push_back(sigma_v * kArea);
  c.radial.push_back(sigma_h * kPi * kD * (kH - s));
}

Curve two_cycles() {
  Curve c;
  const double e = 1e-4;
  for (int k = 0; k <= 200; ++k) add_row(c, k * e, 5e6 * k * e, 0.4 * 5e6 * k * e);
  for (int k = 199; k >= 150; --k) {
    const double sv = 100e3 - 20e6 * (200 - k) * e;
    add_row(c, k * e, sv, 40e3 - 0.1 * (100e3 - sv));
  }
  for (int k = 151; k <= 250; ++k) add_row(c, k * e, 10e6 * (k - 150) * e, 0.4 * 10e6 * (k - 150) * e);
  for (int k = 249; k >= 200; --k) {
    const double sv = 100e3 - 20e6 * (250 - k) * e;
    add_row(c, k * e, sv, 40e3 - 0.1 * (100e3 - sv));
  }
  return c;
}

CycleAnalysisSettings settings(std::vector<double> stresses) {
  CycleAnalysisSettings s;
  s.modulus_stresses = std::move(stresses);
  // Window half-width 10.3 %: its ends (44.85 and 55.15 kPa at 50 kPa) fall between rows, so
  // rounding cannot move a row in or out.
  s.modulus_window = 0.103;
  return s;
}

}  // namespace

TEST(OedometerCycles, SplitsAtTheTurnsAndSharesTheTurningRow) {
  const Curve c = two_cycles();
  const std::vector<RowRange> b = split_branches(c.travel, 1e-3);
  ASSERT_EQ(b.size(), 4u);
  // Rows: 201 loading (0..200), 50 unloading (201..250), 100 reloading (251..350), 50 (351..400).
  EXPECT_EQ(b[0].first, 0u);
  EXPECT_EQ(b[0].last, 200u);
  EXPECT_EQ(b[1].first, 200u);
  EXPECT_EQ(b[1].last, 250u);
  EXPECT_EQ(b[2].last, 350u);
  EXPECT_EQ(b[3].last, 400u);
}

TEST(OedometerCycles, JitterBelowTheToleranceDoesNotSplitABranch) {
  // Travel 0..1 mm in 1000 rows, every odd row 0.5 um behind the row before it (0.05 % of the
  // range): below the tolerance of 0.1 % of the range, so one branch; a real turn of 0.2 mm
  // still splits.
  std::vector<double> s;
  for (int k = 0; k <= 1000; ++k) s.push_back(k % 2 ? 1e-6 * (k - 1) - 0.5e-6 : 1e-6 * k);
  EXPECT_EQ(split_branches(s, 1e-3).size(), 1u);
  for (int k = 1; k <= 200; ++k) s.push_back(1e-3 - 1e-6 * k);
  EXPECT_EQ(split_branches(s, 1e-3).size(), 2u);
}

TEST(OedometerCycles, ModuliPermanentStrainsLoopAreasOfAPiecewiseLinearCurve) {
  const Curve c = two_cycles();
  const LoadUnloadAnalysis a =
      analyse_load_unload(c.travel, c.force, c.radial, {kArea, kH, kD}, settings({50e3, 100e3}));
  ASSERT_TRUE(a.has_radial_force);
  ASSERT_EQ(a.branches.size(), 4u);
  const double moduli[4] = {5e6, 20e6, 10e6, 20e6};
  for (int k = 0; k < 4; ++k) {
    const CurveBranch& b = a.branches[k];
    EXPECT_EQ(b.loading, k % 2 == 0) << k;
    ASSERT_EQ(b.moduli.size(), 2u) << k;  // every branch spans 0..100 kPa
    // Straight segments: the least-squares slope is the segment's modulus to rounding.
    EXPECT_NEAR(b.moduli[0].modulus, moduli[k], 1e-9 * moduli[k]) << k;
    // At 100 kPa the window [89.7, 110.3] kPa is one-sided (the turn), still on one segment.
    EXPECT_NEAR(b.moduli[1].modulus, moduli[k], 1e-9 * moduli[k]) << k;
    // Window 44.85..55.15 kPa: 500 Pa a row on branch 1 (45..55: 21 rows), 2 kPa on the
    // unloadings (46..54: 5 rows), 1 kPa on the reloading (45..55: 11 rows).
    const std::size_t rows[4] = {21, 5, 11, 5};
    EXPECT_EQ(b.moduli[0].points, rows[k]) << k;
    EXPECT_EQ(b.moduli[0].passages, 1u) << k;
    // K at 50 kPa: 0.4 on loading; on unloading the window's mean sigma_v is 50 kPa (rows
    // symmetric about it) and sigma_h is linear in sigma_v, so K = 0.1 + 30e3 / 50e3 = 0.7.
    EXPECT_NEAR(b.moduli[0].lateral_ratio, k % 2 == 0 ? 0.4 : 0.7, 1e-12) << k;
  }
  EXPECT_NEAR(a.branches[0].work, 1000.0, 1e-9);
  EXPECT_NEAR(a.branches[1].work, -250.0, 1e-9);
  EXPECT_NEAR(a.branches[0].lateral_ratio_end, 0.4, 1e-12);  // at the turn, 100 kPa
  ASSERT_EQ(a.cycles.size(), 2u);
  EXPECT_NEAR(a.cycles[0].loop_area, 750.0, 1e-9);
  EXPECT_NEAR(a.cycles[1].loop_area, 250.0, 1e-9);
  EXPECT_NEAR(a.cycles[0].permanent_strain, 0.015, 1e-12);
  EXPECT_NEAR(a.cycles[1].permanent_strain, 0.020, 1e-12);
  EXPECT_NEAR(a.cycles[0].rebound_strain, 0.005, 1e-12);
  EXPECT_NEAR(a.cycles[1].strain_at_turn, 0.025, 1e-12);
}

TEST(OedometerCycles, WithoutRadialForceKIsNotAvailable) {
  const Curve c = two_cycles();
  const LoadUnloadAnalysis a = analyse_load_unload(c.travel, c.force, {}, {kArea, kH, kD}, settings({50e3}));
  EXPECT_FALSE(a.has_radial_force);
  EXPECT_TRUE(std::isnan(a.branches[0].moduli[0].lateral_ratio));
  EXPECT_TRUE(std::isnan(a.branches[1].lateral_ratio_end));
  EXPECT_NEAR(a.branches[0].moduli[0].modulus, 5e6, 5e-3);
}

TEST(OedometerCycles, AStressOutsideABranchOrTooFewRowsIsReportedSo) {
  const Curve c = two_cycles();
  // 150 kPa: no branch reaches it, so no branch lists it. 99.9 kPa with a 0.05 % window
  // (99.85..99.95 kPa): no row of the loading (500 Pa apart) falls in it: listed with 0 points
  // and no modulus.
  CycleAnalysisSettings s = settings({150e3, 99.9e3});
  s.modulus_window = 5e-4;
  const LoadUnloadAnalysis a = analyse_load_unload(c.travel, c.force, c.radial, {kArea, kH, kD}, s);
  ASSERT_EQ(a.branches[0].moduli.size(), 1u);
  EXPECT_EQ(a.branches[0].moduli[0].stress, 99.9e3);
  EXPECT_EQ(a.branches[0].moduli[0].points, 0u);
  EXPECT_TRUE(std::isnan(a.branches[0].moduli[0].modulus));
}

TEST(OedometerCycles, MismatchedArraysAreRefused) {
  EXPECT_THROW(analyse_load_unload({0, 1e-3}, {0}, {}, {kArea, kH, kD}, {}), std::invalid_argument);
  EXPECT_THROW(analyse_load_unload({0, 1e-3}, {0, 1}, {0}, {kArea, kH, kD}, {}), std::invalid_argument);
  EXPECT_THROW(analyse_load_unload({0, 1e-3}, {0, 1}, {}, {0.0, kH, kD}, {}), std::invalid_argument);
}

TEST(OedometerCycles, ABranchThatPassesTheStressTwiceSaysSo) {
  // One loading (travel always growing), rows every 1e-4 of strain: sigma = 5 MPa x eps up to
  // 60 kPa (row 120, eps = 0.012), a collapse to 40 kPa (row 130), then 5 MPa x (eps - 0.005)
  // up to 80 kPa (row 170). The 50 kPa window (44.85..55.15 kPa) holds rows 90..110 and
  // 140..160: two passages of 21 rows, parallel segments of slope 5 MPa offset by 0.005 in
  // strain at the same stresses. The least-squares line through both: the groups' mean
  // stresses are equal, so the between-group part adds nothing to the covariance and
  //   M = 5 MPa x W / (W + B),  W = 2 x 1e-8 x sum_{j=-10..10} j^2 = 1.54e-5,
  //                             B = 42 x 0.0025^2 = 2.625e-4      -> M = 0.2771 MPa,
  // no tangent: `passages` = 2 says so.
  std::vector<double> travel, force;
  for (int k = 0; k <= 120; ++k) travel.push_back(k * 1e-4 * kH), force.push_back(5e6 * k * 1e-4 * kArea);
  for (int k = 130; k <= 170; ++k) travel.push_back(k * 1e-4 * kH), force.push_back(5e6 * (k * 1e-4 - 0.005) * kArea);
  const LoadUnloadAnalysis a = analyse_load_unload(travel, force, {}, {kArea, kH, kD}, settings({50e3}));
  ASSERT_EQ(a.branches.size(), 1u);
  ASSERT_EQ(a.branches[0].moduli.size(), 1u);
  const LocalModulus& m = a.branches[0].moduli[0];
  EXPECT_EQ(m.points, 42u);
  EXPECT_EQ(m.passages, 2u);
  const double w = 2.0 * 1e-8 * 770.0, b = 42.0 * 0.0025 * 0.0025;
  EXPECT_NEAR(m.modulus, 5e6 * w / (w + b), 1e-6 * 5e6 * w / (w + b));
}
