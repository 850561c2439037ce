// The arithmetic of comparing curves: linear interpolation, the rms difference of two
// curves over a range, the largest difference over their first rows, and the Mohr-Coulomb
// line through (normal stress, shear strength) and the least-squares weights behind it.
#pragma once
#include <cstddef>
#include <utility>
#include <vector>

namespace colza {

// ys at x by linear interpolation in increasing xs; NaN outside [xs.front(), xs.back()] and
// for a NaN x.
double interpolate(const std::vector<double>& xs, const std::vector<double>& ys, double x);

// The running maximum of |value| (start from 0): NaN from the first value that is not finite
// on, and NaN stays. std::max would skip a NaN (std::max(m, NaN) is m), so a series of NaN
// would pass as a largest difference of 0.
double max_magnitude(double so_far, double value);

// A largest difference over a largest signal, num / den, as the checks judge it: 0 when both
// are 0 (two zero signals agree); +inf when only den is 0 (any difference from a zero signal
// is large) and when num or den is not finite (a NaN or infinite value was compared), so that
// the row fails.
double relative_difference(double num, double den);

// Curve c (cx, cy) against curve y (yx, yy), at c's points with lo <= cx <= hi where y is
// defined (yx.front() <= cx <= yx.back(), y interpolated there; a NaN bound or abscissa takes
// no point): n points, each curve's rms value there, and relative = sqrt(sum (cy - y)^2 / sum
// cy^2) (NaN without points; +inf when a force taken, cy or y, is not finite: a NaN must not
// drop out of the sums as a point where y is not defined).
struct RmsDifference {
  std::size_t n = 0;
  double rms_colza = 0.0, rms_yade = 0.0, relative = 0.0;
};
RmsDifference rms_difference(const std::vector<double>& cx, const std::vector<double>& cy,
                             const std::vector<double>& yx, const std::vector<double>& yy, double lo, double hi);

// Over the first `rows` rows of curves c and y, sampled at the same points: max |c|,
// max |y| (each NaN if one of its values is not finite) and relative = max |c - y| / max |c|
// by relative_difference (0 when both are all zero, +inf when only c is, and +inf when a value
// of either is not finite).
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

}  // namespace colza
