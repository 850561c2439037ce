// Mohr-Coulomb line: exact recovery of a known line, and the paper's measured line.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/mohr_coulomb.hpp"

using colza::cohesion_note;
using colza::fit_mohr_coulomb;
using colza::MohrCoulombFit;

TEST(MohrCoulomb, RecoversAKnownLineExactly) {
  // tau = C + sigma tan(Phi) with the paper's measured C = 11.41 kPa, Phi = 28.10 deg,
  // sampled at the paper's four loads: the fit must give back C and Phi (to rounding).
  const double c = 11.41e3, phi = 28.10;
  const double slope = std::tan(phi * M_PI / 180.0);
  const std::vector<double> sigma{25.75e3, 43.50e3, 61.00e3, 78.75e3};
  std::vector<double> tau;
  for (double s : sigma) tau.push_back(c + slope * s);
  const auto fit = fit_mohr_coulomb(sigma, tau);
  EXPECT_NEAR(fit.cohesion, c, 1e-9 * c);
  EXPECT_NEAR(fit.friction_angle_deg, phi, 1e-10);
  EXPECT_NEAR(fit.r2, 1.0, 1e-12);
}

TEST(MohrCoulomb, TwoLoadsGiveAnR2OfExactlyOne) {
  // r^2 = Sxy^2 / (Sxx Syy) is 1 for any two points, but rounded it comes out at
  // 1.0000000000000002 for these (tests/unit/mohr_coulomb_r2_reference.py evaluates the sums
  // in the fit's order in IEEE doubles, prints that value and can search for another pair if
  // the fit's order of sums changes); an r^2 above 1 is not a coefficient of determination,
  // so the fit caps it.
  const auto fit = fit_mohr_coulomb({25750.0, 78750.0}, {32913.238569298424, 30202.761029576868});
  EXPECT_EQ(fit.r2, 1.0);
}

TEST(MohrCoulomb, LeastSquaresThroughScatter) {
  // Symmetric scatter +-d about tau = 1000 + 0.5 sigma at sigma = 0, 1, 2, 3 (with signs
  // +, -, -, +) leaves slope and intercept unchanged: sum of (x - mean) * e = 0 and sum e = 0.
  const std::vector<double> sigma{0.0, 1.0, 2.0, 3.0};
  const std::vector<double> e{+1.0, -1.0, -1.0, +1.0};
  std::vector<double> tau;
  for (std::size_t i = 0; i < sigma.size(); ++i) tau.push_back(1000.0 + 0.5 * sigma[i] + e[i]);
  const auto fit = fit_mohr_coulomb(sigma, tau);
  EXPECT_NEAR(fit.cohesion, 1000.0, 1e-9);
  EXPECT_NEAR(fit.slope, 0.5, 1e-12);
  EXPECT_LT(fit.r2, 1.0);
}

TEST(MohrCoulomb, StandardErrorsFromTheScatterAboutTheLine) {
  // Worked by hand: sigma = 0, 1, 2, 3 (x 1e4 Pa), tau = 1, 3, 4, 7 (x 1e4 Pa). Means 1.5 and
  // 3.75, Sxx = 5, Sxy = 9.5: slope 1.9, C = 0.9e4 Pa. Residuals 0.1, 0.2, -0.7, 0.4 (x 1e4),
  // SSE = 0.70e8, s = sqrt(0.35) 1e4 = 5916.08 Pa with 2 degrees of freedom;
  // se(slope) = s / sqrt(5e8) = 0.264575, se(C) = s sqrt(1/4 + 2.25e8 / 5e8) = 4949.75 Pa,
  // se(Phi) = 0.264575 / (1 + 1.9^2) rad = 3.28829 deg.
  const auto fit = fit_mohr_coulomb({0.0, 1e4, 2e4, 3e4}, {1e4, 3e4, 4e4, 7e4});
  EXPECT_NEAR(fit.slope, 1.9, 1e-12);
  EXPECT_NEAR(fit.cohesion, 9000.0, 1e-8);
  EXPECT_EQ(fit.degrees_of_freedom, 2);
  EXPECT_NEAR(fit.slope_se, 0.264575131, 1e-8);
  EXPECT_NEAR(fit.cohesion_se, 4949.74747, 1e-4);
  EXPECT_NEAR(fit.friction_angle_se_deg, 3.288295, 1e-5);
  // Two loads: no degree of freedom, no standard error.
  const auto two = fit_mohr_coulomb({1e4, 3e4}, {3e4, 7e4});
  EXPECT_EQ(two.degrees_of_freedom, 0);
  EXPECT_TRUE(std::isnan(two.cohesion_se));
  EXPECT_TRUE(std::isnan(two.friction_angle_se_deg));
}

TEST(MohrCoulomb, RejectsFewerThanTwoDistinctLoads) {
  EXPECT_THROW(fit_mohr_coulomb({1.0}, {2.0}), std::invalid_argument);
  EXPECT_THROW(fit_mohr_coulomb({1.0, 1.0}, {2.0, 3.0}), std::invalid_argument);
}

TEST(MohrCoulomb, ACohesionWithinTwoStandardErrorsOfZeroIsNoted) {
  MohrCoulombFit fit;
  fit.degrees_of_freedom = 2;
  fit.cohesion = -1151.0;  // a walk-through's series: -1.151 +/- 5.286 kPa
  fit.cohesion_se = 5286.0;
  EXPECT_NE(cohesion_note(fit).find("not a strength"), std::string::npos) << cohesion_note(fit);
  fit.cohesion = 3000.0;
  EXPECT_EQ(cohesion_note(fit), "C is within two standard errors of zero: these loads do not tell it from no cohesion");
  fit.cohesion = 12849.76;  // the same machine's paper series: 12.850 +/- 1.258 kPa
  fit.cohesion_se = 1257.88;
  EXPECT_EQ(cohesion_note(fit), "");
  fit.degrees_of_freedom = 0;  // two loads: no standard error to judge by
  fit.cohesion = -100.0;
  fit.cohesion_se = std::nan("");
  EXPECT_EQ(cohesion_note(fit), "");
}
