#include "diagnose/noise_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace colza::diagnose {

Eigen::VectorXd mean_of(const std::vector<Eigen::VectorXd>& ys) {
  if (ys.empty()) throw std::invalid_argument("mean_of: no realisations");
  Eigen::VectorXd m = Eigen::VectorXd::Zero(ys[0].size());
  for (const auto& y : ys) m += y;
  return m / static_cast<double>(ys.size());
}

Eigen::MatrixXd shrunk_covariance(const std::vector<Eigen::VectorXd>& ys, double& lambda) {
  const std::size_t n = ys.size();
  if (n < 2) throw std::invalid_argument("shrunk_covariance: needs two realisations or more");
  const Eigen::Index f = ys[0].size();
  const Eigen::VectorXd mean = mean_of(ys);
  Eigen::MatrixXd centred(static_cast<Eigen::Index>(n), f);
  for (std::size_t k = 0; k < n; ++k) centred.row(static_cast<Eigen::Index>(k)) = (ys[k] - mean).transpose();
  const double dn = static_cast<double>(n);
  const Eigen::MatrixXd cov = centred.transpose() * centred / (dn - 1.0);
  const Eigen::VectorXd sd = cov.diagonal().cwiseSqrt();
  // Standardised columns w_k = x_k / s; r_ij = sum_k w_ki w_kj / (n - 1);
  // Var(r_ij) = n / (n - 1)^3 sum_k (w_ki w_kj - wbar_ij)^2 (Schafer & Strimmer, appendix A).
  Eigen::MatrixXd w = centred;
  for (Eigen::Index j = 0; j < f; ++j) w.col(j) = sd[j] > 0.0 ? Eigen::VectorXd(centred.col(j) / sd[j]) : Eigen::VectorXd::Zero(centred.rows());
  double sum_var = 0.0, sum_r2 = 0.0;
  for (Eigen::Index i = 0; i < f; ++i)
    for (Eigen::Index j = 0; j < f; ++j) {
      if (i == j) continue;
      const Eigen::ArrayXd prod = w.col(i).array() * w.col(j).array();
      const double wbar = prod.mean();
      const double r = prod.sum() / (dn - 1.0);
      sum_var += dn / std::pow(dn - 1.0, 3) * (prod - wbar).square().sum();
      sum_r2 += r * r;
    }
  lambda = sum_r2 > 0.0 ? std::clamp(sum_var / sum_r2, 0.0, 1.0) : 1.0;
  Eigen::MatrixXd shrunk = cov * (1.0 - lambda);
  shrunk.diagonal() = cov.diagonal();
  return shrunk;
}

NoiseModel make_noise_model(const Eigen::VectorXd& u, const Eigen::MatrixXd& correlation,
                            const std::vector<Eigen::VectorXd>& ys, const Eigen::VectorXd& lab_samples) {
  const Eigen::Index f = u.size();
  NoiseModel m;
  Eigen::MatrixXd U = correlation.size() == 0 ? Eigen::MatrixXd(u.array().square().matrix().asDiagonal())
                                              : Eigen::MatrixXd(u.asDiagonal() * correlation * u.asDiagonal());
  m.realisations = static_cast<int>(ys.size());
  m.scatter_sd = Eigen::VectorXd::Zero(f);
  m.covariance = U;
  if (ys.size() >= 2) {
    const Eigen::MatrixXd S = shrunk_covariance(ys, m.shrinkage);
    const double n = static_cast<double>(ys.size());
    const double small_sample = n > 3.0 ? (n - 1.0) / (n - 3.0) : 1.0;
    const Eigen::VectorXd n_lab = lab_samples.size() == f ? lab_samples : Eigen::VectorXd::Ones(f);
    const Eigen::VectorXd D = (n_lab.cwiseInverse().array() + 1.0 / n).sqrt().matrix();
    m.covariance += small_sample * (D.asDiagonal() * S * D.asDiagonal());
    m.scatter_sd = S.diagonal().cwiseSqrt();
  }
  m.sd = m.covariance.diagonal().cwiseSqrt();
  const Eigen::LLT<Eigen::MatrixXd> llt(m.covariance);
  if (llt.info() != Eigen::Success)
    throw std::runtime_error("the features' noise covariance is not positive definite: a feature with zero "
                             "uncertainty and no scatter, or two features that are the same");
  const Eigen::MatrixXd L = llt.matrixL();
  m.whitener = L.triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(f, f));
  return m;
}

}  // namespace colza::diagnose
