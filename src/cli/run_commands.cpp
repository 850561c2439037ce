#include "cli/run_commands.hpp"

#include "cli/command_common.hpp"
#include "cli/plot_command.hpp"
#include "cli/repose_command.hpp"
#include "cli/shear_commands.hpp"
#include "cli/speed_series_command.hpp"

#include <chrono>
#include <cstdio>
#include <iostream>

#include "analysis/inertial_number.hpp"
#include "config/run_config.hpp"
#include "core/unstable_motion.hpp"
#include "core/version.hpp"
#include "contact/slot_registry.hpp"
#include "io/format_number.hpp"
#include "io/hdf5_writer.hpp"
#include "io/lab_features_json.hpp"
#include "io/output_dir.hpp"
#include "io/scenario_inertial_numbers.hpp"
#include "io/packing_file.hpp"
#include "io/summary.hpp"
#include "scenario/oedometer.hpp"
#include "scenario/scene.hpp"

namespace colza {

namespace {

// What a user must not miss in an oedometer result: printed as WARNING lines and kept in
// summary.json's "warnings".
std::vector<std::string> oedometer_warnings(const RunConfig& c, const OedometerResult& r, double inertial_number) {
  std::vector<std::string> w = settings_warnings(c, Scenario::kOedometer, /*series=*/false);
  if (r.settling.in_this_run() && !r.settling.converged) w.push_back(settling_warning(c, r.settling));
  // A sample cut at the rim stands within a sphere of it; one that stops short was not cut
  // level, and its rough top counts in bulk_density (a walk-through's 1000 spheres: 572 kg/m^3
  // against 660 for the paper's sample, 667 by the mean height of its top).
  const double rim = c.oedometer.cylinder_height;
  if (r.packing_height < rim - c.particle.diameter_max)
    w.push_back("the sample's top, " + format_significant(1e3 * r.packing_height, 4) + " mm, lies more than " +
                "particle.diameter_max below the rim, oedometer.cylinder_height = " + format_significant(1e3 * rim, 4) +
                " mm: it was not cut level, so bulk_density (particle mass / (cylinder area x the highest sphere's "
                "top)) counts its rough top as sample and reads low; " +
                (r.settling.in_this_run() ? "generate more spheres (sample.count)" : "load a packing that fills the cylinder"));
  const OedometerCycleSpec& cycles = c.oedometer.cycles;
  if (!r.fit.reached_force_max && !cycles.enabled())  // with cycles their first target ends the fit's range
    w.push_back("the force never reached fit_force_max = " + format_shortest(c.oedometer.fit_force_max) +
                " N; the fit covers a shorter range");
  if (cycles.enabled() && r.targets_reached < cycles.targets.size())
    w.push_back("the run stopped (" + r.stop_reason + ") after " + std::to_string(r.targets_reached) + " of the " +
                std::to_string(cycles.targets.size()) + " targets of oedometer.cycles: the later branches are missing");
  if (inertial_number > kQuasiStaticInertialNumber)
    w.push_back("the inertial number at the largest piston stress is " + format_significant(inertial_number, 3) +
                ", above " + format_shortest(kQuasiStaticInertialNumber) +
                ": the test is not quasi-static and its curve depends on oedometer.piston_speed");
  return w;
}

// One line per branch and per cycle of a load-unload run (the numbers of summary.json's
// load_unload, in kPa, MPa and per cent).
void print_load_unload(const LoadUnloadAnalysis& a) {
  for (std::size_t k = 0; k < a.branches.size(); ++k) {
    const CurveBranch& b = a.branches[k];
    std::printf("  branch %zu (%s): %.2f -> %.2f kPa, strain %.4f -> %.4f %%", k, b.loading ? "loading" : "unloading",
                1e-3 * b.stress_start, 1e-3 * b.stress_end, 100.0 * b.strain_start, 100.0 * b.strain_end);
    for (const LocalModulus& m : b.moduli)
      std::printf("; at %.4g kPa M = %.4g MPa, K = %.3f", 1e-3 * m.stress, 1e-6 * m.modulus, m.lateral_ratio);
    std::printf("\n");
  }
  for (const LoadUnloadCycle& cy : a.cycles)
    std::printf("  cycle (branches %zu-%zu): loop area %.4g J/m^3, permanent strain %.4f %%, rebound %.4f %%\n",
                cy.loading_branch, cy.unloading_branch, cy.loop_area, 100.0 * cy.permanent_strain,
                100.0 * cy.rebound_strain);
}

void run_oedometer_scenario(const RunConfig& c, const RunOptions& opt, OutputStaging& out) {
  Progress progress(!opt.quiet);
  const OedometerResult r = run_oedometer(c, progress, c.output.snapshot_interval);
  nlohmann::json s = common_summary(c, "oedometer", opt.threads);
  s["particles_generated"] = r.particles_generated;
  s["particles"] = r.particles;
  s["packing_height"] = r.packing_height;
  s["bulk_density"] = r.bulk_density;
  if (r.settling.in_this_run()) s["settling"] = settling_json(c, r.settling);  // absent for a packing file
  s["bond_install"] = to_string(c.contact.bond_install);
  s["bonds_installed"] = r.bonds_installed;
  s["bonds_broken_tension"] = r.bonds_broken_tension;
  s["bonds_broken_shear"] = r.bonds_broken_shear;
  nlohmann::json fit = {{"valid", r.fit.valid},
                        {"force_min", c.oedometer.fit_force_min},
                        {"force_max", c.oedometer.fit_force_max},
                        {"reached_force_max", r.fit.reached_force_max},
                        {"zero_displacement", r.fit.zero_displacement},
                        {"points", r.fit.fit.points}};
  if (r.fit.valid) {
    fit["c0"] = r.fit.fit.coefficients[0];
    fit["c1"] = r.fit.fit.coefficients[1];
    fit["c2"] = r.fit.fit.coefficients[2];
    fit["r2"] = r.fit.fit.r2;
  }
  s["fit"] = fit;
  double inertial_number = 0.0;
  s["inertial_number"] = inertial_number_json(oedometer_inertial_inputs(c, r.packing_height, r.max_force), inertial_number);
  if (c.oedometer.cycles.enabled()) {
    nlohmann::json cycles = load_unload_json(r.cycles, simulated_cycle_settings(c.oedometer.cycles));
    cycles["targets"] = c.oedometer.cycles.targets;
    cycles["targets_reached"] = r.targets_reached;
    cycles["packing_height"] = r.packing_height;
    s["load_unload"] = cycles;
  }
  const std::vector<std::string> warnings = oedometer_warnings(c, r, inertial_number);
  s["warnings"] = warnings;
  s["max_force"] = r.max_force;
  s["stop_reason"] = r.stop_reason;
  s["dt"] = r.dt_min;
  s["dt_max"] = r.dt_max;
  s["steps"] = r.steps;
  add_snapshots_summary(s, r.snapshots);
  add_timing(s, r.stages);

  write_csv(out.path("curve.csv"), r.curve);
  write_packing(out.path("packing.txt"), r.settled);
  write_result_h5(out, "oedometer", c, s, "curve", r.curve,
                  {{"particles/settled", &r.settled}, {"particles/final", &r.final_state}}, &r.snapshots);
  write_json(out.path("summary.json"), s);

  if (c.oedometer.packing_file.empty())
    std::printf("oedometer: %zu particles (%zu generated), bulk density %.1f kg/m^3, settling %s after %.3f s\n",
                r.particles, r.particles_generated, r.bulk_density,
                r.settling.converged ? "converged" : "DID NOT converge", r.settling.simulated_time);
  else
    std::printf("oedometer: %zu particles (of %zu read from %s), bulk density %.1f kg/m^3\n", r.particles,
                r.particles_generated, c.oedometer.packing_file.c_str(), r.bulk_density);
  // The fit ends at fit_force_max, or at the largest force when the run stopped below it.
  const double fit_end = r.fit.reached_force_max ? c.oedometer.fit_force_max : r.max_force;
  std::printf("  max piston force %.1f N (stop: %s); fit F = c0 + c1 s + c2 s^2 over %.0f..%.0f N:", r.max_force,
              r.stop_reason.c_str(), c.oedometer.fit_force_min, fit_end);
  if (r.fit.valid)
    std::printf(" c0 = %.4g N, c1 = %.4g N/m, c2 = %.4g N/m^2, R^2 = %.4f\n", r.fit.fit.coefficients[0],
                r.fit.fit.coefficients[1], r.fit.fit.coefficients[2], r.fit.fit.r2);
  else
    std::printf(" not enough points above %.0f N\n", c.oedometer.fit_force_min);
  if (c.oedometer.cycles.enabled()) print_load_unload(r.cycles);
  std::printf("  inertial number %.3g at the largest piston stress\n", inertial_number);
  for (const std::string& warning : warnings) std::printf("  WARNING: %s\n", warning.c_str());
  std::printf("  %llu steps, dt %.3g..%.3g s, %.1f s wall, %.3g particle-steps/s\n",
              static_cast<unsigned long long>(r.steps), r.dt_min, r.dt_max, total_wall_seconds(r.stages),
              overall_rate(r.stages));
}

void run_scene_scenario(const RunConfig& c, const RunOptions& opt, OutputStaging& out) {
  Progress progress(!opt.quiet);
  const SceneResult r = run_scene(c, progress, c.output.snapshot_interval);
  nlohmann::json s = common_summary(c, "scene", opt.threads);
  s["particles"] = r.final_state.size();
  s["walls"] = c.scene.walls.size();
  s["bonds_installed"] = r.bonds_installed;
  s["dt"] = r.dt;
  s["steps"] = r.steps;
  s["stopped_by_condition"] = r.stopped_by_condition;
  add_snapshots_summary(s, r.snapshots);
  add_timing(s, r.stages);
  write_csv(out.path("series.csv"), r.series);
  write_result_h5(out, "scene", c, s, "series", r.series, {{"particles/final", &r.final_state}}, &r.snapshots);
  write_packing(out.path("packing.txt"), r.final_state);
  write_json(out.path("summary.json"), s);
  std::printf("scene: %zu particles, %zu walls, %llu steps of %.4g s, %.2f s wall\n", r.final_state.size(),
              c.scene.walls.size(), static_cast<unsigned long long>(r.steps), r.dt, total_wall_seconds(r.stages));
}

}  // namespace

int run_command(const RunOptions& opt) {
  if (!opt.speeds.empty()) return speed_series_command(opt);
  const Scenario scenario = opt.scenario == "scene"       ? Scenario::kScene
                            : opt.scenario == "oedometer" ? Scenario::kOedometer
                            : opt.scenario == "repose"    ? Scenario::kRepose
                                                          : Scenario::kShear;
  const bool series = opt.scenario == "shear-series";
  RunConfig config;
  try {
    std::vector<std::string> overrides = opt.overrides;
    if (opt.seed >= 0) overrides.push_back("seed=" + std::to_string(opt.seed));
    if (opt.config_path.empty() && scenario != Scenario::kOedometer)
      throw ConfigError("--config", "", "`colza run " + opt.scenario +
                                            "` needs a config file (the built-in defaults are the oedometer's); "
                                            "the paper's shear box is data/shear.toml");
    config = load_run_config(scenario, opt.config_path, overrides);
    if (opt.out_dir.empty()) throw ConfigError("--out", "", "an output directory is required");
    if (scenario == Scenario::kShear && !series && !(opt.normal_stress > 0.0))
      throw ConfigError("--normal-stress", "", "`colza run shear` needs --normal-stress PA (> 0)");
    if (scenario == Scenario::kShear && !series && config.shear_box.preconsolidation_stress > 0.0 &&
        opt.normal_stress > config.shear_box.preconsolidation_stress)
      throw ConfigError("--normal-stress", "", format_shortest(opt.normal_stress) + " Pa is above "
                        "shear_box.preconsolidation_stress = " + format_shortest(config.shear_box.preconsolidation_stress) +
                        " Pa: a sample is preconsolidated at a stress above the load it is sheared at");
    check_output_dir(opt.out_dir, opt.force, "run", series ? "sample.json" : "");  // a stopped series is resumed
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "colza: error: %s\n", e.what());
    return 2;
  }
  // Before the run, so that a unit slip can be stopped at once; the summaries keep them too.
  const std::vector<double> stresses = scenario != Scenario::kShear ? std::vector<double>{}
                                       : series                     ? config.shear_box.normal_stresses
                                                                    : std::vector<double>{opt.normal_stress};
  for (const std::string& w : settings_warnings(config, scenario, series, stresses))
    std::fprintf(stderr, "colza: warning: %s\n", w.c_str());
  try {
    if (series) {
      const int code = run_shear_series(config, opt);
      if (code == 0 && config.output.plots) plot_after_run(opt.out_dir, opt.quiet);
      return code;
    }
    OutputStaging out(opt.out_dir, opt.force);
    if (scenario == Scenario::kOedometer) run_oedometer_scenario(config, opt, out);
    else if (scenario == Scenario::kShear) run_shear_scenario(config, opt, out);
    else if (scenario == Scenario::kRepose) run_repose_scenario(config, opt, out);
    else run_scene_scenario(config, opt, out);
    // --force: the earlier result's files that this run does not write go too.
    out.commit(opt.force ? earlier_run_outputs(opt.out_dir) : std::vector<std::string>{});
    if (config.output.plots) plot_after_run(opt.out_dir, opt.quiet);
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "colza: error: %s\n", e.what());
    return 2;
  } catch (const UnstableMotion& e) {
    if (!e.fixed_time_step_too_large()) throw;  // main reports it, exit 1
    const ConfigError blame(config.origin_of("integration.time_step"), "integration.time_step",
                            "the fixed time step exceeds the critical estimate and the motion blew up: " +
                                std::string(e.what()) + "; the unfinished outputs were removed, earlier results are untouched");
    std::fprintf(stderr, "colza: error: %s\n", blame.what());
    return 2;
  }
  return 0;
}

}  // namespace colza
