// A candidate mechanism's signature (colza diagnose, step 2): how every feature moves per
// unit of the mechanism's parameter from its neutral value (the value at which the extended
// model is the baseline: mu_r = 0, zeta = 0, k2 / k1 = 1, a_n = a_s = 0), by finite
// differences on the same packings (common random numbers: realisation s of both runs has
// the same seed, so the chaos between packings cancels in the difference):
//     g = (1/n) sum_s (y_s(probe) - y_s(neutral)) / (probe - neutral),
// with the standard error of that mean from the scatter of the n per-seed differences.
// The baseline's own sensitivities (d features / d parameter_j at the fit) are made the
// same way, with a step per parameter.
#pragma once
#include <Eigen/Dense>
#include <vector>

namespace colza::diagnose {

struct Signature {
  Eigen::VectorXd mean;            // d feature / d parameter (feature units per parameter unit)
  Eigen::VectorXd standard_error;  // of the mean; 0 with one seed
  int seeds = 0;
};

// at_neutral[s], at_probe[s]: the features of realisation s at each value; step = probe - neutral.
Signature signature_from_pairs(const std::vector<Eigen::VectorXd>& at_neutral,
                               const std::vector<Eigen::VectorXd>& at_probe, double step);

}  // namespace colza::diagnose
