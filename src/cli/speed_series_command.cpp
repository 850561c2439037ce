#include "cli/speed_series_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "analysis/inertial_number.hpp"
#include "analysis/speed_series.hpp"
#include "calibration/run_cache.hpp"
#include "calibration/run_features.hpp"
#include "cli/command_common.hpp"
#include "config/config_error.hpp"
#include "core/concurrent.hpp"
#include "io/format_number.hpp"
#include "io/output_dir.hpp"
#include "io/scenario_inertial_numbers.hpp"
#include "io/summary.hpp"

namespace colza {

namespace {

Scenario series_scenario(const std::string& scenario) {
  if (scenario == "oedometer") return Scenario::kOedometer;
  if (scenario == "shear-series") return Scenario::kShear;
  if (scenario == "repose") return Scenario::kRepose;
  throw ConfigError("--speeds", "",
                    "`colza run " + scenario + "` has no speed series; oedometer, shear-series (each load of "
                    "shear_box.normal_stresses) and repose do");
}

// The config key the series sets at each speed (m/s).
const char* speed_key(Scenario s) {
  return s == Scenario::kOedometer ? "oedometer.piston_speed" : s == Scenario::kShear ? "shear_box.shear_speed" : "repose.lift_speed";
}

// The run's largest inertial number: the oedometer's at its largest piston stress, a shear
// series' at its smallest load, the repose lift's.
double largest_inertial_number(Scenario s, const RunConfig& c, const nlohmann::json& outputs) {
  InertialNumberInputs in;
  if (s == Scenario::kOedometer) {
    in = oedometer_inertial_inputs(c, outputs.at("packing_height").get<double>(), outputs.at("max_force").get<double>());
  } else if (s == Scenario::kShear) {
    in = shear_inertial_inputs(c, *std::min_element(c.shear_box.normal_stresses.begin(), c.shear_box.normal_stresses.end()));
  } else {
    in = repose_inertial_inputs(c, outputs.at("column_height").get<double>(), outputs.at("column_bulk_density").get<double>());
  }
  double value = std::numeric_limits<double>::quiet_NaN();
  inertial_number_json(in, value);
  return value;
}

struct SpeedRun {
  std::string run_id;
  double inertial_number = 0.0;
  calibration::Features features;
};

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

void print_trends(const std::vector<double>& speeds, const std::vector<SpeedRun>& runs,
                  const std::vector<SpeedTrend>& trends) {
  std::printf("speed series: %zu speeds (m/s):", speeds.size());
  for (std::size_t k = 0; k < speeds.size(); ++k)
    std::printf(" %s (I = %s)", format_significant(speeds[k], 4).c_str(),
                format_significant(runs[k].inertial_number, 3).c_str());
  std::printf("\n  %-40s %14s %12s\n", "feature", "per decade", "change");
  for (const SpeedTrend& t : trends)
    std::printf("  %-40s %14s %11s%%\n", t.feature.c_str(), format_significant(t.per_decade, 4).c_str(),
                std::isfinite(t.relative_change) ? format_significant(100.0 * t.relative_change, 3).c_str() : "-");
}

}  // namespace

int speed_series_command(const RunOptions& opt) {
  try {
    const Scenario scenario = series_scenario(opt.scenario);
    if (const std::string why = speeds_problem(opt.speeds); !why.empty()) throw ConfigError("--speeds", "", why);
    if (opt.config_path.empty() && scenario != Scenario::kOedometer)
      throw ConfigError("--config", "", "`colza run " + opt.scenario + " --speeds` needs a config file");
    std::vector<std::string> overrides = opt.overrides;
    if (opt.seed >= 0) overrides.push_back("seed=" + std::to_string(opt.seed));
    const RunConfig base = load_run_config(scenario, opt.config_path, overrides);  // bad input before any run
    for (const std::string& w : settings_warnings(base, scenario, scenario == Scenario::kShear, base.shear_box.normal_stresses))
      std::fprintf(stderr, "colza: warning: %s\n", w.c_str());

    OutputStaging out(opt.out_dir, opt.force);
    calibration::RunCache cache(out.path("runs"), !opt.quiet);
    std::vector<SpeedRun> runs(opt.speeds.size());
    std::vector<calibration::RunRequest> requests(opt.speeds.size());
    for (std::size_t k = 0; k < opt.speeds.size(); ++k) {
      calibration::RunRequest& r = requests[k];
      r.scenario = scenario;
      r.config_path = opt.config_path;
      r.overrides = overrides;
      r.overrides.push_back(std::string(speed_key(scenario)) + "=" + format_significant(opt.speeds[k], 17));
      // One sample for every speed: the oedometer's packing is settled once (the speed acts
      // only on the piston); the shear box's sample is shared by construction (run_cache.hpp);
      // the repose column is settled at each speed from the same seed, so it is the same.
      if (scenario == Scenario::kOedometer) r.shared_packing_overrides = overrides;
      r.needs_load_curves = scenario == Scenario::kShear;
      r.label = std::string(speed_key(scenario)) + " = " + format_significant(opt.speeds[k], 4);
    }
    run_concurrently(
        opt.speeds.size(), std::max(1, opt.jobs),
        [&](std::size_t k) {
          const calibration::RunRecord rec = cache.run(requests[k]);
          std::string fingerprint, packing;
          const RunConfig c = cache.config_for(requests[k], fingerprint, packing);
          runs[k].run_id = rec.id;
          runs[k].features = calibration::run_features_of(rec.outputs, rec.dir, scenario, c);
          runs[k].inertial_number = largest_inertial_number(scenario, c, rec.outputs);
        },
        opt.threads);

    std::vector<std::map<std::string, double>> features;
    for (const SpeedRun& r : runs) features.push_back(r.features);
    const std::vector<SpeedTrend> trends = speed_trends(opt.speeds, features);

    std::vector<std::string> warnings;
    for (std::size_t k = 0; k < runs.size(); ++k)
      if (runs[k].inertial_number > kQuasiStaticInertialNumber)
        warnings.push_back("at " + std::string(speed_key(scenario)) + " = " + format_significant(opt.speeds[k], 4) +
                           " m/s the inertial number is " + format_significant(runs[k].inertial_number, 3) + ", above " +
                           format_shortest(kQuasiStaticInertialNumber) +
                           ": that run is not quasi-static, so its features move with speed whatever the contact law");
    nlohmann::json s = common_summary(base, opt.scenario + " speed series", opt.threads);
    s["speed_key"] = speed_key(scenario);
    s["speeds"] = opt.speeds;
    nlohmann::json per_speed = nlohmann::json::array();
    for (std::size_t k = 0; k < runs.size(); ++k)
      per_speed.push_back({{"speed", opt.speeds[k]},
                           {"run", "runs/" + runs[k].run_id},
                           {"inertial_number", number_or_null(runs[k].inertial_number)}});
    s["runs"] = per_speed;
    nlohmann::json trend_json = nlohmann::json::array();
    for (const SpeedTrend& t : trends)
      trend_json.push_back({{"feature", t.feature},
                            {"values", t.values},
                            {"per_decade", number_or_null(t.per_decade)},
                            {"relative_change", number_or_null(t.relative_change)}});
    s["trends"] = trend_json;
    s["warnings"] = warnings;

    std::vector<std::string> columns{"speed", "inertial_number"}, units{"m/s", "-"};
    for (const SpeedTrend& t : trends) columns.push_back(t.feature), units.push_back("");
    Table table(columns, units);
    for (std::size_t k = 0; k < runs.size(); ++k) {
      std::vector<double> row{opt.speeds[k], runs[k].inertial_number};
      for (const SpeedTrend& t : trends) row.push_back(t.values[k]);
      table.add_row(row);
    }
    write_csv(out.path("speed_series.csv"), table);
    write_json(out.path("summary.json"), s);
    out.commit(opt.force ? earlier_run_outputs(opt.out_dir) : std::vector<std::string>{});
    print_trends(opt.speeds, runs, trends);
    for (const std::string& w : warnings) std::printf("  WARNING: %s\n", w.c_str());
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "colza: error: %s\n", e.what());
    return 2;
  }
  return 0;
}

}  // namespace colza
