#include "diagnose/score_test.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "diagnose/adequacy.hpp"

namespace colza::diagnose {

std::vector<double> holm_adjusted(const std::vector<double>& p) {
  const std::size_t k = p.size();
  std::vector<std::size_t> order(k);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
  std::vector<double> adjusted(k);
  double running = 0.0;
  for (std::size_t r = 0; r < k; ++r) {
    running = std::max(running, std::min(1.0, static_cast<double>(k - r) * p[order[r]]));
    adjusted[order[r]] = running;
  }
  return adjusted;
}

Eigen::MatrixXd complement_projector(const Eigen::MatrixXd& g) {
  const Eigen::Index f = g.rows();
  Eigen::MatrixXd P = Eigen::MatrixXd::Identity(f, f);
  if (g.cols() == 0) return P;
  // Orthonormal basis of the column space (rank-revealing: a parameter the features do not
  // see adds no direction).
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(g);
  const Eigen::Index rank = qr.rank();
  const Eigen::MatrixXd q = Eigen::MatrixXd(qr.householderQ()).leftCols(rank);
  return P - q * q.transpose();
}

ScoreTests score_candidates(const NoiseModel& noise, const Eigen::MatrixXd& baseline_sensitivity,
                            const std::vector<Signature>& signatures, const std::vector<double>& ranges,
                            const Eigen::VectorXd& residual) {
  const Eigen::MatrixXd P = complement_projector(noise.whiten(baseline_sensitivity));
  const Eigen::VectorXd e = P * noise.whiten(residual);
  ScoreTests t;
  t.projected_residual = e;
  const std::size_t k = signatures.size();
  std::vector<Eigen::VectorXd> perp(k);
  std::vector<double> p(k);
  t.scores.resize(k);
  for (std::size_t i = 0; i < k; ++i) {
    const Eigen::VectorXd h = noise.whiten(signatures[i].mean);
    perp[i] = P * h;
    CandidateScore& s = t.scores[i];
    const double norm = perp[i].norm();
    s.absorbed_fraction = h.squaredNorm() > 0.0 ? 1.0 - perp[i].squaredNorm() / h.squaredNorm() : 1.0;
    if (norm > 0.0) {
      s.z = perp[i].dot(e) / norm;
      s.estimate = perp[i].dot(e) / (norm * norm);
      s.estimate_sd = 1.0 / norm;
      s.alignment = e.norm() > 0.0 ? perp[i].dot(e) / (norm * e.norm()) : 0.0;
      const double se = (P * noise.whiten(signatures[i].standard_error)).norm();
      s.signal_to_noise = se > 0.0 ? norm / se : std::numeric_limits<double>::infinity();
      s.reach = norm * ranges[i];
    }
    s.p_value = normal_survival(s.z);
    p[i] = s.p_value;
  }
  const std::vector<double> adjusted = holm_adjusted(p);
  for (std::size_t i = 0; i < k; ++i) t.scores[i].adjusted_p = adjusted[i];
  t.cosine = Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k));
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < k; ++j) {
      const double d = perp[i].norm() * perp[j].norm();
      t.cosine(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = d > 0.0 ? perp[i].dot(perp[j]) / d : 0.0;
    }
  return t;
}

}  // namespace colza::diagnose
