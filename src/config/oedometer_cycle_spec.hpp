// oedometer.cycles: a load-unload protocol for the oedometer (physics.md section 8). Absent,
// the oedometer loads once, as the paper does (and writes what it always wrote). Given, the
// piston moves down at oedometer.piston_speed until the piston stress reaches the first
// target, reverses and moves up at the same speed until the stress falls to the second, and
// so on; the run ends at the last target. The keys that tune the analysis
// (analysis/oedometer_cycles.hpp) belong to the protocol and are read only with it.
#pragma once
#include <vector>

#include "config/config_reader.hpp"

namespace colza {

struct OedometerCycleSpec {
  std::vector<double> targets;           // Pa, piston stresses to reach in turn; empty: one loading
  std::vector<double> modulus_stresses;  // Pa, where M and K are read (default: half the largest target)
  double modulus_window = 0.1;           // relative half-width of the fit's stress window
  bool enabled() const { return !targets.empty(); }
};

// Reads oedometer.cycles, .modulus_stresses and .modulus_window from the [oedometer] table
// `t`. Targets must be >= 0, the first above 0, and alternate: an unloading target below the
// loading target before it, a loading target above the unloading target before it (the piston
// reverses at each; one the previous branch already passes could never be "reached"). A
// target's force on the piston (target x piston_area) may not exceed oedometer.stop_force,
// which stays the run's safety stop. The analysis keys without cycles are errors too (they
// would do nothing). Throws ConfigError naming the file, the key and the reason.
OedometerCycleSpec read_oedometer_cycles(const ConfigNode& t, double piston_area, double stop_force);

}  // namespace colza
