#include "analysis/shear_strength.hpp"

#include <algorithm>

namespace colza {

ShearStrengthMean shear_strength_of_curve(const std::vector<double>& displacement,
                                          const std::vector<double>& shear_stress, StrengthWindow window) {
  ShearStrengthMean mean(window);
  for (std::size_t k = 0; k < displacement.size() && k < shear_stress.size(); ++k)
    mean.add(displacement[k], shear_stress[k]);
  return mean;
}

ShearPeak peak_shear_strength(const std::vector<double>& displacement, const std::vector<double>& shear_stress,
                              double width) {
  const std::size_t n = std::min(displacement.size(), shear_stress.size());
  // prefix[k] = sum of the first k stresses: the mean over rows j..i is (prefix[i+1] - prefix[j]) / (i - j + 1).
  std::vector<double> prefix(n + 1, 0.0);
  for (std::size_t k = 0; k < n; ++k) prefix[k + 1] = prefix[k] + shear_stress[k];
  ShearPeak peak;
  std::size_t j = 0;  // first row of the interval ending at row i
  for (std::size_t i = 0; i < n; ++i) {
    if (displacement[i] - width < displacement[0]) continue;  // the interval would start before the curve
    while (displacement[j] < displacement[i] - width) ++j;
    const std::size_t count = i - j + 1;
    const double mean = (prefix[i + 1] - prefix[j]) / static_cast<double>(count);
    if (peak.samples == 0 || mean > peak.value) peak = {mean, displacement[i], count};
  }
  return peak;
}

}  // namespace colza
