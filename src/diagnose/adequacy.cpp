#include "diagnose/adequacy.hpp"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>

namespace colza::diagnose {

double chi_square_survival(double x, int k) {
  if (!(x > 0.0)) return 1.0;
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(k), x));
}

double normal_survival(double z) { return boost::math::cdf(boost::math::complement(boost::math::normal(), z)); }

AdequacyTest test_adequacy(const NoiseModel& noise, const Eigen::VectorXd& residual, int fitted_parameters,
                           double significance) {
  AdequacyTest t;
  const Eigen::VectorXd e = noise.whiten(residual);
  t.chi_square = e.squaredNorm();
  t.degrees_of_freedom = std::max(0, static_cast<int>(residual.size()) - fitted_parameters);
  t.p_value = t.degrees_of_freedom > 0 ? chi_square_survival(t.chi_square, t.degrees_of_freedom) : 1.0;
  t.passes = t.p_value >= significance;
  t.z = residual.cwiseQuotient(noise.sd);
  return t;
}

}  // namespace colza::diagnose
