// Whole-curve features of a direct shear curve (analysis/shear_curve_features.hpp) and the
// inertial number (analysis/inertial_number.hpp), on synthetic curves with closed forms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "analysis/inertial_number.hpp"
#include "analysis/shear_curve_features.hpp"

using namespace colza;

namespace {

// Rows every 0.01 mm from 0 to 10 mm (row k at d = k x 1e-5 m).
// Shear stress (kPa, d in mm): a tent rising at a = 20 kPa/mm from 0 to 40 kPa at 2 mm,
// falling at the same slope to 29 kPa at 2.55 mm, then 29 kPa (the residual).
// Plate height (m): 0.08 - 0.05 d for d <= 1 mm (contraction), then rising at slope
// tan(psi) = 0.2 up to 4 mm, then flat.
struct Curve {
  std::vector<double> d, tau, h;
};

Curve tent_curve() {
  Curve c;
  for (int k = 0; k <= 1000; ++k) {
    const double mm = 0.01 * k;
    c.d.push_back(1e-5 * k);
    c.tau.push_back(1e3 * (mm <= 2.0 ? 20.0 * mm : std::max(29.0, 40.0 - 20.0 * (mm - 2.0))));
    const double rise_mm = mm <= 1.0 ? -0.05 * mm : -0.05 + 0.2 * (std::min(mm, 4.0) - 1.0);
    c.h.push_back(0.08 + 1e-3 * rise_mm);
  }
  return c;
}

ShearCurveSettings tent_settings() {
  ShearCurveSettings s;
  s.window = {0.006, 0.010};
  // 1.005 mm: the interval's start falls half-way between rows, so each interval holds 101
  // rows whatever the rounding of the displacements.
  s.peak_width = 1.005e-3;
  s.stiffness_fraction = 0.5;
  return s;
}

}  // namespace

TEST(ShearCurveFeatures, PeakDropDilationAndStiffnessOfATent) {
  const Curve c = tent_curve();
  const ShearCurveFeatures f = shear_curve_features(c.d, c.tau, c.h, tent_settings());
  // Peak: the trailing mean over rows i-100..i grows while tau(i+1) > tau(i-100). At i = 250
  // (2.5 mm) tau(251) = 40 - 20 x 0.51 = 29.8 < tau(150) = 30, and at i = 249 tau(250) = 30 >
  // tau(149) = 29.8: the largest mean is at 2.5 mm, over 1.5..2.5 mm, where
  // tau = 40 - 0.2 |j| kPa for j = -50..50 rows about 2 mm:
  //   mean = 40 - 0.2 x (2 x (1 + ... + 50)) / 101 = 40 - 0.2 x 2550 / 101 kPa.
  const double peak = 1e3 * (40.0 - 0.2 * 2550.0 / 101.0);
  EXPECT_NEAR(f.peak.value, peak, 1e-9);
  EXPECT_NEAR(f.peak.displacement, 2.5e-3, 1e-12);
  EXPECT_EQ(f.peak.samples, 101u);
  // Residual over 6..10 mm: 29 kPa; drop = peak - residual.
  EXPECT_NEAR(f.residual, 29e3, 1e-9);
  EXPECT_NEAR(f.drop, peak - 29e3, 1e-9);
  EXPECT_NEAR(f.drop_fraction, (peak - 29e3) / peak, 1e-12);
  // Largest dilation: -0.05 + 0.2 x (4 - 1) = 0.55 mm, first reached at 4 mm.
  EXPECT_NEAR(f.max_dilation, 0.55e-3, 1e-12);
  EXPECT_NEAR(f.max_dilation_displacement, 4e-3, 1e-12);
  // Dilatancy at the peak: the peak's rows (1.5..2.5 mm) lie on the straight rise of slope 0.2,
  // psi = atan(0.2) = 11.3099 deg.
  EXPECT_EQ(f.dilatancy_points, 101u);
  EXPECT_NEAR(f.dilatancy_angle_deg, std::atan(0.2) * 180.0 / 3.14159265358979323846, 1e-9);
  // Secant to half the peak: on the straight rise from (0, 0), so the slope a = 20 kPa/mm =
  // 2e7 Pa/m, reached at d = 0.5 peak / a.
  EXPECT_NEAR(f.initial_stiffness, 2e7, 1e-3);
  EXPECT_NEAR(f.stiffness_displacement, 0.5 * peak / 2e7, 1e-12);
}

