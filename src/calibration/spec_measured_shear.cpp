#include "calibration/spec_measured.hpp"

#include <filesystem>
#include <set>

#include "analysis/mohr_coulomb.hpp"
#include "calibration/measured_csv.hpp"
#include "calibration/measured_shear_curve.hpp"
#include "calibration/spec_fields.hpp"
#include "calibration/spec_model.hpp"
#include "config/plausibility.hpp"
#include "io/load_label.hpp"

namespace colza::calibration {

namespace fs = std::filesystem;

namespace {

std::string fmt(double v) { return spec_number_text(v); }

// Measured values below or above these are taken for a unit slip (exit 2 before any run):
// the cohesion's uncertainty (Pa; a shear box resolves ~100 Pa, the paper's C is 11.41 kPa;
// kPa gives ~0.5) and tan(Phi)'s (-; tan(Phi) itself is ~0.5; an angle's uncertainty in
// degrees gives ~1..3).
constexpr double kLeastCohesionUncertainty = 10.0;
constexpr double kMostTanPhiUncertainty = 1.0;
// Least tau / sigma at failure of a granular bulk: tan(1 deg).
constexpr double kLeastStrengthRatio = 0.017;

// Why a normal stress `sigma` (Pa) read from the spec or its data is taken for kPa, or "".
std::string normal_stress_in_kpa(double sigma) {
  if (sigma >= kLeastLabNormalStress) return "";
  return "a normal stress of " + fmt(sigma) + " Pa, below " + fmt(kLeastLabNormalStress) +
         " Pa: colza reads Pa (25.75 kPa is 25750); are these kPa?";
}

// measured.strength and measured.peak_width: which strength the targets are made of.
void read_strength_definition(const ConfigNode& m, Spec& s) {
  s.strength.window = {s.base.shear_box.strength_window_start, s.base.shear_box.strength_window_end};
  const std::string kind = string_or(m, "strength", "window");
  if (kind == "peak")
    s.strength.peak = true;
  else if (kind != "window")
    m.fail("strength", "must be \"window\" (the mean over shear_box.strength_window_start .. _end, the paper's) or "
                       "\"peak\" (the largest mean over measured.peak_width), got \"" + kind + "\"");
  if (m.has("peak_width")) {
    if (!s.strength.peak) m.fail("peak_width", "only with strength = \"peak\"");
    s.strength.peak_width = required_positive(m, "peak_width");
  }
  if (s.strength.peak && !(s.strength.peak_width < s.base.shear_box.shear_displacement))
    m.fail("peak_width", "the peak width " + fmt(s.strength.peak_width) + " m must be shorter than the simulated "
                         "shear displacement (shear_box.shear_displacement = " +
                         fmt(s.base.shear_box.shear_displacement) + " m)");
}

struct MeasuredStrengths {
  std::vector<double> sigma, tau;  // Pa
};

// measured.results: a CSV of normal_stress, shear_strength (Pa).
MeasuredStrengths read_results_file(const ConfigNode& m, Spec& s) {
  MeasuredStrengths st;
  s.measured_file = resolve_spec_path(s.file, required_string(m, "results"));
  if (!fs::exists(s.measured_file))
    m.fail("results", "the measured shear results " + s.measured_file + " do not exist");
  const auto cols = read_csv_columns(s.measured_file, {"normal_stress", "shear_strength"}, s.file, "measured.results");
  st.sigma = cols[0], st.tau = cols[1];
  for (std::size_t k = 0; k < st.sigma.size(); ++k)
    if (!(st.sigma[k] > 0.0) || !(st.tau[k] > 0.0))
      m.fail("results", s.measured_file + ": normal stress and shear strength must be > 0 (Pa)");
  return st;
}

// [[measured.curves]]: one measured curve per normal load, its strength by s.strength.
MeasuredStrengths read_curves(const ConfigNode& m, Spec& s) {
  MeasuredStrengths st;
  const toml::array* curves = m.get("curves")->as_array();
  if (!curves || curves->empty())
    m.fail("curves", "must be a non-empty array of tables ([[measured.curves]] with normal_stress and file)");
  for (const auto& t : *curves)
    if (!t.is_table()) m.fail("curves", "must be an array of tables ([[measured.curves]])");
  for (const ConfigNode& c : m.table_array("curves")) {
    const double normal_stress = required_positive(c, "normal_stress");
    const std::string file = resolve_spec_path(s.file, required_string(c, "file"));
    const MeasuredShearCurve curve =
        read_measured_shear_curve(file, normal_stress, s.strength, s.file, c.full("file"), s.warnings,
                                  s.base.shear_box.length);
    if (!(curve.shear_strength > 0.0))
      c.fail("file", file + ": the shear strength (" + s.strength.describe() + ") is " + fmt(curve.shear_strength) +
                         " Pa; a shear strength must be > 0 (check the sign and units of shear_stress, Pa)");
    reject_unknown_spec_keys(c);
    st.sigma.push_back(normal_stress);
    st.tau.push_back(curve.shear_strength);
    s.measured_curves.push_back(curve);
  }
  return st;
}

// Units (colza reads Pa): a lab direct shear load is kilopascals, not tens of pascals, and
// at failure tau / sigma of a granular bulk is tan(Phi) plus cohesion over sigma, never
// below tan(1 deg) = 0.017. A column in kPa beside one in Pa breaks one or the other;
// refused here, before any design run is spent on loads of 26 Pa.
void check_strength_units(const ConfigNode& m, const std::string& source_key, const MeasuredStrengths& st) {
  const std::vector<double>& sigma = st.sigma;
  const std::vector<double>& tau = st.tau;
  for (std::size_t k = 0; k < sigma.size(); ++k) {
    if (const std::string why = normal_stress_in_kpa(sigma[k]); !why.empty()) m.fail(source_key, why);
    if (tau[k] / sigma[k] < kLeastStrengthRatio)
      m.fail(source_key, "a shear strength of " + fmt(tau[k]) + " Pa at a normal stress of " + fmt(sigma[k]) +
                             " Pa, tau / sigma = " + fmt(tau[k] / sigma[k]) + " < " + fmt(kLeastStrengthRatio) +
                             ": colza reads both in Pa; is the shear stress in kPa?");
  }
}

// measured.loads: the normal stresses of each design run's series (default: the lowest and
// the highest measured, the paper's).
void read_design_loads(const ConfigNode& m, Spec& s, const std::set<double>& measured) {
  s.loads = number_array(m, "loads");
  if (s.loads.empty()) s.loads = {*measured.begin(), *measured.rbegin()};  // the paper: lowest and highest
  if (std::set<double>(s.loads.begin(), s.loads.end()).size() < 2)
    m.fail("loads", "needs two or more distinct normal stresses (Pa)");
  for (double l : s.loads) {
    if (!(l > 0.0)) m.fail("loads", "normal stresses must be > 0 (Pa)");
    if (const std::string why = normal_stress_in_kpa(l); !why.empty()) m.fail("loads", why);
  }
  if (const std::string clash = loads_sharing_a_label(s.loads); !clash.empty()) m.fail("loads", clash);
}

// The correlation of the measured C and tan(Phi) errors.
double strength_correlation(const ConfigNode& m, Spec& s, const std::string& source_key,
                            const std::vector<double>& sigma) {
  // The measured C and tan(Phi) come from one line through the measured strengths: unless
  // the spec gives the correlation of their errors ([measured] correlation), it is that of
  // the line's intercept and slope for strengths of equal, independent uncertainty at the
  // measured loads (line_fit_correlation).
  double rho = line_fit_correlation(sigma)(0, 1);
  s.correlation_given = m.has("correlation");
  if (s.correlation_given) {
    rho = required_number(m, "correlation");
    if (!(rho > -1.0 && rho < 1.0)) m.fail("correlation", "must lie strictly between -1 and 1, got " + fmt(rho));
  } else if (1.0 - rho * rho < 1e-6) {
    m.fail(source_key, "the measured normal stresses are too close together for a Mohr-Coulomb line (C and "
                       "tan(Phi) correlate at " + fmt(rho) + ")");
  }
  return rho;
}

}  // namespace

void read_measured_shear(const ConfigNode& m, Spec& s) {
  Problem& p = s.problem;
  const double uc = required_positive(m, "cohesion_uncertainty"), ut = required_positive(m, "tan_phi_uncertainty");
  if (uc < kLeastCohesionUncertainty)
    m.fail("cohesion_uncertainty", fmt(uc) + " Pa is below " + fmt(kLeastCohesionUncertainty) +
                                       " Pa, finer than a shear box resolves: colza reads Pa (0.5 kPa is 500); is "
                                       "it in kPa?");
  if (ut >= kMostTanPhiUncertainty)
    m.fail("tan_phi_uncertainty", fmt(ut) + " is the uncertainty of tan(Phi), which is itself ~0.5 for seeds (the "
                                      "paper's tan 28.1 deg = 0.534): is it an angle in degrees? (2 deg at 28 deg "
                                      "is +/- 0.045 in tan(Phi): sec^2 Phi d Phi)");
  const bool has_results = m.has("results"), has_curves = m.has("curves");
  if (has_results && has_curves)
    m.fail("curves", "give either the shear strengths (results) or one curve per normal load (curves), not both");
  if (!has_results && !has_curves)
    m.fail("results", "missing: name the measured shear strengths (results = \"file.csv\", columns normal_stress, "
                      "shear_strength) or one curve per normal load ([[measured.curves]] with normal_stress and file)");
  const std::string source_key = has_results ? "results" : "curves";
  read_strength_definition(m, s);
  const MeasuredStrengths st = has_results ? read_results_file(m, s) : read_curves(m, s);
  check_strength_units(m, source_key, st);
  const std::vector<double>& sigma = st.sigma;
  const std::vector<double>& tau = st.tau;
  std::set<double> distinct(sigma.begin(), sigma.end());
  if (distinct.size() < 2)
    m.fail(source_key, "needs shear strengths at two or more distinct normal stresses for the Mohr-Coulomb line, "
                       "got " + std::to_string(distinct.size()));
  for (std::size_t k = 0; k < sigma.size(); ++k) s.measured_points.push_back({sigma[k], tau[k]});
  const MohrCoulombFit mc = fit_mohr_coulomb(sigma, tau);
  s.measured_fit_r2 = mc.r2;
  p.targets.push_back({"cohesion", "Pa", mc.cohesion, uc});
  p.targets.push_back({"tan_phi", "-", mc.slope, ut});
  read_design_loads(m, s, distinct);
  const double rho = strength_correlation(m, s, source_key, sigma);
  p.target_correlation = correlation_of_two(rho);
  if (mc.cohesion < 0.0)
    s.warnings.push_back("the measured line has a negative cohesion (" + fmt(mc.cohesion) + " Pa): check the data");
}

}  // namespace colza::calibration
