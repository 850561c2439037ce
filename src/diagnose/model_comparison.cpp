#include "diagnose/model_comparison.hpp"

#include <cmath>

#include "diagnose/adequacy.hpp"

namespace colza::diagnose {

double boundary_likelihood_ratio_p(double chi_square_baseline, double chi_square_extended) {
  const double d = chi_square_baseline - chi_square_extended;
  if (!(d > 0.0)) return 1.0;
  return 0.5 * chi_square_survival(d, 1);
}

double bayesian_information_criterion(double chi_square, int parameters, int features) {
  return chi_square + parameters * std::log(static_cast<double>(features));
}

}  // namespace colza::diagnose
