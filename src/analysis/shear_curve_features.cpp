#include "analysis/shear_curve_features.hpp"

#include <cmath>
#include <stdexcept>

#include "core/types.hpp"

namespace colza {

ShearCurveFeatures shear_curve_features(const std::vector<double>& d, const std::vector<double>& tau,
                                        const std::vector<double>& h, const ShearCurveSettings& settings) {
  const std::size_t n = d.size();
  if (tau.size() != n || (!h.empty() && h.size() != n))
    throw std::invalid_argument("shear displacement, shear stress and plate height must have the same number of rows");
  ShearCurveFeatures f;
  if (n == 0) return f;
  f.peak = peak_shear_strength(d, tau, settings.peak_width);
  const ShearStrengthMean residual = shear_strength_of_curve(d, tau, settings.window);
  f.residual = residual.value();
  f.residual_samples = residual.samples();
  if (f.peak.samples > 0 && f.residual_samples > 0) {
    f.drop = f.peak.value - f.residual;
    if (f.peak.value != 0.0) f.drop_fraction = f.drop / f.peak.value;
  }

  f.has_plate_height = !h.empty();
  if (f.has_plate_height) {
    f.max_dilation = 0.0;  // row 0
    f.max_dilation_displacement = d[0];
    for (std::size_t k = 1; k < n; ++k)
      if (h[k] - h[0] > f.max_dilation) {
        f.max_dilation = h[k] - h[0];
        f.max_dilation_displacement = d[k];
      }
    if (f.peak.samples > 0) {
      // The peak's interval [d_peak - w, d_peak]: the rows whose mean is the peak strength.
      double mx = 0.0, my = 0.0;
      std::size_t m = 0;
      const double lo = f.peak.displacement - settings.peak_width, hi = f.peak.displacement;
      for (std::size_t k = 0; k < n; ++k)
        if (d[k] >= lo && d[k] <= hi) mx += d[k], my += h[k], ++m;
      f.dilatancy_points = m;
      if (m >= 3) {
        mx /= static_cast<double>(m);
        my /= static_cast<double>(m);
        double sxy = 0.0, sxx = 0.0;
        for (std::size_t k = 0; k < n; ++k)
          if (d[k] >= lo && d[k] <= hi) {
            sxy += (d[k] - mx) * (h[k] - my);
            sxx += (d[k] - mx) * (d[k] - mx);
          }
        if (sxx > 0.0) f.dilatancy_angle_deg = std::atan(sxy / sxx) * 180.0 / kPi;
      }
    }
  }

  if (f.peak.samples > 0) {
    const double target = settings.stiffness_fraction * f.peak.value;
    if (tau[0] >= target) return f;  // the curve starts above f tau_peak: no secant from its start
    for (std::size_t k = 1; k < n; ++k) {
      if (tau[k] < target) continue;
      const double t = (target - tau[k - 1]) / (tau[k] - tau[k - 1]);
      f.stiffness_displacement = d[k - 1] + t * (d[k] - d[k - 1]);
      if (f.stiffness_displacement > d[0]) f.initial_stiffness = (target - tau[0]) / (f.stiffness_displacement - d[0]);
      break;
    }
  }
  return f;
}

}  // namespace colza
