// Angle of repose of a heap of spheres (physics.md section 8): a cone fitted to the heap's
// surface spheres away from its toe and its top. From plain arrays (sphere centres and radii),
// so that a run and a measured profile (points of the surface) go through the same fit.
//
// Method: about the vertical axis through (centre_x, centre_y), every sphere has a distance
// rho from the axis and a top z + r - base_height above the base, which lies at `base_height`
// (the plate, or the top of a layer glued to it). The plane is cut into `sectors` equal sectors and, along
// rho, into bins of `bin_width` (default: the mean diameter); the surface sphere of a cell is
// its highest top. The heap's radius R is the largest rho of a surface sphere whose top stands
// at least `toe_height` above the base (default: two mean diameters: spheres lying one layer
// deep on the base, or rolled away, are not heap). The fit is the least-squares line
// top = a - tan(alpha) rho through the surface spheres with inner R <= rho <= outer R
// (defaults 0.25 and 0.75: away from the rounded top and the spread toe):
//   alpha = atan(tan_alpha), its error = se(tan_alpha) / (1 + tan_alpha^2) (rad -> deg),
//   se the slope's standard error, sqrt(SS_res / (n - 2) / S_rho_rho).
// No fit (valid = false) when R is under 3 bins (a sphere or two stacked on a spread layer)
// or fewer than 5 surface spheres lie in the fit's range.
#pragma once
#include <cstddef>
#include <vector>

namespace colza {

struct HeapFitSettings {
  std::size_t sectors = 16;
  double bin_width = 0.0;    // m; 0: the mean diameter
  double toe_height = 0.0;   // m above base_height; 0: two mean diameters
  double base_height = 0.0;  // m, the surface the heap stands on
  double inner = 0.25, outer = 0.75;  // of R
  double centre_x = 0.0, centre_y = 0.0;  // m, the heap's axis
};

struct HeapAngle {
  bool valid = false;            // R at least 3 bins and at least 5 surface spheres in the fit's range
  double angle_deg = 0.0;
  double angle_error_deg = 0.0;  // one standard error
  double tan_angle = 0.0;
  double intercept = 0.0;        // m, a: the fitted cone's apex height above base_height
  double height = 0.0;           // m, the highest top above base_height
  double radius = 0.0;           // m, R
  double fit_rho_min = 0.0, fit_rho_max = 0.0;  // m
  std::size_t points = 0;        // surface spheres in the fit
  std::vector<std::size_t> fit_spheres;  // their indices in the input arrays, ascending
  std::size_t surface_spheres = 0;
  double r2 = 0.0;
};

// Throws std::invalid_argument when the arrays differ in length or settings are out of range.
HeapAngle fit_heap_angle(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                         const std::vector<double>& radius, const HeapFitSettings& settings);

}  // namespace colza
