#include "calibration/run_features.hpp"

#include <cmath>

#include "analysis/mohr_coulomb.hpp"
#include "calibration/calibrate.hpp"
#include "calibration/measured_csv.hpp"
#include "calibration/measured_shear_features.hpp"
#include "calibration/run_cache.hpp"
#include "io/format_number.hpp"
#include "io/load_label.hpp"

namespace colza::calibration {

namespace fs = std::filesystem;

namespace {

void add_numbers(const nlohmann::json& object, const std::string& prefix, Features& f) {
  for (const auto& [name, value] : object.items())
    if (value.is_number()) f[prefix + name] = value.get<double>();
}

void add_if_available(Features& f, const std::string& name, double value) {
  if (std::isfinite(value)) f[name] = value;
}

}  // namespace

std::string feature_names(const Features& f) {
  std::string s;
  for (const auto& [name, value] : f) s += (s.empty() ? "" : ", ") + name;
  return s;
}

std::string load_feature_name(double sigma, const std::string& feature) { return load_label(sigma) + "/" + feature; }

Features output_features(const nlohmann::json& outputs) {
  Features f;
  add_numbers(outputs, "", f);
  if (outputs.contains("loads") && outputs["loads"].is_array())
    for (const auto& load : outputs["loads"])
      if (load.is_object() && load.contains("normal_stress") && load["normal_stress"].is_number())
        add_numbers(load, load_feature_name(load["normal_stress"].get<double>(), ""), f);
  return f;
}

Features strength_line_features(const fs::path& dir, const std::vector<double>& loads,
                                const StrengthDefinition& definition, const std::string& id,
                                std::vector<std::string>& warnings) {
  Features f;
  std::vector<double> tau;
  for (double sigma : loads) {
    const fs::path file = dir / shear_curve_file_name(sigma);
    const auto cols = read_csv_columns(file.string(), {kShearDisplacementColumn, kShearStressColumn}, file.string(),
                                       "(a DEM run's load curve)");
    std::size_t samples = 0;
    double at = 0.0;
    tau.push_back(curve_strength(cols[0], cols[1], definition, samples, at));
    if (samples == 0)
      throw CalibrationError("measured.peak_width", "DEM run " + id + ": " + file.string() + " spans less shear "
                             "displacement than the peak width " + format_significant(definition.peak_width, 6) +
                             " m: narrow measured.peak_width or shear further (shear_box.shear_displacement)");
    if (samples < 2)
      throw CalibrationError("measured.peak_width", "DEM run " + id + ": 1 row of " + file.string() +
                             " in the peak's interval: widen measured.peak_width or record the curve more often "
                             "(shear_box.record_interval)");
    if (at > cols[0].back() - definition.peak_width)
      warnings.push_back("DEM run " + id + ": the largest mean of " + file.string() + " lies in its last " +
                         format_significant(definition.peak_width, 6) + " m: the run may not have reached its "
                         "peak; shear further (shear_box.shear_displacement)");
    f[load_feature_name(sigma, "shear_strength")] = tau.back();
  }
  const MohrCoulombFit mc = fit_mohr_coulomb(loads, tau);
  f["cohesion"] = mc.cohesion;
  f["tan_phi"] = mc.slope;
  return f;
}

void add_shear_curve_features(const ShearCurveFeatures& c, const std::string& prefix, Features& f) {
  if (c.peak.samples > 0) f[prefix + "peak_strength"] = c.peak.value;
  if (c.residual_samples > 0) f[prefix + "residual_strength"] = c.residual;
  add_if_available(f, prefix + "drop", c.drop);
  add_if_available(f, prefix + "drop_fraction", c.drop_fraction);
  add_if_available(f, prefix + "max_dilation", c.max_dilation);
  add_if_available(f, prefix + "dilatancy_angle_deg", c.dilatancy_angle_deg);
  add_if_available(f, prefix + "initial_stiffness", c.initial_stiffness);
}

Features shear_curve_features_of(const fs::path& dir, const std::vector<double>& loads,
                                 const ShearCurveSettings& settings, double box_length) {
  Features f;
  for (double sigma : loads) {
    const std::string file = (dir / shear_curve_file_name(sigma)).string();
    add_shear_curve_features(
        read_measured_shear_features(file, settings, file, "(a DEM run's load curve)", box_length).features,
        load_feature_name(sigma, ""), f);
  }
  return f;
}

Features run_features_of(const nlohmann::json& outputs, const fs::path& run_dir, Scenario scenario,
                         const RunConfig& config) {
  Features f = output_features(outputs);
  if (scenario == Scenario::kShear) {
    ShearCurveSettings settings;
    settings.window = {config.shear_box.strength_window_start, config.shear_box.strength_window_end};
    const Features curves =
        shear_curve_features_of(run_dir, config.shear_box.normal_stresses, settings, config.shear_box.length);
    f.insert(curves.begin(), curves.end());
  }
  return f;
}

Features load_unload_features(const LoadUnloadAnalysis& a) {
  Features f;
  for (std::size_t k = 0; k < a.cycles.size(); ++k) {
    const LoadUnloadCycle& c = a.cycles[k];
    const std::string prefix = "cycle" + std::to_string(k + 1) + "/";
    f[prefix + "loop_area"] = c.loop_area;
    f[prefix + "strain_at_turn"] = c.strain_at_turn;
    f[prefix + "permanent_strain"] = c.permanent_strain;
    f[prefix + "rebound_strain"] = c.rebound_strain;
  }
  for (std::size_t b = 0; b < a.branches.size(); ++b) {
    const CurveBranch& branch = a.branches[b];
    const std::string prefix = "branch" + std::to_string(b + 1) + "/";
    for (const LocalModulus& m : branch.moduli) {
      const std::string at = std::string("@").append(format_shortest(m.stress)).append("Pa");
      add_if_available(f, prefix + "modulus" + at, m.modulus);
      add_if_available(f, prefix + "lateral_ratio" + at, m.lateral_ratio);
    }
    add_if_available(f, prefix + "lateral_ratio_end", branch.lateral_ratio_end);
  }
  return f;
}

}  // namespace colza::calibration
