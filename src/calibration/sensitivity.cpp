#include "calibration/sensitivity.hpp"

namespace colza::calibration {

Eigen::MatrixXd surfaces_jacobian(const std::vector<ResponseSurface>& s, const Eigen::VectorXd& x) {
  Eigen::MatrixXd J(s.size(), x.size());
  for (std::size_t i = 0; i < s.size(); ++i) J.row(i) = s[i].gradient(x).transpose();
  return J;
}

}  // namespace colza::calibration
