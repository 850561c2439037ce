// colza command line. Exit codes: 0 success, 1 internal failure, 2 bad input.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <limits>
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "cli/calibrate_command.hpp"
#include "cli/diagnose_command.hpp"
#include "cli/features_command.hpp"
#include "cli/plot_command.hpp"
#include "cli/run_commands.hpp"
#include "config/config_error.hpp"
#include "core/cpu_model.hpp"
#include "core/interrupt.hpp"
#include "core/unstable_motion.hpp"
#include "core/version.hpp"
#include "core/kernel_isa.hpp"
#include "io/output_error.hpp"

namespace {

// A run that failed for a reason of its own, not a bug of colza's (exit 1).
int run_failed(const std::exception& e) {
  std::fprintf(stderr, "colza: error: %s; the unfinished outputs were removed, earlier results are untouched\n",
               e.what());
  return 1;
}

// Worker threads when --threads is not given: OMP_NUM_THREADS if set, else the machine's
// cores shared among the concurrent jobs. The simulation is the same bit for bit at any
// count (ARCHITECTURE.md, Performance; only the damping-energy total is summed per thread
// range), so the default only decides the speed.
int default_worker_threads(int jobs) {
  if (const char* env = std::getenv("OMP_NUM_THREADS"); env && std::atoi(env) > 0) return std::atoi(env);
#ifdef _OPENMP
  return std::max(1, omp_get_num_procs() / std::max(1, jobs));
#else
  (void)jobs;
  return 1;
#endif
}

// Validators whose messages read well (CLI11's PositiveNumber prints its range as
// 0 .. 1.797...e308 and lets 0 through for integers).
CLI::Validator whole_number(long long lowest, long long highest) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        try {
          std::size_t used = 0;
          const long long v = std::stoll(text, &used);
          if (used == text.size() && v >= lowest && v <= highest) return {};
        } catch (const std::exception&) {
        }
        return "must be a whole number from " + std::to_string(lowest) + " to " + std::to_string(highest) +
               ", got '" + text + "'";
      },
      "INT");
}
CLI::Validator at_least_one() { return whole_number(1, 4096); }
CLI::Validator not_negative_integer() { return whole_number(0, std::numeric_limits<long long>::max()); }

