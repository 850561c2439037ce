// Mohr-Coulomb line: exact recovery of a known line, and the paper's measured line.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/mohr_coulomb.hpp"

using colza::fit_mohr_coulomb;

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

TEST(MohrCoulomb, RejectsFewerThanTwoDistinctLoads) {
  EXPECT_THROW(fit_mohr_coulomb({1.0}, {2.0}), std::invalid_argument);
  EXPECT_THROW(fit_mohr_coulomb({1.0, 1.0}, {2.0, 3.0}), std::invalid_argument);
}
