// `colza features load-unload|shear --csv FILE ...`: the lab-test features of a measured (or
// any colza-written) curve, by the code that reduces colza's runs (docs/running.md, "Load-unload
// cycles, whole shear curves, inertial number"; data/measured/README.md). Prints JSON.
#pragma once
#include <string>
#include <vector>

namespace colza {

struct FeaturesOptions {
  std::string test;                      // "load-unload" | "shear"
  std::string csv;
  // load-unload
  double cylinder_diameter = 0.0;        // m
  double height = 0.0;                   // m, the sample's height at zero travel
  std::vector<double> modulus_stresses;  // Pa (default: half the largest piston stress)
  double modulus_window = 0.1;
  double reversal_tolerance = 1e-3;
  // shear
  double window_start = 0.020, window_end = 0.030;  // m
  double peak_width = 0.001;             // m
  double stiffness_fraction = 0.5;
  double box_length = 1.0;               // m: a displacement beyond it is a curve in mm
};

// 0, or 2 for bad input (the message names the option or the file and the reason).
int features_command(const FeaturesOptions& options);

}  // namespace colza
