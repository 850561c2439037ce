#include "analysis/mohr_coulomb.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/types.hpp"

namespace colza {

MohrCoulombFit fit_mohr_coulomb(const std::vector<double>& sigma, const std::vector<double>& tau) {
  const std::size_t n = sigma.size();
  if (n != tau.size()) throw std::invalid_argument("fit_mohr_coulomb: sizes differ");
  if (n < 2) throw std::invalid_argument("fit_mohr_coulomb: needs at least two loads");
  double ms = 0.0, mt = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    ms += sigma[i];
    mt += tau[i];
  }
  ms /= n;
  mt /= n;
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (sigma[i] - ms) * (sigma[i] - ms);
    sxy += (sigma[i] - ms) * (tau[i] - mt);
    syy += (tau[i] - mt) * (tau[i] - mt);
  }
  if (sxx == 0.0) throw std::invalid_argument("fit_mohr_coulomb: needs at least two distinct normal stresses");
  MohrCoulombFit f;
  f.slope = sxy / sxx;
  f.cohesion = mt - f.slope * ms;
  f.friction_angle_deg = std::atan(f.slope) * 180.0 / kPi;
  // r^2 = sxy^2 / (sxx syy) <= 1 (Cauchy-Schwarz); rounding can put it a hair above 1 (two loads).
  f.r2 = syy > 0.0 ? std::min(1.0, sxy * sxy / (sxx * syy)) : 1.0;
  f.degrees_of_freedom = static_cast<int>(n) - 2;
  if (f.degrees_of_freedom == 0) {
    f.cohesion_se = f.slope_se = f.friction_angle_se_deg = std::numeric_limits<double>::quiet_NaN();
    return f;
  }
  double sse = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = tau[i] - (f.cohesion + f.slope * sigma[i]);
    sse += r * r;
  }
  const double s = std::sqrt(sse / f.degrees_of_freedom);
  f.slope_se = s / std::sqrt(sxx);
  f.cohesion_se = s * std::sqrt(1.0 / static_cast<double>(n) + ms * ms / sxx);
  f.friction_angle_se_deg = f.slope_se / (1.0 + f.slope * f.slope) * 180.0 / kPi;
  return f;
}

std::string cohesion_note(const MohrCoulombFit& fit) {
  if (fit.degrees_of_freedom < 1 || !(std::abs(fit.cohesion) < 2.0 * fit.cohesion_se)) return "";
  std::string note = "C is within two standard errors of zero: these loads do not tell it from no cohesion";
  if (fit.cohesion < 0.0) note += " (a negative C is where the line through the loads meets the stress axis, not a strength)";
  return note;
}

}  // namespace colza
