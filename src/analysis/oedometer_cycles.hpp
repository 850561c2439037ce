// Features of an oedometer load-unload curve (physics.md section 8), from plain arrays so that
// a measured curve (calibration/measured_load_unload.hpp) and a simulated one
// (scenario/oedometer.cpp, oedometer.cycles) go through the same code.
//
// Input rows in time order: piston travel s (m, positive down, from where the piston met the
// sample's top), piston force F (N, compression positive) and, optionally, the radial force
// on the cylinder R (N: the sum of the normal forces the sample exerts on the cylinder's
// wall). With the cylinder's cross-section A, the sample's height H at zero travel and the
// cylinder's diameter D:
//
//   sigma_v = F / A                          (Pa, the piston stress)
//   eps     = s / H                          (-, compression positive)
//   sigma_h = R / (pi D (H - s))             (Pa, mean over the wetted wall below the piston)
//   K       = sigma_h / sigma_v              (-, the lateral pressure ratio)
//
// Branches: the curve is split where the travel turns (a turning point is a running extreme
// that the travel leaves by more than `reversal_tolerance` x its whole range, so that a
// measured curve's jitter does not split it); a branch of increasing travel is a loading, one
// of decreasing travel an unloading; a turning row ends one branch and starts the next.
//
// Per branch:
//   * the constrained tangent modulus at each named stress sigma*: M = d sigma_v / d eps, the
//     slope of the least-squares line sigma_v(eps) through the branch's rows with
//     |sigma_v - sigma*| <= w sigma* (w = modulus_window), at least 3 rows, sigma* within the
//     branch's stress range; K at sigma* = mean sigma_h / mean sigma_v over the same rows.
//     `passages` counts the separate runs of rows in the window: more than 1 when the branch
//     leaves the window and comes back (a collapse that drops the stress below sigma* and a
//     re-rise); the line then runs through all passages and M is no tangent (it can even be
//     negative): read the curve there;
//   * the work per unit volume, W = integral sigma_v d eps (trapezoids over the rows; J/m^3,
//     negative on unloading: the work the sample gives back);
//   * K at the branch's last row.
// Per cycle (a loading branch followed by an unloading branch):
//   * loop area = W_loading + W_unloading (J/m^3): the net work per unit volume the piston did
//     on the sample over the cycle, the area between the two branches (for a first, virgin
//     loading it includes the work of the set that stays);
//   * permanent strain = eps at the unloading branch's last row (where the stress fell to the
//     cycle's lower target); rebound strain = eps at the turn - permanent strain.
#pragma once
#include <cstddef>
#include <limits>
#include <vector>

namespace colza {

struct OedometerGeometry {
  double area = 0.0;               // m^2, the piston's (= the cylinder's cross-section)
  double height = 0.0;             // m, the sample's height at zero travel
  double cylinder_diameter = 0.0;  // m, for the wetted area pi D (H - s)
};

struct CycleAnalysisSettings {
  std::vector<double> modulus_stresses;  // Pa, sigma* where M and K are read on every branch
  double modulus_window = 0.1;           // w: relative half-width of the stress window of the fit
  double reversal_tolerance = 1e-3;      // of the travel's whole range
};

inline constexpr double kNotAvailable = std::numeric_limits<double>::quiet_NaN();

struct LocalModulus {
  double stress = 0.0;               // Pa, sigma* as named
  double modulus = kNotAvailable;    // Pa; NaN: fewer than 3 rows in the window
  double lateral_ratio = kNotAvailable;  // K over the window's rows; NaN without radial force
  double stress_low = 0.0, stress_high = 0.0;  // Pa, the rows' stress range actually used
  std::size_t points = 0;            // rows in the window
  std::size_t passages = 0;          // separate runs of rows in the window (1 on a monotone branch)
};

struct CurveBranch {
  bool loading = true;
  std::size_t first_row = 0, last_row = 0;  // inclusive; a turning row belongs to both branches
  double stress_start = 0.0, stress_end = 0.0;  // Pa
  double strain_start = 0.0, strain_end = 0.0;  // -
  double stress_extreme = 0.0;       // Pa, the largest (loading) or smallest (unloading) stress of the branch
  double work = 0.0;                 // J/m^3, integral sigma_v d eps
  double lateral_ratio_end = kNotAvailable;  // K at the last row (NaN: no radial force, or sigma_v = 0)
  std::vector<LocalModulus> moduli;  // the named stresses inside the branch's stress range, in order
};

struct LoadUnloadCycle {
  std::size_t loading_branch = 0, unloading_branch = 0;
  double loop_area = 0.0;         // J/m^3
  double strain_at_turn = 0.0;    // eps where the loading turned
  double permanent_strain = 0.0;  // eps at the end of the unloading
  double rebound_strain = 0.0;    // strain_at_turn - permanent_strain
};

struct LoadUnloadAnalysis {
  bool has_radial_force = false;
  std::vector<CurveBranch> branches;
  std::vector<LoadUnloadCycle> cycles;
};

// The branches' row ranges [first, last] (inclusive; consecutive branches share the turning
// row); a curve with fewer than 2 rows, or whose travel never moves, is one branch.
struct RowRange {
  std::size_t first = 0, last = 0;
};
std::vector<RowRange> split_branches(const std::vector<double>& travel, double reversal_tolerance);

// Throws std::invalid_argument when the arrays differ in length (radial_force may be empty:
// no radial force), there are fewer than 2 rows, or the geometry is not positive.
LoadUnloadAnalysis analyse_load_unload(const std::vector<double>& travel, const std::vector<double>& force,
                                       const std::vector<double>& radial_force, const OedometerGeometry& geometry,
                                       const CycleAnalysisSettings& settings);

}  // namespace colza
