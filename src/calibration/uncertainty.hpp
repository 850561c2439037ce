// The solution's parameter uncertainty, propagated to first order from the measurement, the
// surfaces' residual error and the realisation scatter (the equations: "Parameter
// uncertainty" in calibrate.hpp), and the warnings on parameters the targets do not determine.
#pragma once
#include <Eigen/Dense>
#include <vector>

#include "calibration/calibrate.hpp"
#include "calibration/response_surface.hpp"

namespace colza::calibration {

// The part of the realisation scatter s that the design's surfaces do not show in their
// residual sigma_s: max(0, s^2 - sigma_s^2), per target. Design runs that each settle their
// own packing are independent draws, their residual already holds the scatter (nothing is
// added); design runs that share one packing or sample carry one common offset of std ~s,
// invisible in the residual, which then moves the solution as a whole.
Eigen::VectorXd unseen_scatter_variance(const Eigen::VectorXd& scatter, const std::vector<ResponseSurface>& s);

// Fills the solution's Jacobian, predicted targets and parameter uncertainties: measurement
// (sigma_t), surface residual (sigma_s) and, when measured, the realisation scatter the
// surfaces do not show (unseen_scatter_variance). G is the linearisation of the solver's
// estimator, whose weights are the inverse measurement covariance S_t^-1 (1 / sigma_t^2
// for independent targets).
void propagate_uncertainty(const Problem& p, const std::vector<ResponseSurface>& s, CalibrationResult& r);

// A parameter whose 95 % interval (x - 2 sigma .. x + 2 sigma, 4 sigma wide; sigma from
// propagate_uncertainty) is wider than its whole design range is not determined by the
// targets: values across the whole range reproduce them within their uncertainty and the
// surfaces' error, so the solution's value of it is arbitrary. One whose interval is wider
// than half the range is weakly determined. Says so, with how much each target's surface
// changes across the range (|J_ij| times the range, in the target's unit and in units of
// its uncertainty). Infinite sigma has its own warning (propagate_uncertainty). A parameter
// whose solution lies on a bound (the solver keeps to the bounds) is said to be there.
void determination_warnings(const Problem& p, CalibrationResult& r);

}  // namespace colza::calibration
