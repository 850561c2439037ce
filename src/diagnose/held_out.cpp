#include "diagnose/held_out.hpp"

#include <cmath>
#include <limits>

namespace colza::diagnose {

double held_out_rms(const Eigen::VectorXd& m, const Eigen::VectorXd& y0, const Eigen::VectorXd& sd,
                    const Eigen::MatrixXd& A, const std::vector<bool>& held) {
  const Eigen::Index f = m.size(), k = A.cols();
  Eigen::Index kept = 0, out = 0;
  for (Eigen::Index i = 0; i < f; ++i) (held[static_cast<std::size_t>(i)] ? out : kept)++;
  if (out == 0 || kept < k) return std::numeric_limits<double>::quiet_NaN();
  Eigen::MatrixXd a(kept, k);
  Eigen::VectorXd b(kept);
  for (Eigen::Index i = 0, r = 0; i < f; ++i)
    if (!held[static_cast<std::size_t>(i)]) {
      a.row(r) = A.row(i) / sd[i];
      b[r++] = (m[i] - y0[i]) / sd[i];
    }
  // a = U S V^T: d = V S^-1 U^T b and C = V S^-2 V^T over the singular values the kept
  // features determine; a held-out feature that moves along a direction they do not determine
  // at all (a zero singular value) cannot be predicted (NaN).
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  const double floor = 1e-12 * (s.size() > 0 ? s[0] : 0.0);
  Eigen::VectorXd d = Eigen::VectorXd::Zero(k);
  Eigen::MatrixXd shift_covariance = Eigen::MatrixXd::Zero(k, k);
  std::vector<Eigen::Index> undetermined;
  for (Eigen::Index j = 0; j < s.size(); ++j) {
    if (s[j] <= floor) {
      undetermined.push_back(j);
      continue;
    }
    d += svd.matrixV().col(j) * (svd.matrixU().col(j).dot(b) / s[j]);
    shift_covariance += svd.matrixV().col(j) * svd.matrixV().col(j).transpose() / (s[j] * s[j]);
  }
  double sum = 0.0;
  for (Eigen::Index i = 0; i < f; ++i)
    if (held[static_cast<std::size_t>(i)]) {
      const Eigen::RowVectorXd g = A.row(i) / sd[i];
      for (Eigen::Index j : undetermined)
        if (std::abs(g.dot(svd.matrixV().col(j))) > 1e-9 * g.norm()) return std::numeric_limits<double>::quiet_NaN();
      const double prediction_variance = g * shift_covariance * g.transpose();
      const double e = (m[i] - y0[i] - A.row(i).dot(d)) / sd[i] / std::sqrt(1.0 + prediction_variance);
      sum += e * e;
    }
  return std::sqrt(sum / static_cast<double>(out));
}

}  // namespace colza::diagnose
