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
  const Eigen::VectorXd d = a.completeOrthogonalDecomposition().solve(b);
  double sum = 0.0;
  for (Eigen::Index i = 0; i < f; ++i)
    if (held[static_cast<std::size_t>(i)]) {
      const double e = (m[i] - y0[i] - A.row(i).dot(d)) / sd[i];
      sum += e * e;
    }
  return std::sqrt(sum / static_cast<double>(out));
}

}  // namespace colza::diagnose
