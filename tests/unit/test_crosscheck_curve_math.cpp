// The cross-check's curve arithmetic (crosscheck/curve_math.hpp), on cases worked by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "crosscheck/curve_math.hpp"

namespace {

using crosscheck::interpolate;
using crosscheck::line_weights;
using crosscheck::max_difference;
using crosscheck::mohr_coulomb;
using crosscheck::rms_difference;

TEST(CrosscheckCurveMath, InterpolatesLinearlyInsideAndGivesNaNOutside) {
  const std::vector<double> xs = {0.0, 1.0, 3.0}, ys = {0.0, 10.0, 30.0};
  EXPECT_DOUBLE_EQ(interpolate(xs, ys, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(interpolate(xs, ys, 0.5), 5.0);
  EXPECT_DOUBLE_EQ(interpolate(xs, ys, 2.0), 20.0);  // 10 + (2 - 1) / (3 - 1) (30 - 10)
  EXPECT_DOUBLE_EQ(interpolate(xs, ys, 3.0), 30.0);
  EXPECT_TRUE(std::isnan(interpolate(xs, ys, -0.1)));
  EXPECT_TRUE(std::isnan(interpolate(xs, ys, 3.1)));
  EXPECT_TRUE(std::isnan(interpolate({}, {}, 0.0)));
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

TEST(CrosscheckCurveMath, MaxDifferenceOverTheFirstRows) {
  const std::vector<double> c = {1.0, -4.0, 2.0, 100.0}, y = {1.5, -4.0, 1.0, 0.0};
  const auto d = max_difference(c, y, 3);  // max |c - y| = 1 (row 2), max |c| = 4, max |y| = 4 (row 1)
  EXPECT_DOUBLE_EQ(d.max_colza, 4.0);
  EXPECT_DOUBLE_EQ(d.max_yade, 4.0);
  EXPECT_DOUBLE_EQ(max_difference({1.0}, {-3.0}, 1).max_yade, 3.0);
  EXPECT_DOUBLE_EQ(d.relative, 0.25);
  EXPECT_DOUBLE_EQ(max_difference({0.0, 0.0}, {1.0, 1.0}, 2).relative, 0.0);
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
