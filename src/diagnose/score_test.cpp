#include "diagnose/score_test.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>

#include "diagnose/adequacy.hpp"

namespace colza::diagnose {

namespace {

// Standard normal numbers from splitmix64 by Box-Muller: the same sequence on every platform.
class NormalStream {
 public:
  explicit NormalStream(std::uint64_t seed) : state_(seed) {}
  double next() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = uniform(), u2 = uniform();
    const double r = std::sqrt(-2.0 * std::log(u1)), a = 6.283185307179586 * u2;
    spare_ = r * std::sin(a);
    has_spare_ = true;
    return r * std::cos(a);
  }

 private:
  double uniform() {  // in (0, 1)
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return (static_cast<double>(z >> 11) + 0.5) / 9007199254740992.0;
  }
  std::uint64_t state_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace

std::vector<double> max_t_adjusted(const std::vector<double>& z, const Eigen::MatrixXd& c, int draws) {
  const std::size_t k = z.size();
  if (k == 0) return {};
  // C^(1/2) from the eigen decomposition (C may be singular: two candidates along one direction).
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(c);
  const Eigen::MatrixXd root =
      eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal() * eig.eigenvectors().transpose();
  NormalStream normal(0x636f6c7a61ULL);
  std::vector<long> reached(k, 0);
  Eigen::VectorXd u(static_cast<Eigen::Index>(k));
  for (int d = 0; d < draws; ++d) {
    for (Eigen::Index i = 0; i < u.size(); ++i) u[i] = normal.next();
    const double largest = (root * u).maxCoeff();
    for (std::size_t i = 0; i < k; ++i)
      if (largest >= z[i]) ++reached[i];
  }
  std::vector<double> p(k);
  for (std::size_t i = 0; i < k; ++i) p[i] = static_cast<double>(reached[i]) / draws;
  return p;
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
  t.cosine = Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k));
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < k; ++j) {
      const double d = perp[i].norm() * perp[j].norm();
      t.cosine(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = d > 0.0 ? perp[i].dot(perp[j]) / d : 0.0;
    }
  std::vector<double> z(k);
  for (std::size_t i = 0; i < k; ++i) z[i] = t.scores[i].z;
  const std::vector<double> adjusted = max_t_adjusted(z, t.cosine);
  for (std::size_t i = 0; i < k; ++i) t.scores[i].adjusted_p = std::max(adjusted[i], t.scores[i].p_value);
  return t;
}

}  // namespace colza::diagnose
