#include "analysis/curve_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace colza {

double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  // Written as "not inside" so that a NaN x is outside too (x < front and x > back are both
  // false for it, and lower_bound would then give ys[0]).
  if (xs.empty() || !(x >= xs.front() && x <= xs.back())) return std::numeric_limits<double>::quiet_NaN();
  const auto it = std::lower_bound(xs.begin(), xs.end(), x);
  const std::size_t i = static_cast<std::size_t>(it - xs.begin());
  if (i == 0) return ys[0];
  const double t = (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
  return ys[i - 1] + t * (ys[i] - ys[i - 1]);
}

double max_magnitude(double so_far, double value) {
  if (std::isnan(so_far) || !std::isfinite(value)) return std::numeric_limits<double>::quiet_NaN();
  return std::max(so_far, std::abs(value));
}

double relative_difference(double num, double den) {
  if (!std::isfinite(num) || !std::isfinite(den)) return std::numeric_limits<double>::infinity();
  if (den > 0.0) return num / den;
  return num == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
}

RmsDifference rms_difference(const std::vector<double>& cx, const std::vector<double>& cy,
                             const std::vector<double>& yx, const std::vector<double>& yy, double lo, double hi) {
  double sq_diff = 0.0, sq = 0.0, sq_y = 0.0;
  std::size_t n = 0;
  bool all_finite = true;
  for (std::size_t r = 0; r < cx.size(); ++r) {
    if (!(cx[r] >= lo) || cx[r] > hi) continue;
    if (yx.empty() || !(cx[r] >= yx.front() && cx[r] <= yx.back())) continue;  // y is not defined there
    const double fy = interpolate(yx, yy, cx[r]);
    if (!std::isfinite(fy) || !std::isfinite(cy[r])) all_finite = false;
    sq_diff += (cy[r] - fy) * (cy[r] - fy);
    sq += cy[r] * cy[r];
    sq_y += fy * fy;
    ++n;
  }
  RmsDifference d;
  d.n = n;
  d.rms_colza = std::sqrt(sq / std::max<std::size_t>(n, 1));
  d.rms_yade = std::sqrt(sq_y / std::max<std::size_t>(n, 1));
  if (!all_finite) d.relative = std::numeric_limits<double>::infinity();
  else d.relative = (n > 0 && sq > 0) ? std::sqrt(sq_diff / sq) : std::numeric_limits<double>::quiet_NaN();
  return d;
}

MaxDifference max_difference(const std::vector<double>& c, const std::vector<double>& y, std::size_t rows) {
  double num = 0.0, den = 0.0, max_y = 0.0;
  for (std::size_t r = 0; r < rows; ++r) {
    num = max_magnitude(num, c[r] - y[r]);
    den = max_magnitude(den, c[r]);
    max_y = max_magnitude(max_y, y[r]);
  }
  return {den, max_y, relative_difference(num, den)};
}

LineWeights line_weights(const std::vector<double>& x) {
  const double n = static_cast<double>(x.size());
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= n;
  double sxx = 0.0;
  for (double v : x) sxx += (v - mean) * (v - mean);
  LineWeights w;
  for (double v : x) {
    w.slope.push_back((v - mean) / sxx);
    w.intercept.push_back(1.0 / n - mean * w.slope.back());
  }
  return w;
}

std::pair<double, double> mohr_coulomb(const std::vector<double>& sigma, const std::vector<double>& tau) {
  const LineWeights w = line_weights(sigma);
  double cohesion = 0.0, slope = 0.0;
  for (std::size_t k = 0; k < sigma.size(); ++k) {
    cohesion += w.intercept[k] * tau[k];
    slope += w.slope[k] * tau[k];
  }
  return {cohesion, std::atan(slope) * 180.0 / std::numbers::pi};
}

}  // namespace colza
