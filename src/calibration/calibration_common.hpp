// Pieces shared by the calibration loop (calibrate.cpp), the solver on the response
// surfaces (surface_solver.cpp) and the uncertainty propagation (uncertainty.cpp): the
// measured targets as vectors, their covariance, the surfaces at a point, and how their
// messages state a number.
#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "calibration/calibrate.hpp"
#include "calibration/response_surface.hpp"
#include "io/format_number.hpp"

namespace colza::calibration {

inline std::string fmt(double v) { return format_significant(v, 6); }

inline Eigen::VectorXd evaluate_surfaces(const std::vector<ResponseSurface>& s, const Eigen::VectorXd& x) {
  Eigen::VectorXd y(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) y[i] = s[i].predict(x);
  return y;
}

// D R D: the covariance of errors with standard deviations sd and correlation R (empty:
// independent, the diagonal).
inline Eigen::MatrixXd covariance_of(const Eigen::VectorXd& sd, const Eigen::MatrixXd& correlation) {
  if (correlation.size() == 0) return Eigen::MatrixXd(sd.array().square().matrix().asDiagonal());
  return sd.asDiagonal() * correlation * sd.asDiagonal();
}

inline Eigen::VectorXd target_values(const Problem& p) {
  Eigen::VectorXd t(p.targets.size());
  for (std::size_t i = 0; i < p.targets.size(); ++i) t[i] = p.targets[i].value;
  return t;
}

inline Eigen::VectorXd target_sigmas(const Problem& p) {
  Eigen::VectorXd t(p.targets.size());
  for (std::size_t i = 0; i < p.targets.size(); ++i) t[i] = p.targets[i].uncertainty;
  return t;
}

}  // namespace colza::calibration
