// Mohr-Coulomb failure line from direct shear results (paper section 3.1):
// tau = C + sigma tan(Phi), a least-squares line through (sigma, tau) over the loads.
#pragma once
#include <string>
#include <vector>

namespace colza {

struct MohrCoulombFit {
  double cohesion = 0.0;            // C (Pa), intercept
  double friction_angle_deg = 0.0;  // Phi (deg) = atan(slope)
  double slope = 0.0;               // tan(Phi)
  double r2 = 0.0;                  // 1 for two loads (a line through two points)
  // Standard errors from the scatter about the line, s^2 = sum(residual^2) / (n - 2):
  // se(slope) = s / sqrt(Sxx), se(C) = s sqrt(1/n + mean(sigma)^2 / Sxx), se(Phi) =
  // se(slope) / (1 + slope^2) in degrees. Zero degrees of freedom (two loads): NaN.
  int degrees_of_freedom = 0;       // n - 2
  double cohesion_se = 0.0;         // Pa
  double slope_se = 0.0;            // -
  double friction_angle_se_deg = 0.0;
};

// Needs at least two distinct normal stresses; throws std::invalid_argument otherwise.
MohrCoulombFit fit_mohr_coulomb(const std::vector<double>& normal_stress, const std::vector<double>& shear_strength);

// What a user must read beside C, or "": a C within two standard errors of zero (with a
// degree of freedom or more) is not told from no cohesion by these loads, and a negative one
// is where the line through the loads meets the stress axis, not a strength (a walk-through's
// series gave C = -1.151 +/- 5.286 kPa without a word).
std::string cohesion_note(const MohrCoulombFit& fit);

}  // namespace colza
