// `colza run oedometer|shear-series|repose --speeds V1,V2,... --out DIR`: the same sample run
// at each speed (the oedometer's piston speed, the shear box's shear speed, the repose
// cylinder's lift speed; m/s) and how every feature moves with speed (analysis/speed_series.hpp),
// with each run's inertial number (analysis/inertial_number.hpp). docs/running.md, "Speed series".
#pragma once
#include <vector>

#include "cli/run_commands.hpp"

namespace colza {

// 0, or 2 for bad input (the message names --speeds, the file or the key, and the reason).
int speed_series_command(const RunOptions& options);

}  // namespace colza
