// How a test's features move with its speed (physics.md section 8: two speeds a decade apart,
// both quasi-static, reveal a rate-dependent contact such as viscous damping; a rate-free
// model gives the same features within the realisation scatter).
//
// For each feature present at every speed v_k: its values, the least-squares slope of the
// feature against log10(v) (units of the feature per decade of speed), and the change from
// the slowest speed to the fastest relative to the slowest's magnitude (-; NaN when that is 0).
#pragma once
#include <map>
#include <string>
#include <vector>

namespace colza {

struct SpeedTrend {
  std::string feature;
  std::vector<double> values;    // one per speed, in the series' order
  double per_decade = 0.0;       // d feature / d log10(speed)
  double relative_change = 0.0;  // (f(v_max) - f(v_min)) / |f(v_min)|
};

// Why `speeds` (m/s) cannot make a series, or "" when they can: at least two, each positive
// and finite, none listed twice.
std::string speeds_problem(const std::vector<double>& speeds);

// speeds: as speeds_problem requires; features[k]: the features of the run at speeds[k].
// Throws std::invalid_argument otherwise (speeds_problem's reason), or when the lists' lengths differ.
std::vector<SpeedTrend> speed_trends(const std::vector<double>& speeds,
                                     const std::vector<std::map<std::string, double>>& features);

}  // namespace colza