CLI::Validator positive_finite() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        try {
          std::size_t used = 0;
          const double v = std::stod(text, &used);
          if (used == text.size() && std::isfinite(v) && v > 0.0) return {};
        } catch (const std::exception&) {
        }
        return "must be a finite number > 0, got '" + text + "'";
      },
      "NUMBER");
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"colza: discrete element simulation of oilseed bulks (oedometer, shear box)"};
  // The version, the force loops' copies (core/kernel_isa.hpp) and the CPU.
  app.set_version_flag("--version", [] {
    std::string s = std::string("colza ") + colza::kVersion + " (" + colza::git_revision() + ")\nforce loops: ";
    try {
      s += colza::kernel_isa_report();
    } catch (const colza::ConfigError& e) {  // a bad $COLZA_ISA
      s += e.what();
    }
    return s + "\nCPU: " + colza::cpu_model();
  });
  app.require_subcommand(1);
  // Usage errors read like every other colza error (`colza: error: ...`), then point at --help.
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string("colza: error: ") + e.what() + "\nRun with --help for more information.\n";
  });

  colza::RunOptions opt;
  CLI::App* run = app.add_subcommand("run", "run a scenario and write its results to --out");
  run->add_option("scenario", opt.scenario, "oedometer | shear | shear-series | repose | scene")
      ->required()
      ->check(CLI::IsMember({"oedometer", "shear", "shear-series", "repose", "scene"}));
  run->add_option("--config", opt.config_path,
                  "TOML config (oedometer: default built-in = data/oedometer.toml; shear, shear-series and "
                  "scene need one, e.g. data/shear.toml)");
  run->add_option("--set", opt.overrides, "override a config key: --set particle.friction=0.3 (repeatable)")
      ->take_last()
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  run->add_option("--seed", opt.seed, "random seed for sample generation (overrides the config's seed)")
      ->check(not_negative_integer());
  run->add_option("--threads", opt.threads,
                  "worker threads per run (default: OMP_NUM_THREADS, else the cores divided by --jobs; "
                  "the simulation is the same bit for bit at any count, only the damping-energy total "
                  "may differ in its last bits)")
      ->check(at_least_one());
  run->add_option("--out", opt.out_dir, "output directory")->required();
  run->add_flag("--force", opt.force, "replace an earlier result in --out (only once the new run has succeeded)");
  run->add_option("--normal-stress", opt.normal_stress, "shear: normal stress held by the plate (Pa)")
      ->check(positive_finite());
  run->add_option("--jobs", opt.jobs, "shear-series: loads run concurrently; with --speeds: speeds run concurrently")
      ->check(at_least_one());
  run->add_option("--speeds", opt.speeds,
                  "oedometer, shear-series, repose: run the same sample at each of these speeds (m/s, comma-separated: "
                  "the piston, shear or lift speed) and report how every feature moves with speed")
      ->delimiter(',');
  run->add_flag("--quiet", opt.quiet, "no progress display");

  colza::CalibrateOptions cal;
  CLI::App* calibrate = app.add_subcommand("calibrate", "calibrate micro-parameters to measured data (paper sections 3.2-3.3)");
  calibrate->add_option("stage", cal.stage, "density | compression | shear | load_unload | repose")
      ->required()
      ->check(CLI::IsMember({"density", "compression", "shear", "load_unload", "repose"}));
  calibrate->add_option("--spec", cal.spec_path, "calibration spec (TOML, see data/calibration/)")->required();
  calibrate->add_option("--out", cal.out_dir, "output directory (design runs are kept and reused in DIR/runs unless --runs)")->required();
  calibrate->add_option("--mode", cal.mode, "paper (fixed design, default) | sequential (trust-region refinement)")
      ->check(CLI::IsMember({"paper", "sequential"}));
  calibrate->add_option("--runs", cal.runs_dir,
                        "where DEM runs are kept and reused (default: OUT/runs); calibrations of the same model "
                        "(the other mode, other targets) can share one: a run is reused when its resolved config, "
                        "seed and packing are the same");
  calibrate->add_option("--jobs", cal.jobs, "design runs run concurrently")->check(at_least_one());
  calibrate->add_option("--threads", cal.threads,
                        "worker threads per design run (default: OMP_NUM_THREADS, else the cores divided by --jobs)")
      ->check(at_least_one());
  calibrate->add_flag("--force", cal.force, "replace an earlier calibration result in --out (finished runs are still reused)");
  calibrate->add_flag("--quiet", cal.quiet, "no per-run lines");

  colza::DiagnoseOptions diag;
  CLI::App* diagnose = app.add_subcommand(
      "diagnose", "what the calibrated model gets wrong against measured features, which mechanism explains it, the gain");
  diagnose->add_option("--spec", diag.spec_path, "diagnosis spec (TOML, see data/diagnosis/README.md)")->required();
  diagnose->add_option("--out", diag.out_dir, "output directory (DEM runs are kept and reused in DIR/runs unless --runs)")
      ->required();
  diagnose->add_option("--runs", diag.runs_dir, "where DEM runs are kept and reused (default: OUT/runs)");
  diagnose->add_option("--jobs", diag.jobs, "DEM runs side by side")->check(at_least_one());
  diagnose->add_option("--threads", diag.threads,
                       "worker threads per DEM run (default: OMP_NUM_THREADS, else the cores divided by --jobs)")
      ->check(at_least_one());
  diagnose->add_flag("--force", diag.force, "replace an earlier diagnosis result in --out (finished runs are still reused)");
  diagnose->add_flag("--quiet", diag.quiet, "no per-run lines");

  colza::FeaturesOptions feat;
  CLI::App* features = app.add_subcommand(
      "features", "the lab-test features of a curve file (a measured one, or a colza curve.csv), printed as JSON");
  features->add_option("test", feat.test, "load-unload | shear")
      ->required()
      ->check(CLI::IsMember({"load-unload", "shear"}));
  features->add_option("--csv", feat.csv, "the curve (formats: data/measured/README.md)")->required();
  features->add_option("--cylinder-diameter", feat.cylinder_diameter, "load-unload: the cylinder's diameter (m)")
      ->check(positive_finite());
  features->add_option("--height", feat.height, "load-unload: the sample's height at zero travel (m)")
      ->check(positive_finite());
  features->add_option("--modulus-stresses", feat.modulus_stresses,
                       "load-unload: piston stresses where M and K are read (Pa; default half the largest)")
      ->delimiter(',');
  features->add_option("--modulus-window", feat.modulus_window, "load-unload: relative half-width of the fit (0.1)")
      ->check(positive_finite());
  features->add_option("--window-start", feat.window_start, "shear: residual window start (m, 0.020)");
  features->add_option("--window-end", feat.window_end, "shear: residual window end (m, 0.030)");
  features->add_option("--box-length", feat.box_length, "shear: the box's length (m, 1.0): a longer displacement is an error")
      ->check(positive_finite());

  colza::PlotOptions plot_opt;
  CLI::App* plot = app.add_subcommand("plot", "draw the plots of a result (run, calibration or diagnosis) into DIR/plots/");
  plot->add_option("dir", plot_opt.dir, "a result directory (it holds summary.json)")->required();
  plot->add_option("--measured-shear", plot_opt.measured_shear,
                   "a shear series: CSV of measured strengths (normal_stress, shear_strength in Pa) beside its "
                   "Mohr-Coulomb line, or 'none' (default: the paper's line, data/measured/)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  // An option the chosen scenario would ignore is an error: a user who passes it expects it to act.
  auto inapplicable = [&](const char* option, const char* who_takes_it) {
    std::fprintf(stderr, "colza: error: %s: `colza run %s` does not take it; %s\n", option, opt.scenario.c_str(),
                 who_takes_it);
    return 2;
  };
  if (run->parsed() && run->count("--normal-stress") > 0 && opt.scenario != "shear")
    return inapplicable("--normal-stress",
                        "only `colza run shear` does (a series takes its loads from shear_box.normal_stresses)");
  if (run->parsed() && run->count("--jobs") > 0 && opt.scenario != "shear-series" && opt.speeds.empty())
    return inapplicable("--jobs", "only `colza run shear-series` and a speed series (--speeds) do (use --threads for one run)");
  if (opt.threads == 0) opt.threads = default_worker_threads(opt.jobs);
  if (cal.threads == 0) cal.threads = default_worker_threads(cal.jobs);
  if (diag.threads == 0) diag.threads = default_worker_threads(diag.jobs);
#ifdef _OPENMP
  omp_set_num_threads(run->parsed() ? opt.threads : diagnose->parsed() ? diag.threads : cal.threads);
#endif
  // A $COLZA_ISA naming no copy of the force loops that runs here is bad input (core/kernel_isa.hpp).
  try {
    colza::active_kernel_isa();
  } catch (const colza::ConfigError& e) {
    std::fprintf(stderr, "colza: error: %s\n", e.what());
    return 2;
  }
  colza::install_interrupt_handlers();
  try {
    if (run->parsed()) return colza::run_command(opt);
    if (calibrate->parsed()) return colza::calibrate_command(cal);
    if (diagnose->parsed()) return colza::diagnose_command(diag);
    if (features->parsed()) return colza::features_command(feat);
    if (plot->parsed()) return colza::plot_command(plot_opt);
  } catch (const colza::Interrupted& e) {
    std::fprintf(stderr, "colza: %s: stopped; the unfinished outputs were removed, earlier results are untouched\n",
                 e.what());
    return 128 + e.signal_number();
  } catch (const colza::UnstableMotion& e) {  // a time step above the critical one, say
    return run_failed(e);
  } catch (const colza::OutputWriteError& e) {  // a full disk, say (HDF5's too)
    return run_failed(e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "colza: internal error: %s\n", e.what());
    return 1;
  }
  return 0;
}
