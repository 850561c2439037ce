#include "calibration/measured_report.hpp"

#include <cstdio>
#include <sstream>

#include "io/format_number.hpp"

namespace colza::calibration {

namespace {

std::string g(double v, int digits = 6) { return format_significant(v, digits); }

std::string shear_source(const Spec& s) { return s.measured_curves.empty() ? "results" : "curves"; }

// Load_unload, repose: each target stated or read off the measured curve.
nlohmann::json feature_targets_summary(const Spec& s) {
  nlohmann::json m;
  m["source"] = s.measured_file.empty() ? "values" : "curve";
  if (!s.measured_file.empty()) {
    m["file"] = s.measured_file;
    m["curve_features"] = s.measured_curve_features;
  }
  m["targets_from_curve"] = s.targets_from_curve;
  return m;
}

std::string feature_targets_section(const Spec& s) {
  std::ostringstream o;
  if (!s.measured_file.empty())
    o << "Features of the measured curve `" << s.measured_file << "`, reduced by the code that reduces the runs' "
      << "(in the model's geometry):\n\n| feature | value |\n|---|---|\n";
  for (const auto& [name, value] : s.measured_curve_features) o << "| " << name << " | " << g(value) << " |\n";
  o << (s.measured_file.empty() ? "" : "\n") << "Targets:\n\n| feature | measured | uncertainty | from |\n|---|---|---|---|\n";
  for (const auto& t : s.problem.targets)
    o << "| " << t.name << " | " << g(t.value) << " | " << g(t.uncertainty) << " | "
      << (s.targets_from_curve.count(t.name) ? "the curve" : "the spec") << " |\n";
  return o.str();
}

}  // namespace

nlohmann::json measured_data_summary(const Spec& s) {
  nlohmann::json m;
  switch (s.stage) {
    case Stage::kDensity:
      m["source"] = "value";
      break;
    case Stage::kCompression:
      m["source"] = s.measured_file.empty() ? "coefficients" : "curve";
      if (!s.measured_file.empty()) {
        m["file"] = s.measured_file;
        m["fit_force_range"] = {s.base.oedometer.fit_force_min, s.base.oedometer.fit_force_max};
        m["c0"] = s.measured_c0;
        m["fit_r2"] = s.measured_fit_r2;
      }
      break;
    case Stage::kShear: {
      m["source"] = shear_source(s);
      m["strengths"] = nlohmann::json::array();
      if (s.measured_curves.empty()) {
        m["file"] = s.measured_file;
        for (const auto& [sigma, tau] : s.measured_points)
          m["strengths"].push_back({{"normal_stress", sigma}, {"shear_strength", tau}});
      } else {
        for (const auto& c : s.measured_curves) {
          nlohmann::json j = {{"normal_stress", c.normal_stress},
                              {"shear_strength", c.shear_strength},
                              {"file", c.file},
                              {"rows", c.rows},
                              {s.strength.peak ? "rows_in_peak_interval" : "rows_in_window", c.window_points},
                              {"max_displacement", c.max_displacement}};
          if (s.strength.peak) j["peak_displacement"] = c.peak_displacement;
          m["strengths"].push_back(j);
        }
      }
      m["strength"] = s.strength.peak ? "peak" : "window";
      if (s.strength.peak)
        m["peak_width"] = s.strength.peak_width;
      else
        m["strength_window"] = {s.strength.window.start, s.strength.window.end};
      m["strength_definition"] = s.strength.describe();
      m["line_r2"] = s.measured_fit_r2;
      m["loads_simulated"] = s.loads;
      break;
    }
    case Stage::kLoadUnload:
    case Stage::kRepose:
      m = feature_targets_summary(s);
      break;
  }
  return m;
}

std::string measured_data_section(const Spec& s) {
  std::ostringstream o;
  o << "## Measured data\n\n";
  switch (s.stage) {
    case Stage::kDensity:
      o << "Bulk density stated in the spec.\n";
      break;
    case Stage::kCompression:
      if (s.measured_file.empty()) {
        o << "c1 and c2 stated in the spec.\n";
      } else {
        o << "c1 and c2 from the measured curve `" << s.measured_file << "`, fitted F = c0 + c1 s + c2 s^2 over "
          << g(s.base.oedometer.fit_force_min) << " .. " << g(s.base.oedometer.fit_force_max) << " N (as the "
          << "simulated curves): c0 = " << g(s.measured_c0) << " N, R^2 = " << g(s.measured_fit_r2, 4) << ".\n";
      }
      break;
    case Stage::kShear:
      if (s.measured_curves.empty()) {
        // colza cannot see how the lab read its strengths off its curves: it says what the
        // runs' strengths are, which the lab's must match for the comparison to hold.
        o << "Shear strengths read from `" << s.measured_file << "` as the lab stated them; the simulated ones "
          << "they are compared with are the " << s.strength.describe()
          << " (the lab's must be read off its curves the same way; with the curves themselves, colza does "
             "it):\n\n| normal stress (Pa) | shear strength (Pa) |\n"
          << "|---|---|\n";
        for (const auto& [sigma, tau] : s.measured_points) o << "| " << g(sigma) << " | " << g(tau) << " |\n";
      } else {
        o << "Shear strengths derived from the measured curves as for the simulated ones: the "
          << s.strength.describe() << ".\n\n| normal stress (Pa) | shear strength (Pa) | curve | rows in "
          << (s.strength.peak ? "the peak's interval" : "window") << " / rows | curve ends at (m) |"
          << (s.strength.peak ? " peak's interval ends at (m) |" : "") << "\n|---|---|---|---|---|"
          << (s.strength.peak ? "---|" : "") << "\n";
        for (const auto& c : s.measured_curves) {
          o << "| " << g(c.normal_stress) << " | " << g(c.shear_strength) << " | `" << c.file << "` | "
            << c.window_points << " / " << c.rows << " | " << g(c.max_displacement) << " |";
          if (s.strength.peak) o << " " << g(c.peak_displacement) << " |";
          o << "\n";
        }
      }
      o << "\nC and tan(Phi) are the least-squares line through these points (R^2 = " << g(s.measured_fit_r2, 4)
        << ").\n";
      break;
    case Stage::kLoadUnload:
    case Stage::kRepose:
      o << feature_targets_section(s);
      break;
  }
  return o.str();
}

}  // namespace colza::calibration
