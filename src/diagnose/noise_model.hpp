// The noise a feature's residual is judged against (colza diagnose, step 1).
//
// A measured feature m_i and the model's mean ybar_i over R realisations (seeds) at the
// fitted parameters differ by r = m - ybar. Its covariance is
//     Sigma = U + c D S D,   D = diag(sqrt(1/n_i + 1/R)),
// U = D_u C D_u the measurement's (u_i the stated standard uncertainty, C its correlation),
// S the realisation scatter of one run (estimated from the R realisations), counted once per
// lab sample for the measured value, a mean over n_i samples (each a realisation of the
// material, its sample-to-sample scatter taken as the model's: conservative for a lab sample
// larger than the simulated one), and once divided by R for the model's mean. c = (n - 1) / (n - 3), n = R, corrects for S being estimated
// (E[sigma^2 / s^2] = (n - 1) / (n - 3) for a sample variance with n - 1 degrees of freedom),
// so the whitened residual's mean square is 1 under the null.
//
// S is shrunk toward its diagonal (Schafer & Strimmer 2005, Stat. Appl. Genet. Mol. Biol.
// 4(1) 32, target "D"): the correlations r_ij are multiplied by 1 - lambda,
// lambda = sum_{i != j} Var(r_ij) / sum_{i != j} r_ij^2 clipped to [0, 1], so that a few
// replicates do not invent correlations between many features.
#pragma once
#include <Eigen/Dense>
#include <vector>

namespace colza::diagnose {

struct NoiseModel {
  Eigen::MatrixXd covariance;  // Sigma (feature units squared)
  Eigen::VectorXd sd;          // sqrt(diag Sigma)
  Eigen::VectorXd scatter_sd;  // sqrt(diag S), one run's realisation scatter (0 without replicates)
  double shrinkage = 1.0;      // lambda in [0, 1] (1: S taken diagonal)
  int realisations = 0;        // R
  Eigen::MatrixXd whitener;    // L^-1 with Sigma = L L^T: whitened residuals are independent, unit variance

  Eigen::VectorXd whiten(const Eigen::VectorXd& v) const { return whitener * v; }
  Eigen::MatrixXd whiten(const Eigen::MatrixXd& m) const { return whitener * m; }
};

// The realisations' sample covariance shrunk toward its diagonal (see above); `lambda`
// receives the shrinkage weight. Needs two realisations or more.
Eigen::MatrixXd shrunk_covariance(const std::vector<Eigen::VectorXd>& realisations, double& lambda);

// Sigma from the measurement's standard uncertainties (and correlation; empty: independent)
// and the model's realisations at one point (R >= 4 for the small-sample correction; fewer:
// c = 1 and the caller should warn); `lab_samples` n_i per feature (empty: one each).
NoiseModel make_noise_model(const Eigen::VectorXd& measurement_sd, const Eigen::MatrixXd& measurement_correlation,
                            const std::vector<Eigen::VectorXd>& realisations,
                            const Eigen::VectorXd& lab_samples = Eigen::VectorXd());

Eigen::VectorXd mean_of(const std::vector<Eigen::VectorXd>& realisations);

}  // namespace colza::diagnose
