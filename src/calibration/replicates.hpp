// Realisations of a forward model: the same point run with other seeds (realisation k:
// seed + k) and the scatter between them (the realisation scatter, calibrate.hpp).
#pragma once
#include <Eigen/Dense>
#include <functional>
#include <vector>

namespace colza::calibration {

// The forward model: parameters (SI) -> targets or features (SI). Must be callable from
// several threads at once (the DEM model is; the identity model is pure).
using ForwardModel = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;
// The same model in realisation k >= 1 (the DEM: seed + k); realisation 0 is ForwardModel.
using ReplicateModel = std::function<Eigen::VectorXd(const Eigen::VectorXd&, int)>;

// Per-component sample standard deviation of realisations y_k (k = 1..n):
// s_i = sqrt(sum_k (y_k,i - mean_i)^2 / (n - 1)); zeros for one realisation, empty for none.
Eigen::VectorXd realisation_scatter(const std::vector<Eigen::VectorXd>& realisations);

struct BatchWithReplicates {
  std::vector<Eigen::VectorXd> points;      // model(points[k]), realisation 0
  std::vector<Eigen::VectorXd> replicates;  // replicate_model(x_replicated, k + 1)
};

// `points` (realisation 0) and realisations 1..`replicates` of `x_replicated`, all in one
// batch of up to `jobs` at once (core/concurrent.hpp); results in input order.
// `replicate_model` is called only when replicates > 0.
BatchWithReplicates evaluate_with_replicates(const ForwardModel& model, const ReplicateModel& replicate_model,
                                             const std::vector<Eigen::VectorXd>& points,
                                             const Eigen::VectorXd& x_replicated, int replicates, int jobs);

}  // namespace colza::calibration
