// The solver on the response surfaces: the parameters where the fitted surfaces give the
// measured targets, inside a box, and the check that every target can be reached there.
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "calibration/calibrate.hpp"
#include "calibration/response_surface.hpp"

namespace colza::calibration {

// Solves surfaces(x) = targets (weighted least squares, projected Levenberg-Marquardt with
// several starts) inside [lower, upper]. Throws CalibrationError if some target cannot be
// reached within its uncertainty inside the bounds.
Eigen::VectorXd solve_on_surfaces(const std::vector<ResponseSurface>& surfaces, const Problem& problem,
                                  const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                  const std::vector<Eigen::VectorXd>& starts, bool require_reach);

}  // namespace colza::calibration