TEST(ShearCurveFeatures, WithoutPlateHeightTheDilatancyIsNotAvailable) {
  const Curve c = tent_curve();
  const ShearCurveFeatures f = shear_curve_features(c.d, c.tau, {}, tent_settings());
  EXPECT_FALSE(f.has_plate_height);
  EXPECT_TRUE(std::isnan(f.dilatancy_angle_deg));
  EXPECT_TRUE(std::isnan(f.max_dilation));
  EXPECT_NEAR(f.initial_stiffness, 2e7, 1e-3);  // the stress features do not need it
}

TEST(ShearCurveFeatures, APlateColumnWithAnOffsetGivesTheSameDilation) {
  // A plate rise since the start (curve.csv's "dilatancy") instead of the plate's height.
  Curve c = tent_curve();
  std::vector<double> rise;
  for (double h : c.h) rise.push_back(h - c.h[0]);
  const ShearCurveFeatures a = shear_curve_features(c.d, c.tau, c.h, tent_settings());
  const ShearCurveFeatures b = shear_curve_features(c.d, c.tau, rise, tent_settings());
  EXPECT_NEAR(a.max_dilation, b.max_dilation, 1e-15);
  EXPECT_NEAR(a.dilatancy_angle_deg, b.dilatancy_angle_deg, 1e-9);
}

TEST(ShearCurveFeatures, MismatchedArraysAreRefused) {
  EXPECT_THROW(shear_curve_features({0, 1}, {0}, {}, {}), std::invalid_argument);
  EXPECT_THROW(shear_curve_features({0, 1}, {0, 1}, {0}, {}), std::invalid_argument);
}

TEST(InertialNumber, ClosedFormAndLinearInSpeed) {
  // I = gamma_dot d sqrt(rho / p): piston 0.01 m/s on H = 0.1 m -> 0.1 1/s; d = 5 mm,
  // rho = 1000 kg/m^3, p = 1e5 Pa -> sqrt(1e-2) = 0.1; I = 0.1 x 0.005 x 0.1 = 5e-5.
  const double i1 = inertial_number(oedometer_strain_rate(0.01, 0.1), 0.005, 1000.0, 1e5);
  EXPECT_NEAR(i1, 5e-5, 1e-18);
  // Linear in speed: each factor of the speed is a factor of I (the strain rate is v / H).
  for (double factor : {2.0, 10.0, 100.0})
    EXPECT_NEAR(inertial_number(oedometer_strain_rate(0.01 * factor, 0.1), 0.005, 1000.0, 1e5), factor * i1,
                1e-15 * factor);
  // Shear box: the zone is 10 mean diameters (65 mm for 6.5 mm seeds), capped at the sample's
  // height: the paper's box at 300 mm/min and 25.75 kPa:
  //   I = (0.005 / 0.065) x 0.0065 x sqrt(1250 / 25750) = 5e-4 x 0.220326 = 1.10163e-4.
  EXPECT_NEAR(shear_zone_thickness(0.0065, 0.080), 0.065, 1e-15);
  EXPECT_NEAR(shear_zone_thickness(0.0065, 0.030), 0.030, 1e-15);
  EXPECT_NEAR(inertial_number(shear_box_strain_rate(0.005, 0.0065, 0.080), 0.0065, 1250.0, 25750.0),
              5e-4 * std::sqrt(1250.0 / 25750.0), 1e-15);
  EXPECT_THROW(inertial_number(0.0, 0.005, 1000.0, 1e5), std::invalid_argument);
  EXPECT_THROW(inertial_number(1.0, 0.005, 1000.0, 0.0), std::invalid_argument);
}
