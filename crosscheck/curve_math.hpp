// The arithmetic of comparing curves: linear interpolation, the rms difference of two
// curves over a range, the largest difference over their first rows, and the Mohr-Coulomb
// line through (normal stress, shear strength) and the least-squares weights behind it.
#pragma once
#include <cstddef>
#include <utility>
#include <vector>

namespace crosscheck {

// ys at x by linear interpolation in increasing xs; NaN outside [xs.front(), xs.back()].
double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x);

// Curve c (cx, cy) against curve y (yx, yy), at c's points with lo <= cx <= hi where y is
// defined (y interpolated there; a NaN bound or abscissa takes no point): n points, each
// curve's rms value there, and relative = sqrt(sum (cy - y)^2 / sum cy^2) (NaN without
// points).
struct RmsDifference {
  std::size_t n = 0;
  double rms_colza = 0.0, rms_yade = 0.0, relative = 0.0;
};
RmsDifference rms_difference(const std::vector<double>& cx, const std::vector<double>& cy,
                             const std::vector<double>& yx, const std::vector<double>& yy, double lo, double hi);

// Over the first `rows` rows of curves c and y, sampled at the same points: max |c|,
// max |y| and relative = max |c - y| / max |c| (0 when c is all zero).
struct MaxDifference {
  double max_colza = 0.0, max_yade = 0.0, relative = 0.0;
};
MaxDifference max_difference(const std::vector<double>& c, const std::vector<double>& y, std::size_t rows);

// Weights of the least-squares line y = a + b x through points (x_k, y_k): a = sum_k
// intercept[k] y_k and b = sum_k slope[k] y_k, with slope[k] = (x_k - mean x) / Sxx and
// intercept[k] = 1/n - mean x slope[k]. Needs two distinct x.
struct LineWeights {
  std::vector<double> intercept, slope;
};
LineWeights line_weights(const std::vector<double>& x);

// Least-squares line tau = C + sigma tan(Phi) (line_weights); returns (C in the unit of tau,
// Phi in degrees).
std::pair<double, double> mohr_coulomb(const std::vector<double>& sigma, const std::vector<double>& tau);

}  // namespace crosscheck
