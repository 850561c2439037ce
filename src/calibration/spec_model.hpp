// The spec's [model] table: the DEM config the runs start from, the overrides every run
// gets and how runs get their packing; and whether the model takes a parameter's value.
#pragma once
#include <string>

#include "calibration/spec.hpp"
#include "config/config_reader.hpp"

namespace colza::calibration {

// `value` (a path in the spec) against the spec's folder when relative.
std::string resolve_spec_path(const std::string& spec_file, const std::string& value);

// Reads [model] into s.model_config, s.model_set and s.shared_packing (s.stage set), then
// loads the model (s.base) and names the packing file every run loads (s.fixed_packing_file).
void read_spec_model(const ConfigNode& model, Spec& s);

// "" when the model config loads with `key` = `value` added to the spec's overrides (and the
// configuration read into `accepted`, when given), else why not ("the model does not accept
// particle.density = -1200: must be positive, ...").
std::string model_rejects(const Spec& s, const std::string& key, double value, RunConfig* accepted = nullptr);

}  // namespace colza::calibration
