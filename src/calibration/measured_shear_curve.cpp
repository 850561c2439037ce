#include "calibration/measured_shear_curve.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "calibration/measured_csv.hpp"
#include "config/config_error.hpp"
#include "io/format_number.hpp"

namespace colza::calibration {

namespace {

std::string fmt(double v) { return format_significant(v, 6); }

// Largest / smallest displacement step between consecutive rows inside the window; above
// this the plain mean of the rows weights the densely sampled part more than the simulation
// (evenly spaced time steps) does.
constexpr double kUnevenStepRatio = 1.5;

}  // namespace

std::string StrengthDefinition::describe() const {
  if (peak)
    return "peak strength: the largest mean shear stress of the rows within a trailing shear displacement interval "
           "of " + fmt(peak_width) + " m";
  return "mean shear stress of the rows with shear displacement in the strength window " + fmt(window.start) + " .. " +
         fmt(window.end) + " m";
}

double curve_strength(const std::vector<double>& displacement, const std::vector<double>& shear_stress,
                      const StrengthDefinition& definition, std::size_t& samples, double& peak_displacement) {
  if (definition.peak) {
    const ShearPeak p = peak_shear_strength(displacement, shear_stress, definition.peak_width);
    samples = p.samples;
    peak_displacement = p.displacement;
    return p.value;
  }
  const ShearStrengthMean mean = shear_strength_of_curve(displacement, shear_stress, definition.window);
  samples = mean.samples();
  peak_displacement = 0.0;
  return mean.value();
}

MeasuredShearCurve read_measured_shear_curve(const std::string& csv, double normal_stress,
                                             const StrengthDefinition& strength, const std::string& spec_file,
                                             const std::string& key, std::vector<std::string>& warnings,
                                             double box_length) {
  const StrengthWindow window = strength.window;
  if (!std::filesystem::exists(csv))
    throw ConfigError(spec_file, key, "the measured shear curve " + csv + " does not exist");
  std::vector<std::size_t> lines;
  const auto cols = read_csv_columns(csv, {kShearDisplacementColumn, kShearStressColumn}, spec_file, key, lines);
  const std::vector<double>& d = cols[0];
  const std::vector<double>& tau = cols[1];
  MeasuredShearCurve c;
  c.file = csv;
  c.normal_stress = normal_stress;
  c.rows = d.size();
  require_increasing(d, lines, kShearDisplacementColumn, csv, spec_file, key);
  c.max_displacement = d.back();
  // A box cannot be sheared by more than its length: such a column is not in metres.
  if (c.max_displacement > box_length)
    throw ConfigError(spec_file, key, csv + ": the shear displacement reaches " + fmt(c.max_displacement) +
                                          ", more than the box's length shear_box.length = " + fmt(box_length) +
                                          " m: colza reads shear_displacement in m (mm / 1000) and shear_stress in Pa");
  c.shear_strength = curve_strength(d, tau, strength, c.window_points, c.peak_displacement);
  if (strength.peak) {
    if (c.window_points == 0)
      throw ConfigError(spec_file, key, csv + ": the curve spans " + fmt(d.back() - d.front()) +
                                            " m of shear displacement, less than the peak width " +
                                            fmt(strength.peak_width) + " m (measured.peak_width): supply the whole "
                                            "curve, or narrow the peak width");
    if (c.window_points < 2)
      throw ConfigError(spec_file, key, csv + ": 1 row inside the peak's interval of " + fmt(strength.peak_width) +
                                            " m; at least 2 are needed for a mean shear stress: supply a curve "
                                            "sampled more densely, or widen measured.peak_width");
    if (c.peak_displacement > d.back() - strength.peak_width)
      warnings.push_back(csv + ": the largest mean lies in the curve's last " + fmt(strength.peak_width) +
                         " m: the curve may not have reached its peak (supply the whole curve)");
    return c;
  }
  if (c.max_displacement < window.end)
    throw ConfigError(spec_file, key, csv + ": the curve ends at a shear displacement of " + fmt(c.max_displacement) +
                                          " m, but the strength window needs it to reach " + fmt(window.end) +
                                          " m (shear_box.strength_window_end; window " + fmt(window.start) + " .. " +
                                          fmt(window.end) + " m): supply the whole curve, or end the window earlier "
                                          "for the simulation and the measurement alike in the spec's [model] set");
  if (c.window_points < 2)
    throw ConfigError(spec_file, key, csv + ": " + std::to_string(c.window_points) + " row(s) inside the strength "
                                          "window " + fmt(window.start) + " .. " + fmt(window.end) +
                                          " m; at least 2 are needed for a mean shear stress: supply a curve sampled "
                                          "more densely");
  double step_min = 0.0, step_max = 0.0;
  bool first = true;
  for (std::size_t k = 1; k < d.size(); ++k) {
    if (!window.contains(d[k]) || !window.contains(d[k - 1])) continue;
    const double step = d[k] - d[k - 1];
    step_min = first ? step : std::min(step_min, step);
    step_max = first ? step : std::max(step_max, step);
    first = false;
  }
  if (!first && step_max > kUnevenStepRatio * step_min)
    warnings.push_back(csv + ": the rows inside the strength window are unevenly spaced (displacement steps " +
                       fmt(step_min) + " .. " + fmt(step_max) + " m); the shear strength is their plain mean, as for "
                       "the simulation's evenly spaced samples: resample the curve at even displacement steps");
  return c;
}

}  // namespace colza::calibration
