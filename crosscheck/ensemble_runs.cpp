#include "ensemble_runs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include "result_files.hpp"

namespace crosscheck {

EnsembleSpec read_ensemble(const ToleranceSection& t) {
  EnsembleSpec e;
  e.realisations = static_cast<std::size_t>(std::max(1.0, tol_number(t.table, "ensemble_realisations", 1.0)));
  e.amplitude = tol_number(t.table, "ensemble_perturbation", e.amplitude);
  e.alpha = t.get("ensemble_alpha", e.alpha.value);
  return e;
}

Tolerance EnsembleSpec::alpha_per_row(std::size_t rows) const {
  rows = std::max<std::size_t>(1, rows);
  return {alpha.value / static_cast<double>(rows), alpha.key + " / " + std::to_string(rows)};
}

void write_perturbed_packing(const std::string& text, const fs::path& file, std::uint64_t seed, double amplitude) {
  std::ofstream out(file);
  out << perturbed_packing(text, seed, amplitude);
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

namespace {

// Runs one code's runs; a FAIL row per run that failed; true if none did.
bool run_all(const std::vector<RealisationRun>& runs, Report& report, const std::string& what) {
  std::vector<std::function<bool()>> jobs;
  for (const RealisationRun& r : runs) jobs.push_back(r.run);
  const std::vector<bool> ok = run_in_parallel(jobs);
  bool all = true;
  for (std::size_t j = 0; j < runs.size(); ++j)
    if (!ok[j]) {
      report.fail(what, runs[j].out.filename().string() + " failed (" + runs[j].out.string() + ".failed.log)");
      all = false;
    }
  return all;
}

}  // namespace

bool run_realisations(const RealisationRuns& runs, Report& report, const std::string& what, double amplitude) {
  std::printf("crosscheck: %s: %zu more runs of each code (packings moved by up to %g m), colza's first...\n",
              what.c_str(), runs.colza.size(), amplitude);
  std::fflush(stdout);
  if (!run_all(runs.colza, report, what)) {
    report.fail(what, "YADE's runs not started: colza's realisations are not all there");
    return false;
  }
  return run_all(runs.yade, report, what);
}

std::string mean_and_error(double mean, double se, const char* f) { return fmt(mean, f) + " +- " + fmt(se, f); }

void check_p(Report& report, const std::string& metric, const std::string& colza, const std::string& yade,
             const MeanDifference& d, const std::string& note, const Tolerance& alpha_row) {
  const bool pass = std::isfinite(d.p) && d.p >= alpha_row.value;
  report.add(Row{metric, colza, yade, "t = " + fmt(d.t, "%.2f") + ", p = " + fmt(d.p, "%.2g") + note,
                 measure_name(Measure::kTTest), "p >= " + fmt(alpha_row.value, "%.2g"), pass, false, alpha_row.key});
}

void compare_means(Report& report, const std::string& metric, const std::string& unit, const SampleSummary& colza,
                   const SampleSummary& yade, double scale, const char* f, const Tolerance& alpha_row) {
  const MeanDifference d = difference_of_means(colza, yade);
  check_p(report, metric + " (" + unit + ", mean +- s.e.)", mean_and_error(scale * colza.mean, scale * colza.se, f),
          mean_and_error(scale * yade.mean, scale * yade.se, f), d,
          ", " + fmt(100.0 * d.difference / yade.mean, "%+.1f") + " %", alpha_row);
  report.info(metric + ": scatter of one realisation (sd, " + unit + ")", fmt(scale * colza.sd, f),
              fmt(scale * yade.sd, f), "chaos, not compared");
}

}  // namespace crosscheck
