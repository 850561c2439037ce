#include "calibration/replicates.hpp"

#include "core/concurrent.hpp"

namespace colza::calibration {

Eigen::VectorXd realisation_scatter(const std::vector<Eigen::VectorXd>& ys) {
  if (ys.empty()) return {};
  const Eigen::Index m = ys[0].size();
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(m), var = Eigen::VectorXd::Zero(m);
  for (const auto& y : ys) mean += y;
  mean /= static_cast<double>(ys.size());
  if (ys.size() < 2) return var;
  for (const auto& y : ys) var += (y - mean).array().square().matrix();
  return (var / static_cast<double>(ys.size() - 1)).cwiseSqrt();
}

BatchWithReplicates evaluate_with_replicates(const ForwardModel& model, const ReplicateModel& replicate_model,
                                             const std::vector<Eigen::VectorXd>& points,
                                             const Eigen::VectorXd& x_replicated, int replicates, int jobs) {
  const std::size_t n = points.size(), extra = static_cast<std::size_t>(replicates);
  BatchWithReplicates b{std::vector<Eigen::VectorXd>(n), std::vector<Eigen::VectorXd>(extra)};
  run_concurrently(n + extra, jobs, [&](std::size_t k) {
    if (k < n) b.points[k] = model(points[k]);
    else b.replicates[k - n] = replicate_model(x_replicated, static_cast<int>(k - n) + 1);
  });
  return b;
}

}  // namespace colza::calibration
