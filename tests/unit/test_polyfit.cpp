// Least-squares polynomial fit and the compression-curve characterisation
// (physics.md section 4: F(s) = c0 + c1 s + c2 s^2 over 150 N .. 29.3 kN, s zeroed where F
// first reaches 150 N).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "analysis/polyfit.hpp"

using namespace colza;

TEST(Polyfit, RecoversExactQuadratic) {
  // y = 150 + 2e6 x + 3e8 x^2 sampled on x in [0, 0.03] m: an exact quadratic, so least
  // squares returns its coefficients (to rounding) and R^2 = 1.
  const double c0 = 150.0, c1 = 2e6, c2 = 3e8;
  std::vector<double> x, y;
  for (int i = 0; i <= 60; ++i) {
    const double s = 0.0005 * i;
    x.push_back(s);
    y.push_back(c0 + c1 * s + c2 * s * s);
  }
  const PolynomialFit f = fit_polynomial(x, y, 2);
  ASSERT_EQ(f.coefficients.size(), 3u);
  EXPECT_EQ(f.points, 61u);
  EXPECT_NEAR(f.coefficients[0], c0, 1e-9 * 3e5);  // y spans up to ~3.3e5 N
  EXPECT_NEAR(f.coefficients[1], c1, 1e-9 * c1);
  EXPECT_NEAR(f.coefficients[2], c2, 1e-9 * c2);
  EXPECT_NEAR(f.r2, 1.0, 1e-12);
}

TEST(Polyfit, LinearFitOfNoisyDataHasKnownR2) {
  // y = {1, 0, 3, 2} at x = {0, 1, 2, 3}, straight line a + b x. Normal equations by hand:
  // sum x = 6, sum x^2 = 14, sum y = 6, sum x y = 0 + 0 + 6 + 6 = 12:
  //   4 a + 6 b = 6,  6 a + 14 b = 12  ->  5 b = 3, b = 0.6, a = 0.6.
  // Fitted 0.6, 1.2, 1.8, 2.4; residuals 0.4, -1.2, 1.2, -0.4, SS_res = 3.2;
  // mean y = 1.5, SS_tot = 0.25 + 2.25 + 2.25 + 0.25 = 5; R^2 = 1 - 3.2/5 = 0.36.
  const PolynomialFit f = fit_polynomial({0, 1, 2, 3}, {1, 0, 3, 2}, 1);
  EXPECT_NEAR(f.coefficients[0], 0.6, 1e-13);
  EXPECT_NEAR(f.coefficients[1], 0.6, 1e-13);
  EXPECT_NEAR(f.r2, 0.36, 1e-13);
}

TEST(Polyfit, RejectsTooFewPoints) {
  EXPECT_THROW(fit_polynomial({0, 1, 2}, {0, 1, 4}, 2), std::invalid_argument);
  EXPECT_THROW(fit_polynomial({0, 1, 2, 3}, {0, 1, 4}, 1), std::invalid_argument);
}

TEST(CompressionFit, ZeroesDisplacementAtForceMinByLinearInterpolation) {
  // Curve F(s) = a s + b s^2 sampled every h = 1e-4 m; force_min = 150 N.
  // a = 1e6 N/m, b = 5e8 N/m^2: F(1e-4) = 100 + 5 = 105 N, F(2e-4) = 200 + 20 = 220 N, so the
  // crossing lies between samples 1 and 2 and the zero is the linear interpolation
  //   s0 = 1e-4 + (150 - 105) / (220 - 105) * 1e-4 = 1e-4 (1 + 45/115).
  // In s' = s - s0 the curve is F = (a s0 + b s0^2) + (a + 2 b s0) s' + b s'^2 exactly, so the
  // quadratic fit returns these three coefficients.
  const double a = 1e6, b = 5e8, h = 1e-4;
  std::vector<double> s, F;
  for (int i = 0; i <= 200; ++i) {
    s.push_back(i * h);
    F.push_back(a * i * h + b * (i * h) * (i * h));
  }
  const CompressionFit c = fit_compression_curve(s, F, 150.0, 1e9);
  ASSERT_TRUE(c.valid);
  const double s0 = 1e-4 * (1.0 + 45.0 / 115.0);
  EXPECT_NEAR(c.zero_displacement, s0, 1e-17);
  EXPECT_FALSE(c.reached_force_max);
  // Points with F >= 150 N: samples 2..200 -> 199 points.
  EXPECT_EQ(c.fit.points, 199u);
  EXPECT_NEAR(c.fit.coefficients[0], a * s0 + b * s0 * s0, 1e-8 * 1e5);
  EXPECT_NEAR(c.fit.coefficients[1], a + 2 * b * s0, 1e-9 * a);
  EXPECT_NEAR(c.fit.coefficients[2], b, 1e-9 * b);
  EXPECT_NEAR(c.fit.r2, 1.0, 1e-12);
}

TEST(CompressionFit, StopsAtForceMaxAndNeedsEnoughPoints) {
  // Linear F = 1e6 s, h = 1e-4: F_i = 100 i N. force_min 150 -> crossing at s0 = 1.5e-4 exactly
  // (midway between 100 N and 200 N). force_max 1050 N: samples 2..10 (200..1000 N) are fitted,
  // sample 11 (1100 N) exceeds the maximum and ends the fit.
  std::vector<double> s, F;
  for (int i = 0; i <= 20; ++i) {
    s.push_back(i * 1e-4);
    F.push_back(100.0 * i);
  }
  const CompressionFit c = fit_compression_curve(s, F, 150.0, 1050.0);
  ASSERT_TRUE(c.valid);
  EXPECT_TRUE(c.reached_force_max);
  EXPECT_NEAR(c.zero_displacement, 1.5e-4, 1e-18);
  EXPECT_EQ(c.fit.points, 9u);
  // In s' = s - 1.5e-4: F = 150 + 1e6 s' (+ 0 s'^2).
  EXPECT_NEAR(c.fit.coefficients[0], 150.0, 1e-8);
  EXPECT_NEAR(c.fit.coefficients[1], 1e6, 1e-4);
  EXPECT_NEAR(c.fit.coefficients[2], 0.0, 1e-2);

  // Never reaching force_min: invalid.
  EXPECT_FALSE(fit_compression_curve(s, F, 5000.0, 1e9).valid);
  // Fewer than 4 points in range: invalid.
  EXPECT_FALSE(fit_compression_curve(s, F, 150.0, 450.0).valid);  // samples 2, 3, 4 only
  // Starting above force_min: no interpolation, zero at the first sample.
  const CompressionFit d = fit_compression_curve(s, F, 0.0, 1e9);
  ASSERT_TRUE(d.valid);
  EXPECT_EQ(d.zero_displacement, 0.0);
}
