#include "cli/calibrate_command.hpp"
#include "cli/plot_command.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <unistd.h>

#include "calibration/calibrate.hpp"
#include "calibration/dem_model.hpp"
#include "calibration/measured_report.hpp"
#include "calibration/report.hpp"
#include "calibration/spec.hpp"
#include "config/config_error.hpp"
#include "core/unstable_motion.hpp"
#include "core/version.hpp"
#include "io/fingerprint.hpp"
#include "io/format_number.hpp"
#include "io/output_dir.hpp"
#include "io/summary.hpp"
#include "io/output_error.hpp"

namespace colza {

namespace fs = std::filesystem;
using namespace colza::calibration;

namespace {

// Spec key a calibration error is about.
std::string spec_key(const Spec& spec, const std::string& key) {
  for (const auto& t : spec.problem.targets)
    if (t.name == key) {
      if (spec.stage == Stage::kDensity) return "measured.bulk_density";
      if (spec.stage == Stage::kCompression) return spec.measured_file.empty() ? "measured." + key : "measured.curve";
      if (spec.stage == Stage::kLoadUnload || spec.stage == Stage::kRepose)
        return spec.targets_from_curve.count(key) ? "measured.curve" : "measured.features";
      return spec.measured_curves.empty() ? "measured.results" : "measured.curves";
    }
  if (key == "design") return "parameters[].design";
  return key;
}

// A design run that blew up with the model's time step fixed above the critical estimate
// (a stiffer design point needs a smaller one): bad input, blamed on where the time step was
// set, the spec's [model] set or the model config (as `colza run` blames integration.time_step).
ConfigError fixed_time_step_error(const Spec& spec, const UnstableMotion& e) {
  const std::string reason = "the fixed time step exceeds the critical estimate of a design run and its motion blew "
                             "up: " + std::string(e.what()) + "; lower integration.time_step, remove it (the "
                             "automatic time step follows the design point's stiffness) or narrow the design range; "
                             "finished design runs are kept";
  for (const std::string& o : spec.model_set)
    if (o.rfind("integration.time_step=", 0) == 0) return ConfigError(spec.file, "model.set", reason);
  return ConfigError(spec.model_config, "integration.time_step", reason);
}

// Runs `step`; bad input (ConfigError, CalibrationError, a fixed time step that made a design
// run blow up) is printed naming file, key and reason and turned into exit code 2. Returns 0
// when `step` succeeded.
template <class Step>
int input_errors_to_exit_code(const CalibrateOptions& opt, const Spec& spec, Step&& step) {
  try {
    step();
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "colza: error: %s\n", e.what());
    return 2;
  } catch (const CalibrationError& e) {
    std::fprintf(stderr, "colza: error: %s: key '%s': %s\n", opt.spec_path.c_str(), spec_key(spec, e.key()).c_str(),
                 e.what());
    return 2;
  } catch (const UnstableMotion& e) {
    if (!e.fixed_time_step_too_large()) throw;  // main reports it, exit 1
    std::fprintf(stderr, "colza: error: %s\n", fixed_time_step_error(spec, e).what());
    return 2;
  }
  return 0;
}

// Warnings about the DEM runs: those the model noted (a peak at a curve's end), and the
// reused runs another revision of colza made (calibration/run_cache.hpp).
std::vector<std::string> warnings_about_runs(const DemModel& dem, const fs::path& runs) {
  std::vector<std::string> w = dem.warnings();
  std::vector<std::pair<std::string, std::string>> reused;
  for (const auto& rec : dem.records())
    if (rec.run.reused) reused.emplace_back(rec.run.id, rec.run.made_by);
  if (std::string other = calibration::runs_by_another_revision_warning(reused, runs); !other.empty())
    w.push_back(std::move(other));
  return w;
}

// Whether `out` holds a calibration that was stopped, to be resumed: a folder runs/ whose
// entries are all design runs (folders named by a run's 16-hex-digit fingerprint, or
// sample-<fingerprint>) or staging folders, and not empty unless `out` holds nothing else.
// A folder named runs of the user's is not one: resuming there would replace a report.md
// beside it without --force.
bool holds_a_stopped_calibration(const fs::path& out) {
  std::error_code ec;
  const fs::path runs = out / "runs";
  if (!fs::is_directory(runs, ec)) return false;
  bool any_run = false;
  for (fs::directory_iterator it(runs, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (is_staging_folder(it->path())) continue;
    const bool design_run =
        is_fingerprint_text(name) || (name.rfind("sample-", 0) == 0 && is_fingerprint_text(name.substr(7)));
    if (!design_run || !fs::is_directory(it->path(), ec)) return false;
    any_run = true;
  }
  if (ec) return false;
  if (any_run) return true;
  for (fs::directory_iterator it(out, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename() != "runs" && !is_staging_folder(it->path())) return false;
  return !ec;
}

// Where the design runs live: --runs, or DIR/runs.
fs::path runs_folder(const CalibrateOptions& opt) {
  return opt.runs_dir.empty() ? fs::path(opt.out_dir) / "runs" : fs::absolute(opt.runs_dir);
}

// Makes --out and the runs folder (--runs, or DIR/runs) before any run starts, and checks that
// both take files: a path that cannot be a writable folder is bad input (exit 2), said before
// the first run, not as an internal error after it. A --out made here is removed again when
// the runs folder then fails, so nothing is left behind.
void make_output_folders(const fs::path& out, const fs::path& runs, bool runs_given) {
  const auto refuse = [&](const std::string& option, const fs::path& dir, const std::string& why) {
    throw ConfigError(option + " " + dir.string(), "", why);
  };
  const auto writable = [](const fs::path& dir) {
    std::error_code ec;
    const fs::path probe = dir / (".colza-write-test-" + std::to_string(::getpid()));
    const bool ok = fs::create_directory(probe, ec) && !ec;
    fs::remove(probe, ec);
    return ok;
  };
  std::error_code ec;
  if (fs::exists(runs, ec) && !fs::is_directory(runs, ec))
    refuse(runs_given ? "--runs" : "--out", runs_given ? runs : out,
           runs_given ? "exists and is not a directory" : "holds a file named runs where the design runs go");
  const bool out_existed = fs::exists(out, ec);
  const bool runs_existed = fs::exists(runs, ec);
  fs::create_directories(out, ec);
  if (ec) refuse("--out", out, "cannot create the directory: " + ec.message());
  const auto undo_out = [&] {
    std::error_code ignored;
    if (!out_existed) fs::remove(out, ignored);  // only if still empty
  };
  if (!writable(out)) {
    undo_out();
    refuse("--out", out, "cannot write into the directory (permission denied?)");
  }
  fs::create_directories(runs, ec);
  if (ec || !writable(runs)) {
    const std::string why = ec ? "cannot create the directory: " + ec.message() : "cannot write into the directory";
    std::error_code ignored;
    if (!runs_existed && fs::is_directory(runs, ignored)) fs::remove(runs, ignored);  // made just now, empty
    undo_out();
    refuse(runs_given ? "--runs" : "--out", runs, why);
  }
}

}  // namespace

int calibrate_command(const CalibrateOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  Spec spec;
  if (const int code = input_errors_to_exit_code(opt, spec, [&] {
        if (opt.spec_path.empty()) throw ConfigError("--spec", "", "a calibration spec is required");
        spec = read_spec(opt.spec_path);
        if (opt.stage != to_string(spec.stage))
          throw ConfigError(opt.spec_path, "stage", "the spec is for stage \"" + std::string(to_string(spec.stage)) +
                                                        "\", the command asked for \"" + opt.stage + "\"");
        validate_problem(spec.problem, opt.mode == "sequential");
        check_output_dir(opt.out_dir, opt.force, "calibrate",  // a stopped calibration is resumed
                         holds_a_stopped_calibration(opt.out_dir) ? "runs" : "");
        make_output_folders(opt.out_dir, runs_folder(opt), !opt.runs_dir.empty());
      }))
    return code;
  for (const auto& w : spec.warnings) std::fprintf(stderr, "colza: warning: %s\n", w.c_str());

  const bool verbose = !opt.quiet;
  if (verbose) {
    std::printf("calibrate %s (%s mode): %zu parameter(s), targets:", to_string(spec.stage), opt.mode.c_str(),
                spec.problem.parameters.size());
    for (const auto& t : spec.problem.targets) std::printf(" %s = %.6g +/- %.3g %s;", t.name.c_str(), t.value, t.uncertainty, t.unit.c_str());
    std::printf(" %d job(s) x %d thread(s)\n", opt.jobs, opt.threads);
    std::fflush(stdout);
  }
  const fs::path out(opt.out_dir);
  const fs::path runs = runs_folder(opt);
  DemModel dem(spec, runs, verbose);
  const ForwardModel model = [&dem](const Eigen::VectorXd& x) { return dem(x); };
  LoopOptions loop;
  loop.jobs = opt.jobs;
  // Other realisations (seed + k) exist only when the seed makes the sample: with one packing
  // file for every run another seed is the same run (replicates are refused by the spec then,
  // and the sequential mode's stop cannot be confirmed).
  if (spec.fixed_packing_file.empty())
    loop.replicate_model = [&dem](const Eigen::VectorXd& x, int replicate) { return dem.run(x, replicate); };
  else if (opt.mode == "sequential") {
    spec.warnings.push_back("the sequential stop is not confirmed by another realisation: every run loads the "
                            "packing file " + spec.fixed_packing_file + ", so another seed gives the same run; a "
                            "lucky stop shows only as a validation that a nearby point would miss");
    std::fprintf(stderr, "colza: warning: %s\n", spec.warnings.back().c_str());
  }
  CalibrationResult result;
  const int code = input_errors_to_exit_code(opt, spec, [&] {
    result = opt.mode == "sequential" ? calibrate_sequential(spec.problem, model, loop)
                                      : calibrate_paper(spec.problem, model, loop);
  });
  // What the runs say (printed whether or not the calibration succeeded: a failed one may
  // be due to them).
  const std::vector<std::string> run_warnings = warnings_about_runs(dem, runs);
  for (const auto& w : run_warnings) std::fprintf(stderr, "colza: warning: %s\n", w.c_str());
  if (code) return code;

  ReportContext ctx;
  ctx.stage = to_string(spec.stage);
  ctx.runs_dir = opt.runs_dir.empty() ? "runs" : runs.string();
  ctx.spec_file = opt.spec_path;
  ctx.title = spec.title;
  ctx.measured_file = spec.measured_file;
  ctx.paper_design_runs = spec.problem.design.size() + 1 + static_cast<std::size_t>(spec.problem.replicates);
  ctx.extra_warnings = spec.warnings;
  if (spec.shared_packing) ctx.notes = "Packing: " + dem.shared_packing_note() + ".";
  if (spec.stage == Stage::kShear) {
    ctx.notes = "Each design run is a shear series at the loads";
    for (std::size_t k = 0; k < spec.loads.size(); ++k)
      ctx.notes += (k ? ", " : " ") + format_significant(spec.loads[k], 6) + " Pa";
    ctx.notes += " from one settled sample (bond strengths do not act before loading); C and tan(Phi) from the "
                 "Mohr-Coulomb line through the shear strengths (" + spec.strength.describe() + ").";
    ctx.notes += spec.correlation_given
                     ? " The correlation of the measured C and tan(Phi) is the spec's ([measured] correlation)."
                     : " The correlation of the measured C and tan(Phi) is that of a line's intercept and slope through "
                       "strengths of equal, independent uncertainty at the measured loads; set [measured] correlation "
                       "(0: independent) if the stated uncertainties did not come from such a fit.";
  }
  // A sentence after the notes so far.
  const auto add_note = [&ctx](const std::string& sentence) { ctx.notes += (ctx.notes.empty() ? "" : " ") + sentence; };
  if (spec.stage == Stage::kRepose)
    add_note("Each design run is an angle of repose test (the column settled in the cylinder, the cylinder lifted, "
             "the heap at rest); its angle is the cone fitted to the heap's surface spheres (docs/running.md).");
  if (spec.stage == Stage::kLoadUnload)
    add_note("Each design run is an oedometer load-unload test (oedometer.cycles); its features come from its "
             "curve by the code that reduces the measured curve.");
  if (spec.stage == Stage::kCompression)
    add_note(spec.correlation_given ? "The correlation of the measured c1 and c2 is the spec's ([measured] correlation)."
                                    : "The measured c1 and c2 are taken as independent; set [measured] correlation "
                                      "if repeated tests show how they vary together.");
  ctx.measured = measured_data_summary(spec);
  ctx.measured_section = measured_data_section(spec);
  for (const auto& run : result.runs) {
    const DemRunRecord* rec = dem.find(run.x, run.replicate);
    ctx.run_ids.push_back(rec ? rec->run.id : "");
    ctx.run_reused.push_back(rec ? rec->run.reused : false);
    ctx.run_wall_seconds.push_back(rec ? rec->run.wall_seconds : 0.0);
  }
  ctx.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const auto& w : run_warnings) ctx.extra_warnings.push_back(w);

  OutputStaging staging(out, /*overwrite=*/true);  // an earlier summary was refused above unless --force
  write_json(staging.path("summary.json"), calibration_summary(spec.problem, result, ctx));
  {
    std::ofstream md(staging.path("report.md"));
    md << calibration_report(spec.problem, result, ctx);
    md.close();  // a full disk shows at the flush: a cut report is never committed
    if (!md) throw_cannot_write(staging.path("report.md"));
  }
  staging.commit();
  plot_after_run(out, opt.quiet);  // plots/ and report.md's Plots section (python/colzaplot/report.py)

  std::printf("calibrated %s (%s): %zu forward runs (paper design: %zu)\n", to_string(spec.stage), result.mode.c_str(),
              result.runs.size(), ctx.paper_design_runs);
  for (std::size_t j = 0; j < spec.problem.parameters.size(); ++j)
    std::printf("  %s = %.6g +/- %.3g %s\n", spec.problem.parameters[j].name.c_str(), result.solution[j], result.sigma[j],
                spec.problem.parameters[j].unit.c_str());
  for (std::size_t i = 0; i < spec.problem.targets.size(); ++i) {
    std::printf("  %s: measured %.6g +/- %.3g, validation %.6g (error %+.3g, %.2f sigma)",
                spec.problem.targets[i].name.c_str(), spec.problem.targets[i].value, spec.problem.targets[i].uncertainty,
                result.achieved[i], result.error[i], result.error[i] / spec.problem.targets[i].uncertainty);
    if (result.scatter.size())
      std::printf("; realisation scatter %.3g, judged against %.3g", result.scatter[i], result.tolerance[i]);
    std::printf("\n");
  }
  if (result.confirmation.size())
    std::printf("  another realisation at the solution (seed + 1): %s (misfit %.3g)%s\n",
                result.confirmation_misfit <= 1.0 ? "within" : "misses", result.confirmation_misfit,
                result.confirmation_misfit <= 1.0 ? "" : ": NOT validated (the stop may have been a lucky draw)");
  for (const auto& w : result.warnings) std::fprintf(stderr, "colza: warning: %s\n", w.c_str());
  return 0;
}

}  // namespace colza
