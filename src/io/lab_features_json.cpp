#include "io/lab_features_json.hpp"

#include <cmath>

#include "analysis/inertial_number.hpp"

namespace colza {

namespace {

// NaN -> null (nlohmann writes a NaN double as null too; explicit, so that the contract holds
// whatever the library does).
nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

nlohmann::json load_unload_json(const LoadUnloadAnalysis& a, const CycleAnalysisSettings& settings) {
  nlohmann::json branches = nlohmann::json::array();
  for (const CurveBranch& b : a.branches) {
    nlohmann::json moduli = nlohmann::json::array();
    for (const LocalModulus& m : b.moduli)
      moduli.push_back({{"stress", m.stress},
                        {"modulus", number(m.modulus)},
                        {"lateral_ratio", number(m.lateral_ratio)},
                        {"points", m.points},
                        {"passages", m.passages},
                        {"stress_range", {m.stress_low, m.stress_high}}});
    branches.push_back({{"kind", b.loading ? "loading" : "unloading"},
                        {"first_row", b.first_row},
                        {"last_row", b.last_row},
                        {"stress_start", b.stress_start},
                        {"stress_end", b.stress_end},
                        {"stress_extreme", b.stress_extreme},
                        {"strain_start", b.strain_start},
                        {"strain_end", b.strain_end},
                        {"work", b.work},
                        {"lateral_ratio_end", number(b.lateral_ratio_end)},
                        {"moduli", moduli}});
  }
  nlohmann::json cycles = nlohmann::json::array();
  for (const LoadUnloadCycle& c : a.cycles)
    cycles.push_back({{"loading_branch", c.loading_branch},
                      {"unloading_branch", c.unloading_branch},
                      {"loop_area", c.loop_area},
                      {"strain_at_turn", c.strain_at_turn},
                      {"permanent_strain", c.permanent_strain},
                      {"rebound_strain", c.rebound_strain}});
  return {{"branches", branches},
          {"cycles", cycles},
          {"radial_force", a.has_radial_force},
          {"modulus_stresses", settings.modulus_stresses},
          {"modulus_window", settings.modulus_window},
          {"reversal_tolerance", settings.reversal_tolerance}};
}

nlohmann::json shear_features_json(const ShearCurveFeatures& f, const ShearCurveSettings& s) {
  const bool peak = f.peak.samples > 0;
  return {{"peak_strength", peak ? number(f.peak.value) : nlohmann::json(nullptr)},
          {"peak_displacement", peak ? number(f.peak.displacement) : nlohmann::json(nullptr)},
          {"peak_width", s.peak_width},
          {"residual_strength", f.residual_samples ? number(f.residual) : nlohmann::json(nullptr)},
          {"strength_window", {s.window.start, s.window.end}},
          {"drop", number(f.drop)},
          {"drop_fraction", number(f.drop_fraction)},
          {"max_dilation", number(f.max_dilation)},
          {"max_dilation_displacement", number(f.max_dilation_displacement)},
          {"dilatancy_angle_deg", number(f.dilatancy_angle_deg)},
          {"dilatancy_points", f.dilatancy_points},
          {"initial_stiffness", number(f.initial_stiffness)},
          {"stiffness_fraction", s.stiffness_fraction},
          {"stiffness_displacement", number(f.stiffness_displacement)}};
}

nlohmann::json inertial_number_json(const InertialNumberInputs& in, double& value) {
  value = in.pressure > 0.0 && in.strain_rate > 0.0
              ? inertial_number(in.strain_rate, in.mean_diameter, in.particle_density, in.pressure)
              : std::nan("");
  return {{"value", number(value)},
          {"strain_rate", in.strain_rate},
          {"strain_rate_is", in.strain_rate_is},
          {"mean_diameter", in.mean_diameter},
          {"particle_density", in.particle_density},
          {"pressure", in.pressure},
          {"pressure_is", in.pressure_is},
          {"quasi_static_limit", kQuasiStaticInertialNumber}};
}

}  // namespace colza
