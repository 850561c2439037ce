#include "analysis/speed_series.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "io/format_number.hpp"

namespace colza {

std::string speeds_problem(const std::vector<double>& speeds) {
  if (speeds.size() < 2) return "a speed series needs at least two speeds (m/s), e.g. --speeds 0.0005,0.005";
  for (std::size_t k = 0; k < speeds.size(); ++k) {
    if (!(speeds[k] > 0.0) || !std::isfinite(speeds[k]))
      return "speed " + format_shortest(speeds[k]) + " is not a positive speed (m/s)";
    for (std::size_t j = 0; j < k; ++j)
      if (speeds[j] == speeds[k]) return "speed " + format_shortest(speeds[k]) + " is listed twice";
  }
  return "";
}

std::vector<SpeedTrend> speed_trends(const std::vector<double>& speeds,
                                     const std::vector<std::map<std::string, double>>& features) {
  if (const std::string why = speeds_problem(speeds); !why.empty()) throw std::invalid_argument(why);
  if (features.size() != speeds.size()) throw std::invalid_argument("one feature set per speed is needed");
  const auto slowest = static_cast<std::size_t>(std::min_element(speeds.begin(), speeds.end()) - speeds.begin());
  const auto fastest = static_cast<std::size_t>(std::max_element(speeds.begin(), speeds.end()) - speeds.begin());
  double mean_log = 0.0;
  for (double v : speeds) mean_log += std::log10(v);
  mean_log /= static_cast<double>(speeds.size());
  double sxx = 0.0;
  for (double v : speeds) sxx += (std::log10(v) - mean_log) * (std::log10(v) - mean_log);
  std::vector<SpeedTrend> trends;
  for (const auto& [name, first] : features.front()) {
    SpeedTrend t;
    t.feature = name;
    for (const auto& f : features) {
      const auto it = f.find(name);
      if (it == f.end()) break;
      t.values.push_back(it->second);
    }
    if (t.values.size() != speeds.size()) continue;
    double mean_value = 0.0;
    for (double y : t.values) mean_value += y;
    mean_value /= static_cast<double>(t.values.size());
    double sxy = 0.0;
    for (std::size_t k = 0; k < speeds.size(); ++k) sxy += (std::log10(speeds[k]) - mean_log) * (t.values[k] - mean_value);
    t.per_decade = sxy / sxx;
    const double base = t.values[slowest];
    t.relative_change = base != 0.0 ? (t.values[fastest] - base) / std::abs(base) : std::numeric_limits<double>::quiet_NaN();
    trends.push_back(std::move(t));
  }
  return trends;
}

}  // namespace colza
