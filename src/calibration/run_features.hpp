// A finished DEM run (run_cache.hpp) as named features: the numbers of its outputs
// (summary.json "outputs") and what its kept curves give. Names are those of the outputs
// (bulk_density, c1, c2, cohesion, tan_phi, ...); a shear series' per-load values are named
// "<load label>/<feature>" (io/load_label.hpp), e.g. "load-25750Pa/shear_strength".
#pragma once
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/oedometer_cycles.hpp"
#include "analysis/shear_curve_features.hpp"
#include "calibration/measured_shear_curve.hpp"
#include "config/run_config.hpp"

namespace colza::calibration {

// Feature name -> value (SI units of the output it comes from).
using Features = std::map<std::string, double>;

// The features' names, ", "-separated (for a message naming what a run or a curve gives).
std::string feature_names(const Features& f);

// "<load label>/<feature>": a shear series' feature at normal stress sigma (Pa).
std::string load_feature_name(double sigma, const std::string& feature);

// Every number in the outputs under its own name (true/false and text are not features),
// and per load of a shear series ("loads": [{normal_stress, ...}]) every number of that
// load under load_feature_name.
Features output_features(const nlohmann::json& outputs);

// The shear strength of each load's kept curve (<run_dir>/load-<sigma>Pa.csv) by
// `definition` (the same as a measured curve's, measured_shear_curve.hpp) and the
// Mohr-Coulomb line through them: cohesion (Pa), tan_phi (-) and per load shear_strength.
// A curve too short for the definition, or with one row in the peak's interval, is a
// CalibrationError (key measured.peak_width) naming `run_id`; a peak in a curve's last peak
// width adds a warning (the run may not have reached its peak).
Features strength_line_features(const std::filesystem::path& run_dir, const std::vector<double>& loads,
                                const StrengthDefinition& definition, const std::string& run_id,
                                std::vector<std::string>& warnings);

// A shear curve's features (analysis/shear_curve_features.hpp) as `prefix` + peak_strength,
// residual_strength, drop, drop_fraction, max_dilation, dilatancy_angle_deg and
// initial_stiffness (Pa, -, m, deg, Pa/m; a feature that is not available is left out).
void add_shear_curve_features(const ShearCurveFeatures& curve, const std::string& prefix, Features& features);

// The whole-curve features of each load's kept curve (analysis/shear_curve_features.hpp):
// per load peak_strength, residual_strength, drop, drop_fraction, max_dilation,
// dilatancy_angle_deg and initial_stiffness (a feature that is not available is left out).
Features shear_curve_features_of(const std::filesystem::path& run_dir, const std::vector<double>& loads,
                                 const ShearCurveSettings& settings, double box_length);

// Every feature of a finished run of `config` (run_cache.hpp) kept in `run_dir`: its outputs'
// numbers (output_features) and, for a shear series, each load's whole-curve features over
// the config's strength window (shear_curve_features_of).
Features run_features_of(const nlohmann::json& outputs, const std::filesystem::path& run_dir, Scenario scenario,
                         const RunConfig& config);

// A load-unload curve's features (analysis/oedometer_cycles.hpp), numbered from 1 in time
// order: per cycle "cycle<k>/loop_area" (J/m^3), "/strain_at_turn", "/permanent_strain",
// "/rebound_strain" (-); per branch "branch<b>/modulus@<sigma*>Pa" (Pa), "/lateral_ratio@<sigma*>Pa"
// and "/lateral_ratio_end" (K, -), each left out where not available.
Features load_unload_features(const LoadUnloadAnalysis& analysis);

}  // namespace colza::calibration
