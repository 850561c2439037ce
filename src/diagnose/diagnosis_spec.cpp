#include "diagnose/diagnosis_spec.hpp"

#include <set>

#include "config/config_error.hpp"
#include "config/config_reader.hpp"
#include "calibration/lab_tests.hpp"
#include "calibration/run_features.hpp"
#include "calibration/spec_model.hpp"
#include "io/format_number.hpp"
#include "io/input_file.hpp"

namespace colza::diagnose {

namespace {

std::vector<std::string> string_list(const ConfigNode& n, const std::string& key) {
  std::vector<std::string> out;
  const toml::node* v = n.get(key);
  if (!v) return out;
  const toml::array* a = v->as_array();
  if (!a) n.fail(key, "must be an array of strings");
  for (const auto& e : *a) {
    const auto s = e.value<std::string>();
    if (!s) n.fail(key, "must be an array of strings");
    out.push_back(*s);
  }
  return out;
}

std::string required_string(const ConfigNode& n, const std::string& key, const std::string& what) {
  n.require(key, what);
  if (!n.is_string(key)) n.fail(key, "must be a string (" + what + ")");
  return n.string(key, "");
}

// The model accepts the test's config with these overrides; else the spec's key is blamed.
void require_model_accepts(const ConfigNode& n, const std::string& key, const DiagnosisTest& t,
                           const std::vector<std::string>& extra, const std::string& what) {
  std::vector<std::string> set = t.set;
  set.insert(set.end(), extra.begin(), extra.end());
  try {
    (void)load_run_config(t.scenario, t.config, set);
  } catch (const ConfigError& e) {
    n.fail(key, "test " + t.name + "'s model does not accept " + what + ": " +
                    (e.key().empty() ? "" : "key '" + e.key() + "': ") + e.reason());
  }
}

std::string assignment(const std::string& key, double value) { return key + "=" + format_significant(value, 17); }

// The features of a test's measured curves, when it names any: an oedometer's load-unload
// curve (`curve`, with the sample's `sample_height` in m), a repose test's heap profile
// (`curve`) or a shear series' curves, one per load (`[[tests.curves]]` with `normal_stress` in Pa and `file`), in the formats of
// data/measured/README.md, reduced by the code that reduces colza's own runs
// (calibration/lab_tests.hpp) and named as a run's features are.
calibration::Features measured_curve_features(const ConfigNode& t, const std::string& spec_file,
                                              const DiagnosisTest& test) {
  calibration::Features out;
  const std::vector<ConfigNode> per_load = t.table_array("curves");
  if (!t.has("curve") && per_load.empty()) return out;
  RunConfig model;
  try {
    model = load_run_config(test.scenario, test.config, test.set);
  } catch (const ConfigError& e) {
    t.fail("config", "test " + test.name + "'s model (its measured curves are read in its geometry): " + e.what());
  }
  if (t.has("curve"))
    out = calibration::measured_test_curve_features(
        test.scenario, calibration::resolve_spec_path(spec_file, required_string(t, "curve", "a measured curve (CSV)")), t, model, spec_file);
  for (const ConfigNode& load : per_load) {
    if (test.scenario != Scenario::kShear) load.fail("file", "shear curves per load belong to a shear test");
    load.require("normal_stress", "the load's normal stress, Pa");
    const double sigma = load.positive("normal_stress", 0.0);
    const calibration::MeasuredCurveContext c{&model, 0.0, spec_file, load.full("file")};
    const std::string csv = calibration::resolve_spec_path(spec_file, required_string(load, "file", "a measured shear curve (CSV)"));
    for (const auto& [name, value] : calibration::lab_test("shear_curve").read_curve_features(csv, c))
      out[calibration::load_feature_name(sigma, name)] = value;
  }
  return out;
}

DiagnosisTest read_test(const ConfigNode& t, const std::string& spec_file, std::set<std::string>& names) {
  DiagnosisTest test;
  test.name = required_string(t, "name", "the test's name, e.g. \"oedometer\"");
  if (!names.insert(test.name).second) t.fail("name", "repeats the name of another test");
  if (test.name.find(':') != std::string::npos) t.fail("name", "must not contain ':'");
  t.require("scenario", "\"oedometer\", \"shear\" or \"repose\"");
  const std::string scenario = t.choice("scenario", "", {"oedometer", "shear", "repose"});
  test.scenario = scenario == "shear" ? Scenario::kShear : scenario == "repose" ? Scenario::kRepose : Scenario::kOedometer;
  test.config = calibration::resolve_spec_path(spec_file, required_string(t, "config", "the model config of this test"));
  if (const std::string why = unreadable_file_reason(test.config); !why.empty())
    t.fail("config", "the model config " + why);
  test.set = string_list(t, "set");
  const int samples = static_cast<int>(t.integer("samples", 1, 1));  // lab samples each measured value is the mean of
  const calibration::Features from_curves = measured_curve_features(t, spec_file, test);
  std::set<std::string> feature_names;
  for (const ConfigNode& f : t.table_array("features")) {
    Feature feature;
    feature.name = required_string(f, "name", "a feature a run of this test yields, e.g. \"bulk_density\"");
    if (!feature_names.insert(feature.name).second) f.fail("name", "repeats another feature of this test");
    const auto from_curve = from_curves.find(feature.name);
    if (from_curve == from_curves.end())
      f.require("value", from_curves.empty() ? "the measured value, SI units"
                                              : "the measured value, SI units: the test's measured curves give no " +
                                                    feature.name + "; they give " + calibration::feature_names(from_curves));
    f.require("uncertainty", "the measured value's standard uncertainty, SI units");
    feature.measured = f.has("value") ? f.number("value", 0.0) : from_curve->second;
    feature.uncertainty = f.positive("uncertainty", 0.0);
    feature.unit = f.string("unit", "");
    feature.test = test.name;
    feature.samples = samples;
    test.features.push_back(feature);
  }
  if (test.features.empty())
    t.fail("features", "missing: give the measured features of this test ([[tests.features]] with name, value, "
                       "uncertainty)");
  return test;
}

calibration::Parameter read_parameter(const ConfigNode& n) {
  calibration::Parameter p;
  p.key = required_string(n, "key", "the config key the parameter sets, e.g. \"particle.friction\"");
  p.name = n.string("name", p.key);
  p.unit = n.string("unit", "");
  n.require("lower", "the lower end of its range");
  n.require("upper", "the upper end of its range");
  p.lower = n.number("lower", 0.0);
  p.upper = n.number("upper", 0.0);
  if (!(p.upper > p.lower)) n.fail("upper", "must be above lower (" + format_significant(p.lower, 6) + ")");
  return p;
}

CatalogueEntry read_candidate(const ConfigNode& n) {
  const std::string name = required_string(n, "name", "a registered mechanism or a name of your own");
  CatalogueEntry e;
  if (const CatalogueEntry* known = catalogue_entry(name)) e = *known;
  else {
    n.require("settings", "the settings that switch the mechanism on (\"" + name + "\" is not one of the catalogue's: "
                          "rolling_resistance, elasto_plastic, viscous_damping, load_induced_cohesion)");
    n.require("key", "the config key of the mechanism's strength");
    e.candidate.name = name;
    e.candidate.parameter.unit = "-";
  }
  if (n.has("settings")) e.candidate.settings = string_list(n, "settings");
  e.candidate.kind = mechanism_kind_of(e.candidate.settings);
  Candidate& c = e.candidate;
  if (n.has("key")) c.parameter.key = required_string(n, "key", "the config key of the mechanism's strength");
  c.parameter.name = n.string("parameter_name", c.parameter.name.empty() ? c.parameter.key : c.parameter.name);
  c.parameter.unit = n.string("unit", c.parameter.unit);
  c.parameter.lower = n.number("neutral", c.parameter.lower);
  c.parameter.upper = n.number("upper", c.parameter.upper);
  c.probe = n.number("probe", c.probe);
  if (!(c.parameter.upper > c.parameter.lower))
    n.fail("upper", "must be above the neutral value " + format_significant(c.parameter.lower, 6));
  if (!(c.probe > c.parameter.lower && c.probe <= c.parameter.upper))
    n.fail("probe", "must lie in (neutral, upper] = (" + format_significant(c.parameter.lower, 6) + ", " +
                        format_significant(c.parameter.upper, 6) + "]");
  return e;
}

}  // namespace

DiagnosisProblem DiagnosisSpec::problem() const {
  DiagnosisProblem p;
  for (const DiagnosisTest& t : tests)
    for (Feature f : t.features) {
      f.name = t.name + ":" + f.name;
      p.features.push_back(f);
    }
  p.parameters = parameters;
  for (const CatalogueEntry& e : candidates) p.candidates.push_back(e.candidate);
  p.settings = settings;
  return p;
}

DiagnosisSpec read_diagnosis_spec(const std::string& path) {
  if (const std::string why = unreadable_file_reason(path); !why.empty())
    throw ConfigError(path, "", "the diagnosis spec " + why);
  const ConfigReader reader = ConfigReader::from_file(path);
  const ConfigNode root = reader.root();
  DiagnosisSpec s;
  s.file = path;
  s.title = root.string("title", "");
  (void)root.string("provenance", "");
  std::set<std::string> names;
  for (const ConfigNode& t : root.table_array("tests")) s.tests.push_back(read_test(t, path, names));
  if (s.tests.empty()) root.fail("tests", "missing: give one [[tests]] table per lab test");
  for (const ConfigNode& n : root.table_array("parameters")) s.parameters.push_back(read_parameter(n));
  if (s.parameters.empty())
    root.fail("parameters", "missing: give one [[parameters]] table per calibrated parameter of the baseline");
  const std::vector<ConfigNode> cands = root.table_array("candidates");
  for (const ConfigNode& n : cands) s.candidates.push_back(read_candidate(n));
  if (cands.empty() && !root.has("candidates")) s.candidates = candidate_catalogue();
  const ConfigNode st = root.table("settings");
  DiagnosisSettings& d = s.settings;
  d.replicates = static_cast<int>(st.integer("replicates", d.replicates, 2));
  d.signature_seeds = static_cast<int>(st.integer("signature_seeds", d.signature_seeds, 1));
  if (d.signature_seeds > d.replicates) st.fail("signature_seeds", "must not exceed replicates");
  d.signature_seeds_max =
      static_cast<int>(st.integer("signature_seeds_max", d.replicates, d.signature_seeds));
  d.signature_signal_to_noise = st.number_in("signature_signal_to_noise", d.signature_signal_to_noise, 0.0, 100.0);
  d.significance = st.number_in("significance", d.significance, 1e-6, 0.2);
  d.ambiguity_cosine = st.number_in("ambiguity_cosine", d.ambiguity_cosine, 0.5, 0.999);
  d.calibration_runs = static_cast<int>(st.integer("calibration_runs", d.calibration_runs, 4));
  d.extend_at_most = static_cast<int>(st.integer("extend_at_most", d.extend_at_most, 1));
  d.sensitivity_step = st.number_in("sensitivity_step", d.sensitivity_step, 0.01, 0.5);
  reader.reject_unknown_keys();
  // Every value a run can be given must be one the test's model accepts: the parameters at
  // their bounds, every candidate at its probe and its top.
  const std::vector<ConfigNode> tests = root.table_array("tests");
  const std::vector<ConfigNode> params = root.table_array("parameters");
  for (std::size_t i = 0; i < s.tests.size(); ++i) {
    for (std::size_t j = 0; j < s.parameters.size(); ++j)
      for (const double v : {s.parameters[j].lower, s.parameters[j].upper})
        require_model_accepts(params[j], "key", s.tests[i], {assignment(s.parameters[j].key, v)},
                              s.parameters[j].key + " = " + format_significant(v, 6));
    for (std::size_t k = 0; k < s.candidates.size(); ++k) {
      const CatalogueEntry& e = s.candidates[k];
      for (const double v : {e.candidate.probe, e.candidate.parameter.upper}) {
        std::vector<std::string> extra = e.candidate.settings;
        extra.push_back(assignment(e.candidate.parameter.key, v));
        for (const StrengthKey& a : e.also_sets) extra.push_back(assignment(a.key, a.factor * v));
        const ConfigNode& blame = cands.empty() ? tests[i] : cands[k];
        require_model_accepts(blame, cands.empty() ? "config" : "name", s.tests[i], extra,
                              "candidate " + e.candidate.name + " at " + format_significant(v, 6));
      }
    }
  }
  return s;
}

}  // namespace colza::diagnose
