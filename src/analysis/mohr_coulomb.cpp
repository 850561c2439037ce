#include "analysis/mohr_coulomb.hpp"

#include <cmath>
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
  f.r2 = syy > 0.0 ? sxy * sxy / (sxx * syy) : 1.0;
  return f;
}

}  // namespace colza
