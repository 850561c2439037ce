// crosscheck shear, part 5: the loads again from more realisations of the sample, means
// compared against their standard errors (crosscheck/README.md, "Ensembles").
//
// Why: the shear box is chaotic. One realisation per code compares two draws from a wide
// distribution (the small box's strength scatters by sd 1-5 kPa on 22-44 kPa from a change of
// 1e-12 m in the sample), so a per-load tolerance loose enough for one draw cannot see an
// offset of 10-15 % in the physics. Realisation k >= 1 of load sigma starts from the sample
// with every coordinate moved by U(-a, a), a = ensemble_perturbation, drawn from seed
// 1000 round(sigma / Pa) + k: the same packing for both codes, a new one for every realisation
// and load, so every run is an independent realisation. (Perturbing the normal stress by
// 1e-8 instead, as earlier sessions did, does not decorrelate the consolidation: the plate
// descends at its clamped speed until the stress is nearly reached, and eight such runs ended
// within 1 um of plate height of each other.)
#include <cmath>
#include <numbers>
#include <string>
#include <vector>
#include "analysis/curve_comparison.hpp"
#include "ensemble_runs.hpp"
#include "result_files.hpp"
#include "shear_setting.hpp"

namespace crosscheck {

void compare_shear_ensemble(const CheckContext& ctx, const ShearSetting& s, Report& report, const toml::table& doc,
                            const std::vector<double>& loads) {
  const EnsembleSpec e = read_ensemble(s.tolerances());
  if (e.realisations < 2) return;
  const std::string what = s.label + " ensemble (" + std::to_string(e.realisations) + " realisations)";
  const fs::path sample = doc.at_path("shear_box.packing_file").value_or(std::string());

  // Realisation k >= 1 of every load: its packing and config, then both codes.
  RealisationRuns runs;
  try {
    const std::string packing = read_text(sample);
    for (double sigma : loads)
      for (std::size_t k = 1; k < e.realisations; ++k) {
        const std::string name = load_run_name(sigma, k);
        const fs::path packing_k = sample.parent_path() / ("packing-" + name + ".txt");
        write_perturbed_packing(packing, packing_k, 1000 * static_cast<std::uint64_t>(std::llround(sigma)) + k,
                                e.amplitude);
        toml::table d = doc;
        d["shear_box"].as_table()->insert_or_assign("packing_file", packing_k.string());
        const fs::path config = write_run_config(s.work / ("shear_" + s.size + "_" + name + ".toml"), d, s.scene);
        const std::vector<std::string> arg = normal_stress_argument(sigma);
        const fs::path c_out = load_run_folder(s, "colza", sigma, k), y_out = load_run_folder(s, "yade", sigma, k);
        runs.colza.push_back({c_out, [&ctx, config, arg, c_out] { return ctx.runs.run_colza("shear", config, c_out, {}, arg); }});
        runs.yade.push_back({y_out, [&ctx, config, arg, y_out] { return ctx.runs.run_yade("run_shear.py", config, y_out, arg); }});
      }
  } catch (const std::exception& ex) {
    report.fail(what, ex.what());
    return;
  }
  if (!run_realisations(runs, report, what, e.amplitude)) return;

  // Every realisation's strength (realisation 0 is the load run of compare_load).
  std::vector<SampleSummary> colza, yade;
  for (double sigma : loads) {
    std::vector<double> c, y;
    for (std::size_t k = 0; k < e.realisations; ++k) {
      try {
        c.push_back(read_json(load_run_folder(s, "colza", sigma, k) / "summary.json").at("shear_strength").get<double>());
        y.push_back(read_json(load_run_folder(s, "yade", sigma, k) / "summary.json").at("shear_strength").get<double>());
      } catch (const std::exception& ex) {
        report.fail(what + " " + load_run_name(sigma, k), std::string("no shear strength: ") + ex.what());
        return;
      }
    }
    colza.push_back(summarise(c));
    yade.push_back(summarise(y));
  }

  // Rows judged: one per load, the mean relative difference, C and Phi (with two loads or
  // more); each at alpha / rows.
  const std::size_t rows = loads.size() + 1 + (loads.size() >= 2 ? 2 : 0);
  const Tolerance alpha_row = e.alpha_per_row(rows);
  for (std::size_t l = 0; l < loads.size(); ++l)
    compare_means(report, what + " " + fmt(1e-3 * loads[l], "%.2f") + " kPa strength", "kPa", colza[l], yade[l], 1e-3,
                  "%.3f", alpha_row);
  const LinearComparison relative = compare_mean_relative(colza, yade);
  check_p(report, what + " mean relative strength difference over the loads (%)",
          fmt(100.0 * relative.difference.difference, "%+.2f"), "-", relative.difference,
          ", s.e. " + fmt(100.0 * relative.difference.se, "%.2f") + " %", alpha_row);
  if (loads.size() < 2) return;
  // The Mohr-Coulomb line through the mean strengths.
  const colza::LineWeights w = colza::line_weights(loads);
  const LinearComparison cohesion = compare_linear(w.intercept, colza, yade);
  check_p(report, what + " cohesion C (kPa, mean +- s.e.)",
          mean_and_error(1e-3 * cohesion.colza, 1e-3 * cohesion.colza_se),
          mean_and_error(1e-3 * cohesion.yade, 1e-3 * cohesion.yade_se), cohesion.difference, "", alpha_row);
  const LinearComparison tan_phi = compare_linear(w.slope, colza, yade);
  // Phi = atan(tan Phi) in degrees; its s.e. from d Phi = d tan(Phi) / (1 + tan^2 Phi).
  const auto degrees = [](double tan_value, double tan_se) {
    const double to_deg = 180.0 / std::numbers::pi;
    return mean_and_error(to_deg * std::atan(tan_value), to_deg * tan_se / (1.0 + tan_value * tan_value), "%.2f");
  };
  check_p(report, what + " friction angle Phi (deg, mean +- s.e.; t of tan Phi)",
          degrees(tan_phi.colza, tan_phi.colza_se), degrees(tan_phi.yade, tan_phi.yade_se), tan_phi.difference, "",
          alpha_row);
}

}  // namespace crosscheck
