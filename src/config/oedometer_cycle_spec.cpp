#include "config/oedometer_cycle_spec.hpp"

#include <algorithm>
#include <string>

#include "io/format_number.hpp"

namespace colza {

OedometerCycleSpec read_oedometer_cycles(const ConfigNode& t, double piston_area, double stop_force) {
  OedometerCycleSpec s;
  if (!t.has("cycles")) {
    for (const char* key : {"modulus_stresses", "modulus_window"})
      if (t.has(key)) t.fail(key, "applies to a load-unload protocol only: give oedometer.cycles too");
    return s;  // nothing read, nothing recorded: a single loading's config is as before
  }
  s.targets = t.number_list("cycles");
  const auto pa = [](double v) { return format_shortest(v) + " Pa"; };
  if (s.targets.empty())
    t.fail("cycles", "needs at least one piston stress (Pa); leave the key out for a single loading");
  for (std::size_t k = 0; k < s.targets.size(); ++k) {
    const double target = s.targets[k];
    const std::string entry = "entry " + std::to_string(k + 1) + " (" + pa(target) + ")";
    if (target < 0.0) t.fail("cycles", entry + " is negative: piston stresses are compressive, >= 0 Pa");
    if (k == 0) {
      if (!(target > 0.0))
        t.fail("cycles", entry + " must be above 0: the piston starts unloaded, so the first branch is a loading");
    } else if (k % 2 == 1 && !(target < s.targets[k - 1])) {
      t.fail("cycles", entry + " follows a loading to " + pa(s.targets[k - 1]) +
                           ": the piston reverses there and unloads, so the stress must fall below it");
    } else if (k % 2 == 0 && !(target > s.targets[k - 1])) {
      t.fail("cycles", entry + " follows an unloading to " + pa(s.targets[k - 1]) +
                           ": the piston reverses there and loads, so the stress must rise above it");
    }
    if (target * piston_area > stop_force)
      t.fail("cycles", entry + " is " + format_significant(target * piston_area, 4) +
                           " N on the piston, above oedometer.stop_force = " + format_shortest(stop_force) +
                           " N (the run's safety stop): raise stop_force or lower the target (stresses are in Pa)");
  }
  const double largest = *std::max_element(s.targets.begin(), s.targets.end());
  s.modulus_stresses = t.number_list("modulus_stresses", {0.5 * largest});
  for (double v : s.modulus_stresses)
    if (!(v > 0.0)) t.fail("modulus_stresses", "every stress must be above 0 Pa, got " + pa(v));
  s.modulus_window = t.number_in("modulus_window", s.modulus_window, 1e-3, 0.5);
  return s;
}

}  // namespace colza
