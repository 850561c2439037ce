#include "cli/diagnose_command.hpp"
#include "cli/plot_command.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "calibration/calibrate.hpp"
#include "calibration/run_cache.hpp"
#include "config/config_error.hpp"
#include "diagnose/diagnosis_report.hpp"
#include "diagnose/diagnosis_spec.hpp"
#include "diagnose/dem_forward.hpp"
#include "io/output_dir.hpp"
#include "io/output_error.hpp"
#include "io/summary.hpp"

namespace colza {

namespace fs = std::filesystem;
using namespace colza::diagnose;

namespace {

// Bad input (ConfigError, CalibrationError) printed naming file, key and reason: exit 2.
template <class Step>
int input_errors_to_exit_code(const DiagnoseOptions& opt, Step&& step) {
  try {
    step();
  } catch (const ConfigError& e) {
    std::fprintf(stderr, "colza: error: %s\n", e.what());
    return 2;
  } catch (const calibration::CalibrationError& e) {
    std::fprintf(stderr, "colza: error: %s: key '%s': %s\n", opt.spec_path.c_str(), e.key().c_str(), e.what());
    return 2;
  }
  return 0;
}

void write_text(OutputStaging& staging, const std::string& name, const std::string& text) {
  std::ofstream f(staging.path(name));
  f << text;
  f.close();
  if (!f) throw_cannot_write(staging.path(name));
}

// A calibrated model of the diagnosis as one config per test: the test's config with the
// overrides the diagnosis ran it with, resolved (every default written out).
void write_model_configs(OutputStaging& staging, const DiagnosisSpec& spec, const DemForward& dem,
                         const std::string& model, const ModelPoint& point, std::vector<std::string>& written) {
  for (const DiagnosisTest& t : spec.tests) {
    const RunConfig c = load_run_config(t.scenario, t.config, dem.overrides(t, point));
    const std::string name = "model-" + model + "-" + t.name + ".toml";
    write_text(staging, name,
               "# " + model + " model of " + spec.file + ", calibrated by colza diagnose, for test " + t.name + "\n" +
                   c.resolved_toml);
    written.push_back(name);
  }
}

ModelPoint point_of(const Fit& f, std::size_t baseline_parameters, int candidate) {
  ModelPoint p{f.parameters.head(static_cast<Eigen::Index>(baseline_parameters))};
  if (candidate >= 0) {
    p.candidate = candidate;
    p.strength = f.parameters[static_cast<Eigen::Index>(baseline_parameters)];
  }
  return p;
}

}  // namespace

int diagnose_command(const DiagnoseOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  DiagnosisSpec spec;
  DiagnosisProblem problem;
  const fs::path out(opt.out_dir);
  const fs::path runs = opt.runs_dir.empty() ? out / "runs" : fs::absolute(opt.runs_dir);
  if (const int code = input_errors_to_exit_code(opt, [&] {
        spec = read_diagnosis_spec(opt.spec_path);
        problem = spec.problem();
        problem.settings.jobs = opt.jobs;
        validate_diagnosis(problem);
        check_output_dir(out, opt.force, "diagnose", "runs");  // a stopped diagnosis is resumed
        fs::create_directories(runs);
      }))
    return code;
  if (!opt.quiet) {
    problem.settings.on_progress = [](const std::string& line) {
      std::printf("%s\n", line.c_str());
      std::fflush(stdout);
    };
    std::printf("diagnose %s: %zu features from %zu tests, %zu baseline parameters, %zu candidates; %d job(s)\n",
                opt.spec_path.c_str(), problem.features.size(), spec.tests.size(), problem.parameters.size(),
                problem.candidates.size(), opt.jobs);
  }
  calibration::RunCache cache(runs, !opt.quiet);
  DemForward dem(spec, cache, !opt.quiet);
  DiagnosisResult result;
  if (const int code = input_errors_to_exit_code(opt, [&] {
        result = colza::diagnose::diagnose(problem, [&dem](const ModelPoint& x, int k) { return dem(x, k); });
      }))
    return code;

  DiagnosisContext ctx;
  ctx.spec_file = opt.spec_path;
  ctx.title = spec.title;
  ctx.reused_runs = dem.reused_runs();
  ctx.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ctx.notes.push_back("DEM runs: " + std::to_string(dem.runs()) + " test runs (" + std::to_string(dem.reused_runs()) +
                      " reused from " + runs.string() + ")");
  if (std::string other = calibration::runs_by_another_revision_warning(dem.reused_revisions(), runs); !other.empty()) {
    std::fprintf(stderr, "colza: warning: %s\n", other.c_str());
    result.warnings.push_back(std::move(other));
  }
  OutputStaging staging(out, /*overwrite=*/true);  // an earlier result was refused above unless --force
  std::vector<std::string> configs;
  write_model_configs(staging, spec, dem, "baseline", point_of(result.baseline, spec.parameters.size(), -1), configs);
  for (const ExtendedFit& e : result.extended)
    write_model_configs(staging, spec, dem, problem.candidates[static_cast<std::size_t>(e.candidate)].name,
                        point_of(e.fit, spec.parameters.size(), e.candidate), configs);
  std::string list;
  for (const auto& c : configs) list += (list.empty() ? "" : ", ") + c;
  ctx.notes.push_back("calibrated models as configs `colza run` accepts: " + list);
  write_text(staging, "report.md", diagnosis_report(problem, result, ctx));
  write_json(staging.path("summary.json"), diagnosis_summary(problem, result, ctx));
  staging.commit();
  plot_after_run(out, opt.quiet);  // features before and after, the signatures' similarity (python/colzaplot/diagnosis.py)
  std::printf("verdict: %s\n%s\n", to_string(result.verdict.kind), result.verdict.text.c_str());
  std::printf("%d forward runs (%d test runs reused), %.0f s; report: %s\n", result.forward_runs, dem.reused_runs(),
              ctx.wall_seconds, (out / "report.md").c_str());
  return 0;
}

}  // namespace colza
