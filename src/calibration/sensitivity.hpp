// How the response surfaces change with the parameters.
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "calibration/response_surface.hpp"

namespace colza::calibration {

// J_ij = d surface_i / d x_j at x (targets x parameters), from each surface's gradient.
Eigen::MatrixXd surfaces_jacobian(const std::vector<ResponseSurface>& surfaces, const Eigen::VectorXd& x);

}  // namespace colza::calibration
