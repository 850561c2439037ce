// The cross-check's curve arithmetic (src/analysis/curve_comparison.hpp), on cases worked by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "analysis/curve_comparison.hpp"

namespace {

using colza::interpolate;
using colza::line_weights;
using colza::max_difference;
using colza::max_magnitude;
using colza::mohr_coulomb;
using colza::relative_difference;
using colza::rms_difference;

const double kInfinity = std::numeric_limits<double>::infinity();

TEST(CrosscheckCurveMath, InterpolatesLinearlyInsideAndGivesNaNOutside) {
  const std::vector<double> xs = {0.0, 1.0, 3.0}, ys = {0.0, 10.0, 30.0};
  EXPECT_DOUBLE_EQ(interpolate(xs, ys, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(interpolate(xs, ys, 0.5), 5.0);
  EXPECT_DOUBLE_EQ(interpolate(xs, ys, 2.0), 20.0);  // 10 + (2 - 1) / (3 - 1) (30 - 10)
  EXPECT_DOUBLE_EQ(interpolate(xs, ys, 3.0), 30.0);
  EXPECT_TRUE(std::isnan(interpolate(xs, ys, -0.1)));
  EXPECT_TRUE(std::isnan(interpolate(xs, ys, 3.1)));
  EXPECT_TRUE(std::isnan(interpolate({}, {}, 0.0)));
  EXPECT_TRUE(std::isnan(interpolate(xs, ys, std::nan(""))));  // not ys[0]: NaN is nowhere inside
}

// colza c = x + 1 (1, 2, 3, 4 at x = 0..3) against YADE y = x + 2 (2, 3, 4, 5 at the same
// x): inside [1, 3] the points x = 1, 2, 3 with colza 2, 3, 4 and YADE 3, 4, 5, so
// relative = sqrt(3 / (4 + 9 + 16)), rms colza = sqrt(29 / 3), rms YADE = sqrt(50 / 3).
TEST(CrosscheckCurveMath, RmsDifferenceOverTheRange) {
  const std::vector<double> x = {0.0, 1.0, 2.0, 3.0}, c = {1.0, 2.0, 3.0, 4.0}, y = {2.0, 3.0, 4.0, 5.0};
  const auto d = rms_difference(x, c, x, y, 1.0, 3.0);
  EXPECT_EQ(d.n, 3u);
  EXPECT_DOUBLE_EQ(d.relative, std::sqrt(3.0 / 29.0));
  EXPECT_DOUBLE_EQ(d.rms_colza, std::sqrt(29.0 / 3.0));
  EXPECT_DOUBLE_EQ(d.rms_yade, std::sqrt(50.0 / 3.0));
}

TEST(CrosscheckCurveMath, RmsDifferenceSkipsWhereYadeIsNotDefinedAndIsNaNWithoutPoints) {
  const std::vector<double> cx = {0.0, 1.0, 2.0}, cy = {1.0, 1.0, 1.0};
  const std::vector<double> yx = {0.5, 1.5}, yy = {1.0, 1.0};
  EXPECT_EQ(rms_difference(cx, cy, yx, yy, 0.0, 2.0).n, 1u);  // only x = 1 lies in [0.5, 1.5]
  EXPECT_TRUE(std::isnan(rms_difference(cx, cy, yx, yy, 5.0, 6.0).relative));
  EXPECT_TRUE(std::isnan(rms_difference(cx, cy, yx, yy, std::nan(""), 2.0).relative));  // no lower bound found
  EXPECT_EQ(rms_difference({std::nan(""), 1.0}, {1.0, 1.0}, yx, yy, 0.0, 2.0).n, 1u);  // a NaN abscissa takes no point
}

// A force that is not finite where both curves are defined is no missing point: it makes the
// difference +inf (it used to be skipped as "YADE not defined there", or to give NaN).
TEST(CrosscheckCurveMath, RmsDifferenceIsInfiniteWhenAForceIsNotFinite) {
  const std::vector<double> x = {0.0, 1.0, 2.0}, c = {1.0, 2.0, 3.0};
  const double nan = std::nan("");
  EXPECT_EQ(rms_difference(x, c, x, {1.0, nan, 3.0}, 0.0, 2.0).relative, kInfinity);
  EXPECT_EQ(rms_difference(x, c, x, {nan, nan, nan}, 0.0, 2.0).relative, kInfinity);
  EXPECT_EQ(rms_difference(x, {1.0, kInfinity, 3.0}, x, c, 0.0, 2.0).relative, kInfinity);
  EXPECT_EQ(rms_difference(x, c, x, c, 0.0, 2.0).relative, 0.0);
}

// std::max(m, NaN) is m: a running maximum by std::max skips NaN. max_magnitude keeps it.
TEST(CrosscheckCurveMath, MaxMagnitudeKeepsANaNOrInfiniteValue) {
  EXPECT_EQ(max_magnitude(max_magnitude(0.0, -3.0), 2.0), 3.0);
  EXPECT_TRUE(std::isnan(max_magnitude(1.0, std::nan(""))));
  EXPECT_TRUE(std::isnan(max_magnitude(1.0, -kInfinity)));
  EXPECT_TRUE(std::isnan(max_magnitude(std::nan(""), 5.0)));  // and stays NaN
}

TEST(CrosscheckCurveMath, RelativeDifferenceOfAZeroOrNonFiniteSignal) {
  EXPECT_EQ(relative_difference(1.0, 4.0), 0.25);
  EXPECT_EQ(relative_difference(0.0, 0.0), 0.0);  // two zero signals agree
  EXPECT_EQ(relative_difference(1e-300, 0.0), kInfinity);
  EXPECT_EQ(relative_difference(std::nan(""), 1.0), kInfinity);
  EXPECT_EQ(relative_difference(1.0, std::nan("")), kInfinity);
  EXPECT_EQ(relative_difference(kInfinity, 1.0), kInfinity);
}

TEST(CrosscheckCurveMath, MaxDifferenceOverTheFirstRows) {
  const std::vector<double> c = {1.0, -4.0, 2.0, 100.0}, y = {1.5, -4.0, 1.0, 0.0};
  const auto d = max_difference(c, y, 3);  // max |c - y| = 1 (row 2), max |c| = 4, max |y| = 4 (row 1)
  EXPECT_DOUBLE_EQ(d.max_colza, 4.0);
  EXPECT_DOUBLE_EQ(d.max_yade, 4.0);
  EXPECT_DOUBLE_EQ(max_difference({1.0}, {-3.0}, 1).max_yade, 3.0);
  EXPECT_DOUBLE_EQ(d.relative, 0.25);
}

// colza all zero: YADE all zero agrees (0); YADE not zero is an infinite relative difference,
// whatever it gives (it used to be 0, so any YADE passed).
TEST(CrosscheckCurveMath, MaxDifferenceFromAZeroSignal) {
  EXPECT_EQ(max_difference({0.0, 0.0}, {0.0, 0.0}, 2).relative, 0.0);
  EXPECT_EQ(max_difference({0.0, 0.0}, {1.0, 1.0}, 2).relative, kInfinity);
  EXPECT_EQ(max_difference({0.0, 0.0}, {0.0, -1e-300}, 2).relative, kInfinity);
}

// A value that is not finite, in either code, makes the relative difference +inf and that
// code's maximum NaN (std::max skipped it: an all-NaN YADE gave 0 and passed).
TEST(CrosscheckCurveMath, MaxDifferenceWithAValueThatIsNotFinite) {
  const double nan = std::nan("");
  const std::vector<double> c = {1.0, 2.0, 3.0};
  const auto all_nan = max_difference(c, {nan, nan, nan}, 3);
  EXPECT_EQ(all_nan.relative, kInfinity);
  EXPECT_TRUE(std::isnan(all_nan.max_yade));
  EXPECT_DOUBLE_EQ(all_nan.max_colza, 3.0);
  EXPECT_EQ(max_difference(c, {1.0, nan, 3.0}, 3).relative, kInfinity);
  const auto colza_inf = max_difference({1.0, kInfinity}, {1.0, 2.0}, 2);
  EXPECT_EQ(colza_inf.relative, kInfinity);
  EXPECT_TRUE(std::isnan(colza_inf.max_colza));
  EXPECT_EQ(max_difference(c, {1.0, 2.0, nan}, 2).relative, 0.0);  // past `rows`: not compared
}

// Points on tau = 5 kPa + sigma tan(30 deg) give C = 5 kPa and Phi = 30 deg.
TEST(CrosscheckCurveMath, MohrCoulombLineThroughExactPoints) {
  const double tan_phi = std::tan(std::numbers::pi / 6.0);
  const std::vector<double> sigma = {25750.0, 52250.0, 78750.0};
  std::vector<double> tau;
  for (double s : sigma) tau.push_back(5000.0 + s * tan_phi);
  const auto [c, phi] = mohr_coulomb(sigma, tau);
  EXPECT_NEAR(c, 5000.0, 1e-8);
  EXPECT_NEAR(phi, 30.0, 1e-10);
}


// Loads 1, 2, 3: mean 2, Sxx = 2, slope weights (-1/2, 0, 1/2), intercept weights
// 1/3 - 2 (-1/2, 0, 1/2) = (4/3, 1/3, -2/3). On tau = 5 + 2 sigma (7, 9, 11) they give the
// intercept 28/3 + 3 - 22/3 = 5 and the slope 2.
TEST(CrosscheckCurveMath, LeastSquaresLineWeights) {
  const auto w = line_weights({1.0, 2.0, 3.0});
  ASSERT_EQ(w.slope.size(), 3u);
  EXPECT_DOUBLE_EQ(w.slope[0], -0.5);
  EXPECT_DOUBLE_EQ(w.slope[1], 0.0);
  EXPECT_DOUBLE_EQ(w.slope[2], 0.5);
  EXPECT_DOUBLE_EQ(w.intercept[0], 4.0 / 3.0);
  EXPECT_DOUBLE_EQ(w.intercept[1], 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(w.intercept[2], -2.0 / 3.0);
  const std::vector<double> tau = {7.0, 9.0, 11.0};
  double a = 0.0, b = 0.0;
  for (int k = 0; k < 3; ++k) {
    a += w.intercept[k] * tau[k];
    b += w.slope[k] * tau[k];
  }
  EXPECT_NEAR(a, 5.0, 1e-14);
  EXPECT_NEAR(b, 2.0, 1e-14);
}

}  // namespace
