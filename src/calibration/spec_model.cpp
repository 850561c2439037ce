#include "calibration/spec_model.hpp"

#include <filesystem>

#include "calibration/lab_tests.hpp"
#include "calibration/spec_fields.hpp"
#include "config/config_error.hpp"
#include "io/format_number.hpp"

namespace colza::calibration {

namespace fs = std::filesystem;

std::string resolve_spec_path(const std::string& spec_file, const std::string& value) {
  fs::path p(value);
  if (p.is_relative()) p = fs::path(spec_file).parent_path() / p;
  return p.lexically_normal().string();
}

void read_spec_model(const ConfigNode& model, Spec& s) {
  s.model_config = resolve_spec_path(s.file, required_string(model, "config"));
  if (!fs::exists(s.model_config)) model.fail("config", "the model config " + s.model_config + " does not exist");
  s.model_set = string_array(model, "set");
  const std::string packing = string_or(model, "packing", "per_run");
  if (packing != "per_run" && packing != "shared") model.fail("packing", "must be \"per_run\" or \"shared\"");
  s.shared_packing = packing == "shared";
  if (s.shared_packing && s.stage == Stage::kDensity)
    model.fail("packing", "the density stage measures the settled packing: every run must settle (\"per_run\")");
  if (s.shared_packing && s.stage == Stage::kRepose)
    model.fail("packing", "a repose run settles its own column in the cylinder: every run must settle (\"per_run\")");
  reject_unknown_spec_keys(model);
  try {
    s.base = load_run_config(scenario_of(s.stage), s.model_config, s.model_set);
  } catch (const ConfigError& e) {
    throw ConfigError(s.file, "model", std::string("the model config does not load: ") + e.what());
  }
  s.fixed_packing_file = s.stage == Stage::kShear    ? s.base.shear_box.packing_file
                         : s.stage == Stage::kRepose ? std::string()
                                                     : s.base.oedometer.packing_file;
}

std::string model_rejects(const Spec& s, const std::string& key, double value, RunConfig* accepted) {
  // The value exactly as a run would be given it: rounded to 6 digits, a bound just past a
  // model limit (0.9990001 for a limit of 0.999) would pass here and be refused mid-calibration.
  std::vector<std::string> set = s.model_set;
  set.push_back(key + "=" + format_shortest(value));
  try {
    RunConfig model = load_run_config(scenario_of(s.stage), s.model_config, set);
    if (accepted) *accepted = std::move(model);
  } catch (const ConfigError& e) {
    // The key that objected, when another than the parameter's (a limit between two keys).
    const std::string other = e.key().empty() || e.key() == key ? "" : "key '" + e.key() + "': ";
    return "the model does not accept " + key + " = " + format_shortest(value) + ": " + other + e.reason();
  }
  return "";
}

}  // namespace colza::calibration
