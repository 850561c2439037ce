#include "calibration/lab_tests.hpp"

#include <algorithm>
#include <stdexcept>

#include "calibration/measured_heap_profile.hpp"
#include "calibration/measured_load_unload.hpp"
#include "calibration/measured_shear_features.hpp"
#include "calibration/spec_measured.hpp"
#include "core/types.hpp"

namespace colza::calibration {

namespace {

// A measured load-unload curve in the model's cylinder: A = pi D^2 / 4, D =
// oedometer.cylinder_diameter; moduli at oedometer.modulus_stresses (default: half the
// curve's largest stress).
Features measured_load_unload_curve_features(const std::string& csv, const MeasuredCurveContext& c) {
  const MeasuredLoadUnload m = read_measured_load_unload(csv, c.spec_file, c.key);
  const double diameter = c.model->oedometer.cylinder_diameter;
  const double area = kPi * 0.25 * diameter * diameter;
  CycleAnalysisSettings s;
  s.modulus_stresses = c.model->oedometer.cycles.modulus_stresses;
  s.modulus_window = c.model->oedometer.cycles.modulus_window;
  if (s.modulus_stresses.empty()) s.modulus_stresses = {0.5 * *std::max_element(m.force.begin(), m.force.end()) / area};
  return load_unload_features(
      measured_load_unload_features(m, {area, c.sample_height, diameter}, s, c.spec_file, c.key));
}

// A measured shear curve with the model's strength window (shear_box.strength_window_*),
// the peak over a trailing 1 mm and the secant stiffness to half the peak; its features
// under the per-load names without the load (the file does not state its normal stress).
Features measured_shear_curve_features(const std::string& csv, const MeasuredCurveContext& c) {
  ShearCurveSettings s;
  s.window = {c.model->shear_box.strength_window_start, c.model->shear_box.strength_window_end};
  Features f;
  add_shear_curve_features(read_measured_shear_features(csv, s, c.spec_file, c.key, c.model->shear_box.length).features,
                           "", f);
  return f;
}

// A measured heap profile in the model's repose settings (measured_heap_profile.hpp): the
// cone's angle, its error and the heap's height and radius, under a run's names.
Features measured_heap_profile_features(const std::string& csv, const MeasuredCurveContext& c) {
  const HeapAngle h = measured_heap_angle(csv, *c.model, c.spec_file, c.key);
  return {{"angle_of_repose_deg", h.angle_deg},
          {"angle_of_repose_error_deg", h.angle_error_deg},
          {"heap_height", h.height},
          {"heap_radius", h.radius}};
}

}  // namespace

const std::vector<LabTest>& lab_tests() {
  static const std::vector<LabTest> kTests = {
      {"density", Scenario::kOedometer, {"bulk_density"}, &read_measured_density, nullptr},
      {"compression", Scenario::kOedometer, {"c0", "c1", "c2", "fit_r2", "bulk_density"}, &read_measured_compression,
       nullptr},
      {"shear", Scenario::kShear, {"cohesion", "tan_phi", "friction_angle_deg", "<load>/shear_strength"},
       &read_measured_shear, nullptr},
      {"load_unload", Scenario::kOedometer,
       {"cycle<k>/loop_area", "cycle<k>/strain_at_turn", "cycle<k>/permanent_strain", "cycle<k>/rebound_strain",
        "branch<b>/modulus@<sigma*>Pa", "branch<b>/lateral_ratio@<sigma*>Pa", "branch<b>/lateral_ratio_end",
        "bulk_density"},
       &read_measured_load_unload_stage, &measured_load_unload_curve_features},
      {"shear_curve", Scenario::kShear,
       {"<load>/peak_strength", "<load>/residual_strength", "<load>/drop", "<load>/max_dilation",
        "<load>/dilatancy_angle_deg", "<load>/initial_stiffness"},
       nullptr, &measured_shear_curve_features},
      {"repose", Scenario::kRepose,
       {"angle_of_repose_deg", "angle_of_repose_error_deg", "heap_height", "heap_radius", "column_bulk_density"},
       &read_measured_repose_stage, &measured_heap_profile_features},
  };
  return kTests;
}

const LabTest& lab_test(const std::string& name) {
  for (const LabTest& t : lab_tests())
    if (t.name == name) return t;
  throw std::out_of_range("no lab test named \"" + name + "\"");
}

const LabTest& lab_test(Stage stage) { return lab_test(std::string(to_string(stage))); }

Scenario scenario_of(Stage stage) { return lab_test(stage).scenario; }

Features measured_test_curve_features(Scenario scenario, const std::string& csv, const ConfigNode& n,
                                      const RunConfig& model, const std::string& spec_file) {
  MeasuredCurveContext context{&model, 0.0, spec_file, n.full("curve")};
  if (scenario == Scenario::kRepose) return lab_test("repose").read_curve_features(csv, context);
  if (scenario != Scenario::kOedometer)
    n.fail("curve", "a load-unload curve belongs to an oedometer test, a heap profile to a repose test (a shear "
                    "test names [[tests.curves]], one per load)");
  n.require("sample_height", "the measured sample's height at zero piston travel, m");
  context.sample_height = n.positive("sample_height", 0.0);
  return lab_test("load_unload").read_curve_features(csv, context);
}

namespace {

// `name` against one of a test's feature patterns: a "<...>" stands for one or more
// characters other than '/' (a load label, a cycle or branch number, a stress).
bool matches_pattern(const std::string& pattern, std::size_t p, const std::string& name, std::size_t n) {
  if (p == pattern.size()) return n == name.size();
  if (pattern[p] == '<') {
    const std::size_t close = pattern.find('>', p);
    for (std::size_t end = n + 1; end <= name.size() && name[end - 1] != '/'; ++end)
      if (matches_pattern(pattern, close + 1, name, end)) return true;
    return false;
  }
  return n < name.size() && pattern[p] == name[n] && matches_pattern(pattern, p + 1, name, n + 1);
}

}  // namespace

bool names_a_feature_of(const LabTest& test, const std::string& name) {
  return std::any_of(test.features.begin(), test.features.end(),
                     [&](const std::string& pattern) { return matches_pattern(pattern, 0, name, 0); });
}

std::string lab_test_feature_list(const LabTest& test) {
  std::string list;
  for (const std::string& f : test.features) list += (list.empty() ? "" : ", ") + f;
  return list;
}

}  // namespace colza::calibration
