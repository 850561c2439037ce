#include "calibration/uncertainty.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "calibration/calibration_common.hpp"
#include "calibration/sensitivity.hpp"

namespace colza::calibration {

namespace {

// Which parameter (or combination) the targets do not determine: the direction of least
// response, the right singular vector of the smallest singular value of the Jacobian scaled
// to targets in their uncertainties and parameters over their ranges, J_ij (upper_j -
// lower_j) / sigma_t,i. Its parameters with a weight of at least a third of the largest.
std::string undetermined_direction(const Problem& p, const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& sig_t) {
  const Eigen::Index n = static_cast<Eigen::Index>(p.parameters.size());
  Eigen::VectorXd range(n);
  for (Eigen::Index j = 0; j < n; ++j) range[j] = p.parameters[j].upper - p.parameters[j].lower;
  const Eigen::MatrixXd scaled = sig_t.cwiseInverse().asDiagonal() * jacobian * range.asDiagonal();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(scaled, Eigen::ComputeFullV);
  const Eigen::VectorXd v = svd.matrixV().col(n - 1).cwiseAbs();  // singular values are sorted, largest first
  std::vector<std::string> names;
  for (Eigen::Index j = 0; j < n; ++j)
    if (v[j] >= v.maxCoeff() / 3.0) names.push_back(p.parameters[j].name);
  if (names.size() == 1) return names[0];
  std::string list;
  for (std::size_t k = 0; k < names.size(); ++k)
    list += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
  return "a combination of " + list;
}

}  // namespace

Eigen::VectorXd unseen_scatter_variance(const Eigen::VectorXd& scatter, const std::vector<ResponseSurface>& s) {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(scatter.size());
  for (Eigen::Index i = 0; i < scatter.size(); ++i)
    v[i] = std::max(0.0, scatter[i] * scatter[i] - std::pow(s[static_cast<std::size_t>(i)].residual_std(), 2));
  return v;
}

void propagate_uncertainty(const Problem& p, const std::vector<ResponseSurface>& s, CalibrationResult& r) {
  const Eigen::Index n = static_cast<Eigen::Index>(p.parameters.size());
  r.jacobian = surfaces_jacobian(s, r.solution);
  r.predicted = evaluate_surfaces(s, r.solution);
  const Eigen::VectorXd sig_t = target_sigmas(p);
  Eigen::VectorXd sig_s(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) sig_s[i] = s[i].residual_std();
  const bool scatter = r.scatter.size() == sig_t.size();
  const Eigen::VectorXd sig_r =
      scatter ? Eigen::VectorXd(unseen_scatter_variance(r.scatter, s).cwiseSqrt()) : Eigen::VectorXd::Zero(sig_t.size());
  const Eigen::MatrixXd cov_targets = covariance_of(sig_t, p.target_correlation);
  const Eigen::VectorXd inv_sig = sig_t.array().inverse();
  const Eigen::MatrixXd W = p.target_correlation.size() == 0  // the solver's weights, S_t^-1 = D^-1 R^-1 D^-1
                                ? Eigen::MatrixXd(sig_t.array().square().inverse().matrix().asDiagonal())
                                : Eigen::MatrixXd(inv_sig.asDiagonal() * p.target_correlation.inverse() *
                                                  inv_sig.asDiagonal());
  const Eigen::MatrixXd JtW = r.jacobian.transpose() * W;
  const Eigen::MatrixXd normal = JtW * r.jacobian;
  Eigen::MatrixXd G;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(normal);
  if (lu.rank() < n) {
    r.warnings.push_back("the fitted surfaces are (nearly) flat in " + undetermined_direction(p, r.jacobian, sig_t) +
                         " at the solution: the targets do not determine it; the uncertainties are reported as "
                         "infinite");
    const double inf = std::numeric_limits<double>::infinity();
    r.sigma_target = r.sigma_surface = r.sigma_scatter = r.sigma = Eigen::VectorXd::Constant(n, inf);
    return;
  }
  G = lu.solve(JtW);  // dx = G dy (= J^-1 for a square system)
  auto through_G = [&](const Eigen::MatrixXd& cov_y) { return Eigen::MatrixXd(G * cov_y * G.transpose()); };
  const Eigen::MatrixXd cov_t = through_G(cov_targets);
  const Eigen::MatrixXd cov_s = through_G(covariance_of(sig_s, {}));
  const Eigen::MatrixXd cov_r = through_G(covariance_of(sig_r, {}));
  r.sigma_target = cov_t.diagonal().cwiseSqrt();
  r.sigma_surface = cov_s.diagonal().cwiseSqrt();
  r.sigma_scatter = cov_r.diagonal().cwiseSqrt();
  r.sigma = (cov_t + cov_s + cov_r).diagonal().cwiseSqrt();
}

void determination_warnings(const Problem& p, CalibrationResult& r) {
  for (std::size_t j = 0; j < p.parameters.size(); ++j) {
    const Parameter& q = p.parameters[j];
    // On a bound: the solver keeps to [lower, upper], so the surfaces' best point lies there
    // or beyond (found in session 27's walk-through: Cs = 3 N exactly, its upper bound, where
    // the planes' own solution was Cs = 3.55, Cn = -0.35, and nothing said so).
    const double range = q.upper - q.lower, sigma = r.sigma[static_cast<Eigen::Index>(j)];
    const double xj = r.solution[static_cast<Eigen::Index>(j)];
    const double tolerance = 1e-9 * range;
    const bool on_lower = std::abs(xj - q.lower) <= tolerance, on_upper = std::abs(xj - q.upper) <= tolerance;
    if (on_lower || on_upper) {
      r.warnings.push_back(q.name + " = " + fmt(xj) + unit_suffix(q.unit) + " lies on its " + (on_lower ? "lower" : "upper") +
                           " bound: the solution is held inside [" + fmt(q.lower) + ", " + fmt(q.upper) +
                           "], and the targets may be met better beyond it, so the value is the bound's, not a "
                           "measurement. Move the design (and the bound) past it, or check the measured data");
    }
    const double interval = 4.0 * sigma;
    if (!std::isfinite(sigma) || interval <= 0.5 * range) continue;
    std::string effects;
    for (std::size_t i = 0; i < p.targets.size(); ++i) {
      const double change = std::abs(r.jacobian(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j))) * range;
      effects += (i ? ", " : "") + p.targets[i].name + " by " + fmt(change) + " " + p.targets[i].unit + " (" +
                 fmt(change / p.targets[i].uncertainty) + " uncertainties)";
    }
    const bool arbitrary = interval > range;
    r.warnings.push_back(q.name + (arbitrary ? " is not determined" : " is only weakly determined") +
                         " by these targets: its 95 % interval, +/- 2 sigma = +/- " + fmt(2.0 * sigma) + unit_suffix(q.unit) +
                         " (" + fmt(interval) + unit_suffix(q.unit) + " wide), is wider than " +
                         (arbitrary ? "its" : "half its") + " design range " + fmt(q.lower) + " .. " + fmt(q.upper) +
                         unit_suffix(q.unit) + " (across it the surfaces change " + effects + "); " +
                         (arbitrary ? "its value in the solution is arbitrary" : "its value in the solution is rough") +
                         ": fix it from other data, or add a target that depends on it");
  }
}

}  // namespace colza::calibration
