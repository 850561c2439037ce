// The solver on the response surfaces: the parameters where the fitted surfaces give the
// measured targets, inside a box, and the verdict whether every target can be reached there.
#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "calibration/calibrate.hpp"
#include "calibration/response_surface.hpp"

namespace colza::calibration {

// Solves surfaces(x) = targets (weighted least squares, projected Levenberg-Marquardt with
// several starts and the box's centre) inside [lower, upper].
Eigen::VectorXd solve_on_surfaces(const std::vector<ResponseSurface>& surfaces, const Problem& problem,
                                  const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                  const std::vector<Eigen::VectorXd>& starts);

// Whether the surfaces meet every target within its uncertainty at the solution x of the box
// [lower, upper]; if not, whether some target is out of reach even alone (kNotAlone: `key`
// names the first such target, `text` them all with what their surfaces get at best) or
// only the targets together (kNotTogether: `text` names the misses at the compromise x).
struct ReachVerdict {
  enum Kind { kReached, kNotTogether, kNotAlone };
  Kind kind = kReached;
  std::string key, text;
};
ReachVerdict judge_reach(const std::vector<ResponseSurface>& surfaces, const Problem& problem,
                         const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                         const std::vector<Eigen::VectorXd>& starts, const Eigen::VectorXd& x);

}  // namespace colza::calibration
