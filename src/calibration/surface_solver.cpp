#include "calibration/surface_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "calibration/calibration_common.hpp"

namespace colza::calibration {

namespace {

// The solver's starts: the given points and the box's centre.
std::vector<Eigen::VectorXd> with_centre(std::vector<Eigen::VectorXd> starts, const Eigen::VectorXd& lower,
                                         const Eigen::VectorXd& upper) {
  starts.push_back(0.5 * (lower + upper));
  return starts;
}

std::string point_text(const Problem& p, const Eigen::VectorXd& x) {
  std::string s = "(";
  for (std::size_t j = 0; j < p.parameters.size(); ++j) s += (j ? ", " : "") + p.parameters[j].name + " = " + fmt(x[j]);
  return s + ")";
}

// Projected Levenberg-Marquardt on the weighted residuals r_i(u) = (f_i(x(u)) - t_i) / sigma_i
// of the targets `which` (whitened by the Cholesky factor of their covariance when they are
// correlated), u = (x - mid) / half the scaled parameters, clamped to [lower, upper]; the
// best of the given starts.
Eigen::VectorXd least_squares_in_box(const std::vector<ResponseSurface>& s, const std::vector<std::size_t>& which,
                                     const Problem& p, const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                     const std::vector<Eigen::VectorXd>& starts) {
  const ParameterScaling sc = ParameterScaling::from_bounds(p.lower(), p.upper());
  const Eigen::VectorXd t = target_values(p);
  const Eigen::VectorXd ulo = sc.to_unit(lower), uhi = sc.to_unit(upper);
  const Eigen::Index m = static_cast<Eigen::Index>(which.size());
  // Whitened residuals L^-1 (f - t), Sigma_t = L L^T over the targets `which`; with
  // independent targets (the usual case) simply (f_i - t_i) / sigma_i.
  const bool correlated = p.target_correlation.size() != 0;
  const Eigen::VectorXd sig = target_sigmas(p);
  Eigen::MatrixXd cov = Eigen::MatrixXd::Identity(m, m);
  if (correlated) {
    const Eigen::MatrixXd cov_all = covariance_of(sig, p.target_correlation);
    for (Eigen::Index a = 0; a < m; ++a)
      for (Eigen::Index b = 0; b < m; ++b)
        cov(a, b) = cov_all(static_cast<Eigen::Index>(which[a]), static_cast<Eigen::Index>(which[b]));
  }
  const Eigen::LLT<Eigen::MatrixXd> chol(cov);
  if (chol.info() != Eigen::Success)
    throw CalibrationError("targets", "the targets' covariance is not positive definite (their correlation is +/-1)");
  auto residual = [&](const Eigen::VectorXd& u) {
    const Eigen::VectorXd x = sc.from_unit(u);
    Eigen::VectorXd r(m);
    if (!correlated) {
      for (Eigen::Index k = 0; k < m; ++k) r[k] = (s[which[k]].predict(x) - t[which[k]]) / sig[which[k]];
      return r;
    }
    for (Eigen::Index k = 0; k < m; ++k) r[k] = s[which[k]].predict(x) - t[which[k]];
    return Eigen::VectorXd(chol.matrixL().solve(r));
  };
  auto jacobian = [&](const Eigen::VectorXd& u) {  // d r / d u
    const Eigen::VectorXd x = sc.from_unit(u);
    Eigen::MatrixXd J(m, u.size());
    if (!correlated) {
      for (Eigen::Index k = 0; k < m; ++k)
        J.row(k) = (s[which[k]].gradient(x) * (1.0 / sig[which[k]])).cwiseProduct(sc.half).transpose();
      return J;
    }
    for (Eigen::Index k = 0; k < m; ++k) J.row(k) = s[which[k]].gradient(x).cwiseProduct(sc.half).transpose();
    return Eigen::MatrixXd(chol.matrixL().solve(J));
  };
  auto clamp = [&](Eigen::VectorXd u) {
    for (Eigen::Index j = 0; j < u.size(); ++j) u[j] = std::clamp(u[j], ulo[j], uhi[j]);
    return u;
  };
  auto solve_from = [&](Eigen::VectorXd u) {
    u = clamp(u);
    Eigen::VectorXd r = residual(u);
    double cost = r.squaredNorm(), lambda = 1e-3;
    for (int it = 0; it < 200 && cost > 1e-28; ++it) {
      const Eigen::MatrixXd J = jacobian(u);
      const Eigen::MatrixXd JtJ = J.transpose() * J;
      const Eigen::VectorXd g = J.transpose() * r;
      Eigen::MatrixXd A = JtJ;
      A.diagonal().array() += lambda * (JtJ.diagonal().array() + 1e-12);
      const Eigen::VectorXd un = clamp(u - A.ldlt().solve(g));
      const Eigen::VectorXd rn = residual(un);
      const double cn = rn.squaredNorm();
      if (cn < cost) {
        const bool small = (un - u).norm() < 1e-13;
        u = un, r = rn, cost = cn, lambda = std::max(lambda / 3.0, 1e-12);
        if (small) break;
      } else {
        lambda *= 4.0;
        if (lambda > 1e12) break;
      }
    }
    return std::make_pair(cost, u);
  };
  double best_cost = std::numeric_limits<double>::infinity();
  Eigen::VectorXd best_u;
  for (const auto& x0 : starts) {
    const auto [c, u] = solve_from(sc.to_unit(x0));
    if (c < best_cost) best_cost = c, best_u = u;
  }
  return sc.from_unit(best_u);
}

}  // namespace

// Reach is judged ONE TARGET AT A TIME: the joint solution trades the targets off against
// each other (weighted least squares), so when one target is out of reach the compromise can
// also miss a reachable target by more than its uncertainty. Naming the first target missed
// at the compromise named the wrong one (e.g. cohesion when tan(Phi) was out of reach).
// Only if every target is reachable alone is the verdict that they are not reachable together.
ReachVerdict judge_reach(const std::vector<ResponseSurface>& s, const Problem& p, const Eigen::VectorXd& lower,
                         const Eigen::VectorXd& upper, const std::vector<Eigen::VectorXd>& starts,
                         const Eigen::VectorXd& x) {
  const std::vector<Eigen::VectorXd> all = with_centre(starts, lower, upper);
  const Eigen::VectorXd t = target_values(p), sig = target_sigmas(p);
  const Eigen::VectorXd y = evaluate_surfaces(s, x);
  std::vector<std::size_t> missed;
  for (std::size_t i = 0; i < p.targets.size(); ++i)
    if (std::abs(y[i] - t[i]) > sig[i]) missed.push_back(i);
  if (missed.empty()) return {};
  const std::string bounds = "inside the bounds " + point_text(p, lower) + " .. " + point_text(p, upper);
  auto measured_value = [&](std::size_t i) { return fmt(t[i]) + " +/- " + fmt(sig[i]) + unit_suffix(p.targets[i].unit); };
  auto measured = [&](std::size_t i) { return "the measured " + p.targets[i].name + " = " + measured_value(i); };
  std::string unreachable, first;
  for (std::size_t i : missed) {
    const Eigen::VectorXd xi = least_squares_in_box(s, {i}, p, lower, upper, all);
    const double yi = s[i].predict(xi);
    if (std::abs(yi - t[i]) <= sig[i]) continue;
    // Range of the surface over the box corners (exact for a plane).
    const std::size_t n = p.parameters.size();
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t mask = 0; mask < (std::size_t{1} << n); ++mask) {
      Eigen::VectorXd c(n);
      for (std::size_t j = 0; j < n; ++j) c[j] = (mask >> j & 1) ? upper[j] : lower[j];
      const double v = s[i].predict(c);
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
    if (first.empty()) first = p.targets[i].name;
    unreachable += (unreachable.empty() ? "" : "; ") + measured(i) + " is outside what the design can reach: " +
                   bounds + " the surface for " + p.targets[i].name + " gets at best " + fmt(yi) + " (at " +
                   point_text(p, xi) + "; surface range over the box corners " + fmt(lo) + " .. " + fmt(hi) + ")";
  }
  if (!first.empty())
    return {ReachVerdict::kNotAlone, first,
            unreachable + ". Widen or move the design range, or check the measured value"};
  std::string misses;
  for (std::size_t i : missed)
    misses += (misses.empty() ? "" : "; ") + p.targets[i].name + " = " + fmt(y[i]) + " for the measured " + measured_value(i);
  return {ReachVerdict::kNotTogether, p.targets[missed[0]].name,
          "the measured targets cannot all be reached at once: each alone is inside what the design can reach, but " +
              bounds + " the best compromise (at " + point_text(p, x) +
              ", weighted by the inverse covariance of the measured targets) misses " + misses +
              ". Widen or move the design range, or check the measured values and their uncertainties"};
}

Eigen::VectorXd solve_on_surfaces(const std::vector<ResponseSurface>& s, const Problem& p, const Eigen::VectorXd& lower,
                                  const Eigen::VectorXd& upper, const std::vector<Eigen::VectorXd>& starts) {
  std::vector<std::size_t> every(p.targets.size());
  std::iota(every.begin(), every.end(), 0);
  return least_squares_in_box(s, every, p, lower, upper, with_centre(starts, lower, upper));
}

}  // namespace colza::calibration
