// The rows of an ensemble comparison (crosscheck/README.md, "Ensembles"): a mean with its
// standard error, and a row judged by Welch's t.
#pragma once
#include <cmath>
#include <string>
#include "ensemble_stats.hpp"
#include "report.hpp"

namespace crosscheck {

// "21.910 +- 0.780"
inline std::string mean_and_error(double mean, double se, const char* f = "%.3f") {
  return fmt(mean, f) + " +- " + fmt(se, f);
}

// A row that passes when |t| <= t_max; `note` follows the t in the difference column.
inline void check_t(Report& report, const std::string& metric, const std::string& colza, const std::string& yade,
                    const MeanDifference& d, const std::string& note, double t_max) {
  const bool pass = std::isfinite(d.t) && std::abs(d.t) <= t_max;
  report.add(Row{metric, colza, yade, "t = " + fmt(d.t, "%.2f") + note, "|t| <= " + fmt(t_max, "%g"), pass, false});
}

}  // namespace crosscheck
