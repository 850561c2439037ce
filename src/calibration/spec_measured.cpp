#include "calibration/spec_measured.hpp"

#include <algorithm>
#include <filesystem>

#include "analysis/polyfit.hpp"
#include "calibration/measured_csv.hpp"
#include "calibration/spec_fields.hpp"
#include "calibration/spec_model.hpp"

namespace colza::calibration {

namespace fs = std::filesystem;

namespace {

std::string fmt(double v) { return spec_number_text(v); }

// Measured values below or above these are taken for a unit slip (exit 2 before any run,
// where a slip used to surface as "outside what the design can reach" after the design runs):
// a seed bulk's density (kg/m^3; oilseeds ~350..800, the paper's rapeseed 651; g/cm^3 gives
// ~0.65) and the oedometer's initial stiffness c1 (N/m; the paper's cylinder ~1e6, the 40 mm
// test cylinder ~1e5; kN/m gives ~1e2..1e3).
constexpr double kLeastBulkDensity = 100.0, kMostBulkDensity = 2000.0;
constexpr double kLeastInitialStiffness = 1e3;

// measured.curve: c1 and c2 of F = c0 + c1 s + c2 s^2 fitted to the measured curve over the
// model's fit range (oedometer.fit_force_min .. _max), as a run's are.
void read_compression_curve(const ConfigNode& m, Spec& s, double u1, double u2) {
  Problem& p = s.problem;
  if (m.has("c1") || m.has("c2")) m.fail("curve", "give either the curve or c1 and c2, not both");
  s.measured_file = resolve_spec_path(s.file, string_or(m, "curve", ""));
  if (!fs::exists(s.measured_file)) m.fail("curve", "the measured curve " + s.measured_file + " does not exist");
  const std::string dcol = string_or(m, "displacement_column", "displacement");
  const std::string fcol = string_or(m, "force_column", "force");
  std::vector<std::size_t> lines;
  const auto cols = read_csv_columns(s.measured_file, {dcol, fcol}, s.file, "measured.curve", lines);
  require_increasing(cols[0], lines, dcol, s.measured_file, s.file, "measured.curve");
  const double fmin = s.base.oedometer.fit_force_min, fmax = s.base.oedometer.fit_force_max;
  // Units (colza reads m and N): a piston cannot travel further than the sample is high,
  // and a curve whose largest force is under 1 % of the fit range's top is in kN or a
  // lever's units, not one to shorten the fit range for.
  const double cylinder_height = s.base.oedometer.cylinder_height;
  if (cols[0].back() > cylinder_height)
    m.fail("curve", s.measured_file + ": the displacement reaches " + fmt(cols[0].back()) + ", more than the "
                        "sample's height oedometer.cylinder_height = " + fmt(cylinder_height) +
                        " m: colza reads " + dcol + " in m (mm / 1000)");
  const double peak = *std::max_element(cols[1].begin(), cols[1].end());
  if (!(peak > 0.0))
    m.fail("curve", s.measured_file + ": the curve has no positive force (" + fcol + " in N, compression "
                        "positive)");
  if (peak < 0.01 * fmax)
    m.fail("curve", s.measured_file + ": its largest force is " + fmt(peak) + " N, under 1 % of "
                        "oedometer.fit_force_max = " + fmt(fmax) + " N: colza reads " + fcol +
                        " in N (kN x 1000); is it in kN?");
  if (peak < fmax)
    m.fail("curve", s.measured_file + ": the curve never reaches its fit range: its largest force is " + fmt(peak) +
                        " N, the fit runs to oedometer.fit_force_max = " + fmt(fmax) +
                        " N; lower it in [model] set (e.g. \"oedometer.fit_force_max=" + fmt(0.95 * peak) +
                        "\") or supply the whole curve");
  const CompressionFit cf = fit_compression_curve(cols[0], cols[1], fmin, fmax);
  if (!cf.valid || cf.fit.points < 10)
    m.fail("curve", s.measured_file + ": too few points between " + fmt(fmin) + " and " + fmt(fmax) +
                        " N to fit F = c0 + c1 s + c2 s^2 (need >= 10)");
  p.targets.push_back({"c1", "N/m", cf.fit.coefficients[1], u1});
  p.targets.push_back({"c2", "N/m^2", cf.fit.coefficients[2], u2});
  s.measured_c0 = cf.fit.coefficients[0];
  s.measured_fit_r2 = cf.fit.r2;
  if (cf.fit.r2 < 0.95)
    s.warnings.push_back("the measured curve is poorly described by a quadratic (R^2 = " + fmt(cf.fit.r2) +
                         " < 0.95, the paper's simulated curves reach > 0.95): check the curve's units and range");
}

}  // namespace

Eigen::MatrixXd correlation_of_two(double rho) {
  Eigen::MatrixXd r = Eigen::MatrixXd::Identity(2, 2);
  r(0, 1) = r(1, 0) = rho;
  return r;
}

void read_measured_density(const ConfigNode& m, Spec& s) {
  Problem& p = s.problem;
  const double bulk = required_positive(m, "bulk_density");
  if (bulk < kLeastBulkDensity || bulk > kMostBulkDensity)
    m.fail("bulk_density", fmt(bulk) + " kg/m^3 is outside the " + fmt(kLeastBulkDensity) + ".." +
                               fmt(kMostBulkDensity) + " kg/m^3 of a seed bulk: colza reads kg/m^3 (0.651 g/cm^3 "
                               "is 651, the paper's rapeseed); is it in g/cm^3?");
  p.targets.push_back({"bulk_density", "kg/m^3", bulk, required_positive(m, "bulk_density_uncertainty")});
}

void read_measured_compression(const ConfigNode& m, Spec& s) {
  Problem& p = s.problem;
  const double u1 = required_positive(m, "c1_uncertainty"), u2 = required_positive(m, "c2_uncertainty");
  if (m.has("curve")) {
    read_compression_curve(m, s, u1, u2);
  } else {
    const double c1 = required_number(m, "c1");
    if (c1 < kLeastInitialStiffness)
      m.fail("c1", fmt(c1) + " N/m is below " + fmt(kLeastInitialStiffness) + " N/m: colza reads N/m (a bulk in "
                                 "the paper's cylinder starts near 1e6 N/m); is it in kN/m?");
    p.targets.push_back({"c1", "N/m", c1, u1});
    p.targets.push_back({"c2", "N/m^2", required_number(m, "c2"), u2});
  }
  // c1 and c2 come from one quadratic over the same range, so their errors are seldom
  // independent: from sample to sample a stiffer start (c1) goes with a flatter rise (c2).
  // [measured] correlation gives it (e.g. from repeated tests); not set: independent.
  s.correlation_given = m.has("correlation");
  if (s.correlation_given) {
    const double rho = required_number(m, "correlation");
    if (!(rho > -1.0 && rho < 1.0)) m.fail("correlation", "must lie strictly between -1 and 1, got " + fmt(rho));
    p.target_correlation = correlation_of_two(rho);
  }
}

}  // namespace colza::calibration
