// Held-out check (colza diagnose, step 3): calibrate without one test, predict it. Linearised
// about each model's fit: features(theta) ~ y0 + A (theta - theta0), A the sensitivities
// measured at the fit by common random numbers (the baseline's J; the extended model's
// [J, g_k]); the parameter shift d fitted by least squares to the other tests' features in
// noise units (diagonal: each feature's sd), the held-out features predicted as y0 + A d.
// Each error is standardised by the prediction's own sd, sd_i sqrt(1 + g_i C g_i^T) with
// g_i = A_i / sd_i and C = (a^T a)^+ the whitened shift's covariance from the kept features
// (a their whitened sensitivities): a parameter the other tests hardly determine (the
// unloading stiffness ratio without the load-unload test) makes the prediction uncertain, not
// wrong. The errors are summarised as a root mean square in those units. A model that only
// fits because it has a parameter for every feature predicts what it did not see badly; a
// model with the right mechanism predicts it as well as it fits it.
#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace colza::diagnose {

// RMS of the held-out features' standardised errors; NaN when the other features do not
// determine d (fewer than the columns of A) or leave a direction of it that a held-out
// feature moves along wholly undetermined.
double held_out_rms(const Eigen::VectorXd& measured, const Eigen::VectorXd& fitted, const Eigen::VectorXd& sd,
                    const Eigen::MatrixXd& sensitivity, const std::vector<bool>& held_out);

}  // namespace colza::diagnose
