// The spec's design of the calibration: [[parameters]] (each a config key with its design
// values and bounds, every value a run can be given checked against the model), [fit],
// [sequential] and [scatter].
#pragma once
#include "calibration/spec.hpp"
#include "config/config_reader.hpp"

namespace colza::calibration {

// [[parameters]] into s.problem.parameters and s.problem.design (s.base and the model read);
// warnings about implausible bounds into s.warnings.
void read_spec_parameters(const ConfigNode& root, Spec& s);

// [fit]: the response surface's kind.
void read_spec_fit(const ConfigNode& fit, Problem& p);

// [sequential]: the run budget and the start points (inside the bounds, accepted by the model,
// spanning a line or a plane).
void read_spec_sequential(const ConfigNode& sequential, Spec& s);

// [scatter]: replicates, 0 (off) or >= 2, and only when the seed makes the sample.
void read_spec_scatter(const ConfigNode& scatter, Spec& s);

}  // namespace colza::calibration
