// Is the model adequate for the measured features? (colza diagnose, step 1.)
// The whitened residual e = L^-1 (m - ybar) (noise_model.hpp) of a model that is right has
// independent unit-variance components; after fitting p parameters to F features its
// squared length, the Mahalanobis distance chi2 = e^T e = r^T Sigma^-1 r, follows a
// chi-square law with F - p degrees of freedom. The model is judged inadequate when
// P(X >= chi2) < alpha (the significance level).
#pragma once
#include <Eigen/Dense>

#include "diagnose/noise_model.hpp"

namespace colza::diagnose {

struct AdequacyTest {
  double chi_square = 0.0;
  int degrees_of_freedom = 0;  // F - p; 0: nothing left to test (p_value 1)
  double p_value = 1.0;
  bool passes = true;          // p_value >= alpha
  Eigen::VectorXd z;           // r_i / sd_i: each feature's residual in its own noise units (report)
};

AdequacyTest test_adequacy(const NoiseModel& noise, const Eigen::VectorXd& residual, int fitted_parameters,
                           double significance);

// P(X >= x) for X ~ chi-square with k degrees of freedom (k >= 1).
double chi_square_survival(double x, int k);
// P(Z >= z) for a standard normal Z.
double normal_survival(double z);

}  // namespace colza::diagnose
