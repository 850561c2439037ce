// The [measured] table of the load_unload and repose stages: features of the lab test by the
// names a run of it yields (lab_tests.hpp), each stated or read off the test's measured curve
// by the code that reduces colza's own runs.
#include <filesystem>
#include <set>

#include "calibration/lab_tests.hpp"
#include "calibration/spec_fields.hpp"
#include "calibration/spec_measured.hpp"
#include "calibration/spec_model.hpp"
#include "io/input_file.hpp"

namespace colza::calibration {

namespace {

std::string fmt(double v) { return spec_number_text(v); }

// [measured] curve: the test's measured curve (a load-unload curve with the sample's height,
// or a heap profile) -> its features, in the model's geometry. Empty when none is named.
Features measured_curve_of(const ConfigNode& m, Spec& s, const LabTest& test) {
  if (!m.has("curve")) {
    if (m.has("sample_height")) m.fail("sample_height", "belongs to a measured load-unload curve (curve)");
    return {};
  }
  s.measured_file = resolve_spec_path(s.file, required_string(m, "curve"));
  if (const std::string why = unreadable_file_reason(s.measured_file); !why.empty())
    m.fail("curve", "the measured curve " + why);
  if (s.stage == Stage::kRepose && m.has("sample_height"))
    m.fail("sample_height", "belongs to a measured load-unload curve, not to a heap profile");
  return measured_test_curve_features(test.scenario, s.measured_file, m, s.base, s.file);
}

// An angle of repose stated in radians, or a heap size in mm, is a unit slip (colza reads
// deg and m): refused before any run.
void check_repose_units(const ConfigNode& f, const std::string& name, double value) {
  if (name == "angle_of_repose_deg" && !(value > 1.6 && value < 90.0))
    f.fail("value", fmt(value) + " is not an angle of repose in degrees (between 1.6 and 90): colza reads deg; "
                    "is it in radians?");
  if ((name == "heap_height" || name == "heap_radius") && value > 10.0)
    f.fail("value", fmt(value) + " m is no heap's size: colza reads m (mm / 1000)");
}

// [[measured.features]] {name, value (or from the curve), uncertainty, unit} -> the targets.
void read_feature_targets(const ConfigNode& m, Spec& s, const LabTest& test) {
  s.measured_curve_features = measured_curve_of(m, s, test);
  const std::vector<ConfigNode> rows = m.table_array("features");
  if (rows.empty())
    m.fail("features", "missing: the measured features to calibrate to ([[measured.features]] with name, value and "
                       "uncertainty; a " + test.name + " run yields " + lab_test_feature_list(test) + ")");
  std::set<std::string> seen;
  for (const ConfigNode& f : rows) {
    const std::string name = required_string(f, "name");
    if (!seen.insert(name).second) f.fail("name", "repeats another feature");
    if (!names_a_feature_of(test, name))
      f.fail("name", "\"" + name + "\" is not a feature of a " + test.name + " run: it yields " +
                         lab_test_feature_list(test));
    const auto from_curve = s.measured_curve_features.find(name);
    const bool stated = f.has("value");
    if (!stated && from_curve == s.measured_curve_features.end())
      f.fail("value", s.measured_file.empty()
                          ? std::string("missing: the measured value, SI units (or name the measured curve in curve)")
                          : "missing: the measured curve gives no " + name + "; it gives " +
                                feature_names(s.measured_curve_features));
    const double value = stated ? required_number(f, "value") : from_curve->second;
    if (s.stage == Stage::kRepose) check_repose_units(f, name, value);
    s.problem.targets.push_back({name, string_or(f, "unit", ""), value, required_positive(f, "uncertainty")});
    if (!stated) s.targets_from_curve.insert(name);
    reject_unknown_spec_keys(f);
  }
}

}  // namespace

void read_measured_load_unload_stage(const ConfigNode& m, Spec& s) {
  if (s.base.oedometer.cycles.targets.empty())
    throw ConfigError(s.file, "model", "a load_unload stage needs a load-unload cycle in the model: set "
                                       "oedometer.cycles in its config or in [model] set, e.g. "
                                       "\"oedometer.cycles=[40e3, 0.0]\"");
  read_feature_targets(m, s, lab_test("load_unload"));
}

void read_measured_repose_stage(const ConfigNode& m, Spec& s) { read_feature_targets(m, s, lab_test("repose")); }

}  // namespace colza::calibration
