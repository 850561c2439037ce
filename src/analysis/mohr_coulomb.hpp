// Mohr-Coulomb failure line from direct shear results (paper section 3.1):
// tau = C + sigma tan(Phi), a least-squares line through (sigma, tau) over the loads.
#pragma once
#include <vector>

namespace colza {

struct MohrCoulombFit {
  double cohesion = 0.0;            // C (Pa), intercept
  double friction_angle_deg = 0.0;  // Phi (deg) = atan(slope)
  double slope = 0.0;               // tan(Phi)
  double r2 = 0.0;                  // 1 for two loads (a line through two points)
};

// Needs at least two distinct normal stresses; throws std::invalid_argument otherwise.
MohrCoulombFit fit_mohr_coulomb(const std::vector<double>& normal_stress, const std::vector<double>& shear_strength);

}  // namespace colza
