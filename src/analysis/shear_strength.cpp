#include "analysis/shear_strength.hpp"

namespace colza {

ShearStrengthMean shear_strength_of_curve(const std::vector<double>& displacement,
                                          const std::vector<double>& shear_stress, StrengthWindow window) {
  ShearStrengthMean mean(window);
  for (std::size_t k = 0; k < displacement.size() && k < shear_stress.size(); ++k)
    mean.add(displacement[k], shear_stress[k]);
  return mean;
}

}  // namespace colza
