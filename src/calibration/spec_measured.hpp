// The spec's [measured] table, one reader per stage: the measured data (values, or files in
// plain formats, data/measured/README.md) and their uncertainties -> s.problem.targets (and
// their correlation) and what they were derived from, for the report. Each reader expects
// [measured] present, s.stage, s.base and s.file set; checks units (colza reads SI) and
// every file before any run.
#pragma once
#include "calibration/spec.hpp"
#include "config/config_reader.hpp"

namespace colza::calibration {

// Density: bulk_density (kg/m^3) +/- bulk_density_uncertainty.
void read_measured_density(const ConfigNode& measured, Spec& s);

// Compression: c1 (N/m), c2 (N/m^2) given, or fitted to a measured curve over the model's
// fit range; c1_uncertainty, c2_uncertainty; optional correlation.
void read_measured_compression(const ConfigNode& measured, Spec& s);

// Shear: cohesion C (Pa) and tan(Phi) of the Mohr-Coulomb line through measured strengths
// (a results CSV, or one curve per normal load read by measured.strength), their
// uncertainties and correlation, and the loads of each design run's series (s.loads).
void read_measured_shear(const ConfigNode& measured, Spec& s);

// Load_unload and repose: [[measured.features]] (name, value, uncertainty, unit), each a
// feature a run of the test yields (lab_tests.hpp), its value stated or read off the measured
// curve ([measured] curve: a load-unload curve with sample_height in m, or a heap profile;
// data/measured/README.md) by the code that reduces a run's. Load_unload needs
// oedometer.cycles in the model.
void read_measured_load_unload_stage(const ConfigNode& measured, Spec& s);
void read_measured_repose_stage(const ConfigNode& measured, Spec& s);

// [[1, rho], [rho, 1]]: the correlation matrix of two targets from one fit.
Eigen::MatrixXd correlation_of_two(double rho);

}  // namespace colza::calibration
