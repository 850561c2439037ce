// What the cross-check's ensembles share (crosscheck/README.md, "Ensembles"): their keys in
// the tolerance table, the perturbed packings, running the realisations, and their rows.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <toml++/toml.h>
#include <vector>
#include "code_runs.hpp"
#include "ensemble_stats.hpp"
#include "report.hpp"

namespace crosscheck {

// ensemble_realisations (N, realisation 0 is the unperturbed sample; < 2: no ensemble),
// ensemble_perturbation (a, m) and ensemble_alpha (the probability that a check's ensemble
// rows fail although the codes agree: each of its R rows is judged at alpha / R, Bonferroni).
struct EnsembleSpec {
  std::size_t realisations = 1;
  double amplitude = 1e-12;
  Tolerance alpha{0.01, "ensemble_alpha (default)"};
  // alpha / rows, its key followed by " / rows".
  Tolerance alpha_per_row(std::size_t rows) const;
};
EnsembleSpec read_ensemble(const ToleranceSection& t);

// `text` (a packing file's) perturbed by perturbed_packing(seed, amplitude), written to
// `file`. Throws std::runtime_error if it cannot.
void write_perturbed_packing(const std::string& text, const fs::path& file, std::uint64_t seed, double amplitude);

// One run of one code: where it writes, and how to run it.
struct RealisationRun {
  fs::path out;
  std::function<bool()> run;
};
// The realisations' runs of each code.
struct RealisationRuns {
  std::vector<RealisationRun> colza, yade;
};
// Says what it starts (`what`, the runs per code, the perturbation amplitude a in m) and runs
// them kParallelRuns at a time: colza's first, then YADE's only if every colza run succeeded
// (the ensemble is judged on all realisations or none, and YADE's runs are the long ones). A
// FAIL row per run that failed; true if none did.
bool run_realisations(const RealisationRuns& runs, Report& report, const std::string& what, double amplitude);

// "21.910 +- 0.780"
std::string mean_and_error(double mean, double se, const char* f = "%.3f");

// A row judged by the p-value of d: passes when p >= alpha_row. `note` follows t and p.
void check_p(Report& report, const std::string& metric, const std::string& colza, const std::string& yade,
             const MeanDifference& d, const std::string& note, const Tolerance& alpha_row);

// The two rows of one quantity measured on every realisation of both codes: the means judged
// by check_p (values printed times `scale`, format f), then an information row with each code's
// scatter of one realisation (sd).
void compare_means(Report& report, const std::string& metric, const std::string& unit, const SampleSummary& colza,
                   const SampleSummary& yade, double scale, const char* f, const Tolerance& alpha_row);

}  // namespace crosscheck
