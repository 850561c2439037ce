// crosscheck shear, part 5: the loads again from more realisations of the sample, means
// compared against their standard errors (crosscheck/README.md, "Ensembles").
//
// Why: the shear box is chaotic. One realisation per code compares two draws from a wide
// distribution (the strength of the small box scatters by ~10 % from a change of 1e-12 m in
// the sample), so a per-load tolerance loose enough for one draw cannot see an offset of
// 10-15 % in the physics. Realisation k >= 1 starts from the sample with every coordinate
// moved by U(-a, a), a = ensemble_perturbation, from seed k: the same sample for both codes,
// and a new realisation of the chaos for each k. (Perturbing the normal stress by 1e-8
// instead, as earlier sessions did, does not decorrelate the consolidation: the plate
// descends at its clamped speed until the stress is nearly reached, and eight such runs ended
// within 1 um of plate height of each other.)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <numbers>
#include <string>
#include <vector>
#include "ensemble_rows.hpp"
#include "ensemble_stats.hpp"
#include "result_files.hpp"
#include "shear_setting.hpp"

namespace crosscheck {

void compare_shear_ensemble(const CheckContext& ctx, const ShearSetting& s, Report& report, const toml::table& doc,
                            const std::vector<double>& loads) {
  const std::size_t realisations = static_cast<std::size_t>(tol_number(s.t, "ensemble_realisations", 1.0));
  if (realisations < 2) return;
  const double amplitude = tol_number(s.t, "ensemble_perturbation", 1e-12);
  const double t_max = tol_number(s.t, "ensemble_t_max", 3.0);
  const std::string what = s.label + " ensemble (" + std::to_string(realisations) + " realisations)";
  const fs::path sample = doc.at_path("shear_box.packing_file").value_or(std::string());
  std::string packing;
  try {
    packing = read_text(sample);
  } catch (const std::exception& e) {
    report.fail(what, e.what());
    return;
  }

  // Realisation k >= 1: its packing and config, then both codes at every load.
  std::vector<std::function<bool()>> jobs;
  for (std::size_t k = 1; k < realisations; ++k) {
    const fs::path packing_k = sample.parent_path() / ("packing-r" + std::to_string(k) + ".txt");
    try {
      std::ofstream(packing_k) << perturbed_packing(packing, k, amplitude);
    } catch (const std::exception& e) {
      report.fail(what, sample.string() + ": " + e.what());
      return;
    }
    toml::table d = doc;
    d["shear_box"].as_table()->insert_or_assign("packing_file", packing_k.string());
    const fs::path config = write_config(s, d, "shear_" + s.size + "_r" + std::to_string(k) + ".toml");
    for (double sigma : loads) {
      const std::string name = load_run_name(sigma, k);
      const std::vector<std::string> arg = normal_stress_argument(sigma);
      jobs.push_back([&ctx, config, arg, out = s.work / ("colza_" + name)] {
        return ctx.runs.run_colza("shear", config, out, {}, arg);
      });
      jobs.push_back([&ctx, config, arg, out = s.work / ("yade_" + name)] {
        return ctx.runs.run_yade("run_shear.py", config, out, arg);
      });
    }
  }
  std::printf("crosscheck: %s: %zu more runs of each code (packings moved by up to %g m)...\n", what.c_str(),
              jobs.size() / 2, amplitude);
  std::fflush(stdout);
  run_in_parallel(jobs);

  // Every realisation's strength (realisation 0 is the load run of compare_load).
  std::vector<SampleSummary> colza, yade;
  for (double sigma : loads) {
    std::vector<double> c, y;
    for (std::size_t k = 0; k < realisations; ++k) {
      const std::string name = load_run_name(sigma, k);
      try {
        c.push_back(read_json(s.work / ("colza_" + name) / "summary.json").at("shear_strength").get<double>());
        y.push_back(read_json(s.work / ("yade_" + name) / "summary.json").at("shear_strength").get<double>());
      } catch (const std::exception& e) {
        report.fail(what + " " + name, std::string("run failed or unreadable: ") + e.what());
        return;
      }
    }
    colza.push_back(summarise(c));
    yade.push_back(summarise(y));
  }

  // Per load, and the mean relative difference over the loads.
  double relative_sum = 0.0, relative_var = 0.0;
  for (std::size_t l = 0; l < loads.size(); ++l) {
    const SampleSummary &c = colza[l], &y = yade[l];
    const MeanDifference d = difference_of_means(c, y);
    const std::string at = what + " " + fmt(1e-3 * loads[l], "%.2f") + " kPa";
    check_t(report, at + " strength (kPa, mean +- s.e.)", mean_and_error(1e-3 * c.mean, 1e-3 * c.se),
            mean_and_error(1e-3 * y.mean, 1e-3 * y.se), d, ", " + fmt(100.0 * d.difference / y.mean, "%+.1f") + " %",
            t_max);
    report.info(at + " scatter of one realisation (sd, kPa)", fmt(1e-3 * c.sd, "%.3f"), fmt(1e-3 * y.sd, "%.3f"),
                "chaos, not compared");
    relative_sum += d.difference / y.mean;
    relative_var += (d.se / y.mean) * (d.se / y.mean);
  }
  const double n = static_cast<double>(loads.size());
  const MeanDifference pooled{relative_sum / n, std::sqrt(relative_var) / n,
                              relative_var > 0.0 ? relative_sum / std::sqrt(relative_var) : 0.0};
  check_t(report, what + " mean relative strength difference over the loads (%)",
          fmt(100.0 * pooled.difference, "%+.2f"), "-", pooled, ", s.e. " + fmt(100.0 * pooled.se, "%.2f") + " %",
          t_max);

  // The Mohr-Coulomb line through the mean strengths.
  if (loads.size() < 2) return;
  const LineWeights w = line_weights(loads);
  const LinearComparison cohesion = compare_linear(w.intercept, colza, yade);
  check_t(report, what + " cohesion C (kPa, mean +- s.e.)", mean_and_error(1e-3 * cohesion.colza, 1e-3 * cohesion.colza_se),
          mean_and_error(1e-3 * cohesion.yade, 1e-3 * cohesion.yade_se), cohesion.difference, "", t_max);
  const LinearComparison tan_phi = compare_linear(w.slope, colza, yade);
  // Phi = atan(tan Phi) in degrees; its s.e. from d Phi = d tan(Phi) / (1 + tan^2 Phi).
  const auto degrees = [](double tan_value, double tan_se) {
    const double to_deg = 180.0 / std::numbers::pi;
    return mean_and_error(to_deg * std::atan(tan_value), to_deg * tan_se / (1.0 + tan_value * tan_value), "%.2f");
  };
  check_t(report, what + " friction angle Phi (deg, mean +- s.e.; t of tan Phi)", degrees(tan_phi.colza, tan_phi.colza_se),
          degrees(tan_phi.yade, tan_phi.yade_se), tan_phi.difference, "", t_max);
}

}  // namespace crosscheck
