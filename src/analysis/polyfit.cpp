#include "analysis/polyfit.hpp"

#include <Eigen/Dense>
#include <stdexcept>

namespace colza {

PolynomialFit fit_polynomial(const std::vector<double>& x, const std::vector<double>& y, int degree) {
  const std::size_t n = x.size();
  const int m = degree + 1;
  if (n != y.size()) throw std::invalid_argument("fit_polynomial: x and y differ in length");
  if (static_cast<int>(n) <= m) throw std::invalid_argument("fit_polynomial: too few points for the degree");
  // Scale x to O(1) for conditioning, then undo the scaling on the coefficients.
  double scale = 0.0;
  for (double v : x) scale = std::max(scale, std::abs(v));
  if (scale == 0.0) scale = 1.0;
  Eigen::MatrixXd a(n, m);
  Eigen::VectorXd b(n);
  for (std::size_t i = 0; i < n; ++i) {
    double p = 1.0;
    for (int k = 0; k < m; ++k, p *= x[i] / scale) a(i, k) = p;
    b(i) = y[i];
  }
  const Eigen::VectorXd c = a.colPivHouseholderQr().solve(b);
  PolynomialFit fit;
  fit.points = n;
  fit.coefficients.resize(m);
  double s = 1.0;
  for (int k = 0; k < m; ++k, s *= scale) fit.coefficients[k] = c(k) / s;
  const double mean = b.mean();
  const double ss_tot = (b.array() - mean).square().sum();
  const double ss_res = (a * c - b).squaredNorm();
  fit.r2 = ss_tot > 0.0 ? 1.0 - ss_res / ss_tot : 1.0;
  return fit;
}

CompressionFit fit_compression_curve(const std::vector<double>& s, const std::vector<double>& f,
                                     double force_min, double force_max) {
  CompressionFit out;
  std::size_t first = s.size();
  for (std::size_t i = 0; i < s.size(); ++i)
    if (f[i] >= force_min) { first = i; break; }
  if (first == s.size()) return out;
  // Interpolate the displacement where F crosses force_min.
  out.zero_displacement = s[first];
  if (first > 0 && f[first] > f[first - 1])
    out.zero_displacement = s[first - 1] + (force_min - f[first - 1]) / (f[first] - f[first - 1]) * (s[first] - s[first - 1]);
  std::vector<double> xs, ys;
  for (std::size_t i = first; i < s.size(); ++i) {
    if (f[i] > force_max) { out.reached_force_max = true; break; }
    if (f[i] >= force_min) {
      xs.push_back(s[i] - out.zero_displacement);
      ys.push_back(f[i]);
    }
  }
  if (xs.size() < 4) return out;
  out.fit = fit_polynomial(xs, ys, 2);
  out.valid = true;
  return out;
}

}  // namespace colza
