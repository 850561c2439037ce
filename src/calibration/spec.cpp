#include "calibration/spec.hpp"

#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "calibration/lab_tests.hpp"
#include "calibration/spec_design.hpp"
#include "calibration/spec_fields.hpp"
#include "calibration/spec_model.hpp"
#include "config/config_error.hpp"
#include "config/config_reader.hpp"
#include "io/input_file.hpp"

namespace colza::calibration {

const char* to_string(Stage s) {
  switch (s) {
    case Stage::kDensity: return "density";
    case Stage::kCompression: return "compression";
    case Stage::kShear: return "shear";
    case Stage::kLoadUnload: return "load_unload";
    case Stage::kRepose: return "repose";
  }
  return "?";
}

namespace {

// The spec file parsed (ConfigError: unreadable, or not TOML).
toml::table parse_spec_file(const std::string& path) {
  if (const std::string why = unreadable_file_reason(path); !why.empty())
    throw ConfigError(path, "", "the calibration spec " + why);
  try {
    return toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    std::ostringstream m;
    m << "TOML syntax error: " << e.description() << " (line " << e.source().begin.line << ")";
    throw ConfigError(path, "", m.str());
  }
}

// The top level, first: a misspelt [modle] would otherwise read as a missing model.config.
void reject_unknown_top_level(const ConfigNode& root) {
  static const std::set<std::string> kTopLevel = {"stage", "title",      "provenance", "model",   "parameters",
                                                  "fit",   "sequential", "scatter",    "measured"};
  for (const std::string& key : root.keys())
    if (!kTopLevel.count(key))
      root.fail(key, "unknown key or table (misspelt?): a spec has stage, title, provenance, [model], "
                     "[[parameters]], [fit], [sequential], [scatter] and [measured]");
}

Stage read_stage(const ConfigNode& root) {
  const std::string stage = required_string(root, "stage");
  if (stage == "density") return Stage::kDensity;
  if (stage == "compression") return Stage::kCompression;
  if (stage == "shear") return Stage::kShear;
  if (stage == "load_unload") return Stage::kLoadUnload;
  if (stage == "repose") return Stage::kRepose;
  root.fail("stage", "must be \"density\", \"compression\", \"shear\", \"load_unload\" or \"repose\", got \"" +
                         stage + "\"");
}

// [measured], by the stage's reader (lab_tests.hpp).
void read_measured(const ConfigNode& root, Spec& s) {
  const ConfigNode m = sub_table(root, "measured");
  if (!m.exists()) root.fail("measured", "missing: the [measured] table names the measured data and their uncertainties");
  lab_test(s.stage).read_spec_measured(m, s);
  if (s.stage == Stage::kDensity && m.has("correlation"))
    m.fail("correlation", "correlates two targets from one fit (compression: c1 and c2; shear: C and tan(Phi)); a "
                          "density spec has one target, bulk_density");
  reject_unknown_spec_keys(m);
}

}  // namespace

Spec read_spec(const std::string& path) {
  Spec s;
  s.file = path;
  const ConfigReader reader = ConfigReader::from_table(parse_spec_file(path), path);
  const ConfigNode root = reader.root();
  reject_unknown_top_level(root);
  s.stage = read_stage(root);
  s.title = string_or(root, "title", "");
  string_or(root, "provenance", "");
  read_spec_model(sub_table(root, "model"), s);
  read_spec_parameters(root, s);
  read_spec_fit(sub_table(root, "fit"), s.problem);
  read_spec_sequential(sub_table(root, "sequential"), s);
  // Realisation scatter: the same point with other seeds (calibrate.hpp).
  read_spec_scatter(sub_table(root, "scatter"), s);
  read_measured(root, s);
  return s;
}

}  // namespace colza::calibration
