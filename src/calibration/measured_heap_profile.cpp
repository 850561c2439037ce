#include "calibration/measured_heap_profile.hpp"

#include <cmath>

#include "calibration/measured_csv.hpp"
#include "config/config_error.hpp"
#include "core/types.hpp"
#include "io/format_number.hpp"
#include "scenario/repose.hpp"

namespace colza::calibration {

HeapAngle measured_heap_angle(const std::string& csv, const RunConfig& model, const std::string& spec_file,
                              const std::string& key) {
  const auto cols =
      read_csv_columns_with_optional(csv, {kHeapRhoColumn, kHeapTopColumn}, {kHeapAzimuthColumn}, spec_file, key);
  const bool azimuths = !cols[2].empty();  // a column the header names has a value per row (at least one)
  const std::size_t n = cols[0].size();
  if (n < 5) throw ConfigError(spec_file, key, csv + ": a heap profile needs at least 5 points, it has " + std::to_string(n));
  std::vector<double> x(n), y(n, 0.0), z = cols[1], radius(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double rho = cols[0][i];
    if (rho < 0.0) throw ConfigError(spec_file, key, csv + ": rho " + format_shortest(rho) + " is negative (a distance from the axis)");
    const double a = azimuths ? cols[2][i] * kPi / 180.0 : 0.0;
    x[i] = rho * std::cos(a);
    y[i] = rho * std::sin(a);
  }
  HeapFitSettings s = repose_fit_settings(model.repose, 0.0);  // a profile's tops stand above its base
  if (!azimuths) s.sectors = 1;
  s.centre_x = s.centre_y = 0.0;
  const double mean_diameter = 0.5 * (model.particle.diameter_min + model.particle.diameter_max);
  s.bin_width = mean_diameter;
  s.toe_height = 2.0 * mean_diameter;
  const HeapAngle h = fit_heap_angle(x, y, z, radius, s);
  if (!h.valid)
    throw ConfigError(spec_file, key,
                      csv + ": no cone fits this profile (its radius is under 3 mean diameters of the model's particles, " +
                          format_significant(mean_diameter, 4) + " m, or fewer than 5 surface points lie between repose.fit_inner and "
                          "fit_outer of it; rho and top are in metres)");
  return h;
}

}  // namespace colza::calibration
