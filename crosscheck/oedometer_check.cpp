// crosscheck oedometer: both codes load the same settled packing (small: the committed
// 208-sphere packing; full: the paper's packing, made first by `colza run oedometer`) and
// their force-displacement curves (curve.csv) are compared; for the small packing also an
// ensemble of realisations (crosscheck/README.md, "Ensembles"): the mean forces at the
// travels against their standard errors.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>
#include "checks.hpp"
#include "analysis/curve_comparison.hpp"
#include "ensemble_runs.hpp"
#include "result_files.hpp"

namespace crosscheck {

namespace {

// The lower force of the oedometer's fit (oedometer.fit_force_min, N) in a config; 150 N,
// colza's default, if absent.
double fit_force_min(const fs::path& config) {
  try {
    const toml::table t = toml::parse_file(config.string());
    return t.at_path("oedometer.fit_force_min").value_or(150.0);
  } catch (...) {
    return 150.0;
  }
}

// The travels (m) of the tolerance table's `travels`.
std::vector<double> travels_of(const toml::table& t) {
  std::vector<double> travels;
  if (const auto* a = t.at_path("travels").as_array())
    for (const auto& node : *a) travels.push_back(node.value<double>().value_or(0.0));
  return travels;
}

}  // namespace

void compare_oedometer_curves(Report& report, const std::string& label, const Csv& c, const Csv& y,
                              const ToleranceSection& t, const nlohmann::json& cs, const nlohmann::json& ys,
                              const fs::path& config) {
  const auto& cs_ = c.at("piston_displacement");
  const auto& cf = c.at("piston_force");
  const auto& ysd = y.at("piston_displacement");
  const auto& yf = y.at("piston_force");
  // The same start: identical particle count and contact count at step 0.
  check_same_count(report, label + " particles", cs, ys, "particles");
  report.check(label + " contacts at the start", c.at("contacts")[0], y.at("contacts")[0],
               std::abs(c.at("contacts")[0] - y.at("contacts")[0]), Measure::kAbsolute, fixed_tolerance(0.0), "%.0f");
  // Early rows: before chaos amplifies rounding, the curves must coincide.
  const std::size_t early = static_cast<std::size_t>(t.table.at_path("early_rows").value_or(10));
  const colza::MaxDifference start = colza::max_difference(cf, yf, std::min({early, c.rows(), y.rows()}));
  report.check(label + " force, first " + std::to_string(early) + " rows (max |diff| / max F)", start.max_colza,
               start.max_yade, start.relative, Measure::kRelative, t.get("early_relative", 1e-5));
  // Logged range: from the fit's lower force on, up to the smaller final travel.
  const double f_min = fit_force_min(config);
  double s_lo = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t r = 0; r < c.rows(); ++r)
    if (cf[r] >= f_min) {
      s_lo = cs_[r];
      break;
    }
  const double s_hi = std::min(cs_.back(), ysd.back());
  const colza::RmsDifference d = colza::rms_difference(cs_, cf, ysd, yf, s_lo, s_hi);
  report.check(label + " force rms difference / rms force (" + std::to_string(d.n) + " rows, travel " +
                   fmt(1e3 * s_lo, "%.2f") + "-" + fmt(1e3 * s_hi, "%.2f") + " mm)",
               d.rms_colza, d.rms_yade, d.relative, Measure::kRelative, t.get("rms_relative", 0.05));
  for (const double s : travels_of(t.table)) {
    const std::string metric = label + " force at " + fmt(1e3 * s, "%.1f") + " mm travel (N; difference / colza's)";
    // Said as such: the force there is not defined, rather than "not finite".
    if (s > cs_.back() || s > ysd.back()) {
      report.fail(metric, std::string(s > cs_.back() ? "colza's" : "YADE's") + " curve stops before this travel");
      continue;
    }
    const double fc = colza::interpolate(cs_, cf, s), fy = colza::interpolate(ysd, yf, s);
    report.check(metric, fc, fy, std::abs(fc - fy) / std::abs(fc), Measure::kRelative, t.get("force_at_relative", 0.1),
                 "%.1f");
  }
  report.info(label + " travel at stop (mm)", fmt(1e3 * cs_.back(), "%.3f"), fmt(1e3 * ysd.back(), "%.3f"),
              cs.value("stop_reason", std::string("?")) + " / " + ys.value("stop_reason", std::string("?")));
  // A summary without the count (a run that did not finish, an older script) fails, as in the
  // ensemble: the check is that the count is 0, not that nobody reported one.
  if (!ys.contains("foreign_patch_contacts"))
    report.fail(label + " YADE cylinder patches", "YADE's summary.json has no foreign_patch_contacts");
  else if (ys.value("foreign_patch_contacts", -1) != 0)
    report.fail(label + " YADE cylinder patches", "a patch touched a sphere other than its own");
}

namespace {

// Realisations 1..N-1 of the loading (realisation 0 is the run of check_oedometer in c_out0,
// y_out0) from copies of the config's packing with every coordinate moved by U(-a, a), seed k;
// then the mean force of each code at every travel, judged by Welch's t test at alpha / the
// number of travels (crosscheck/README.md, "Ensembles"). Nothing when the table asks for
// fewer than two realisations.
void compare_ensemble(const CheckContext& ctx, Report& report, const std::string& label, const ToleranceSection& t,
                      const fs::path& config, const fs::path& work, const fs::path& c_out0, const fs::path& y_out0) {
  const EnsembleSpec e = read_ensemble(t);
  if (e.realisations < 2) return;
  const std::string what = label + " ensemble (" + std::to_string(e.realisations) + " realisations)";
  std::vector<fs::path> c_out{c_out0}, y_out{y_out0};
  RealisationRuns runs;
  try {
    toml::table doc = toml::parse_file(config.string());
    toml::table* oedometer = doc["oedometer"].as_table();
    const std::string packing_file = doc.at_path("oedometer.packing_file").value_or(std::string());
    if (!oedometer || packing_file.empty()) throw std::runtime_error(config.string() + " names no oedometer.packing_file");
    fs::path packing = packing_file;
    if (packing.is_relative()) packing = config.parent_path() / packing;  // as colza reads it
    const std::string text = read_text(packing);
    for (std::size_t k = 1; k < e.realisations; ++k) {
      const std::string r = "-r" + std::to_string(k);
      const fs::path packing_k = work / ("packing" + r + ".txt");
      write_perturbed_packing(text, packing_k, k, e.amplitude);
      oedometer->insert_or_assign("packing_file", fs::absolute(packing_k).string());
      const fs::path config_k = write_run_config(work / (config.stem().string() + r + ".toml"), doc, config);
      c_out.push_back(work / ("colza" + r));
      y_out.push_back(work / ("yade" + r));
      runs.colza.push_back({c_out.back(), [&ctx, config_k, out = c_out.back()] { return ctx.runs.run_colza("oedometer", config_k, out); }});
      runs.yade.push_back({y_out.back(), [&ctx, config_k, out = y_out.back()] {
                        return ctx.runs.run_yade("run_oedometer.py", config_k, out);
                      }});
    }
  } catch (const std::exception& ex) {
    report.fail(what, ex.what());
    return;
  }
  if (!run_realisations(runs, report, what, e.amplitude)) return;

  const std::vector<double> travels = travels_of(t.table);
  std::vector<std::vector<double>> c_force(travels.size()), y_force(travels.size());
  for (std::size_t k = 0; k < e.realisations; ++k) {
    const std::string realisation = what + " realisation " + std::to_string(k);
    try {
      const Csv c = read_csv(c_out[k] / "curve.csv"), y = read_csv(y_out[k] / "curve.csv");
      if (read_json(y_out[k] / "summary.json").value("foreign_patch_contacts", -1) != 0)
        throw std::runtime_error("YADE's summary.json is missing, or a cylinder patch touched a sphere other than its own");
      for (std::size_t j = 0; j < travels.size(); ++j) {
        const double fc = colza::interpolate(c.at("piston_displacement"), c.at("piston_force"), travels[j]);
        const double fy = colza::interpolate(y.at("piston_displacement"), y.at("piston_force"), travels[j]);
        if (!std::isfinite(fc) || !std::isfinite(fy))
          throw std::runtime_error("a curve stops before " + fmt(1e3 * travels[j], "%.1f") + " mm of travel");
        c_force[j].push_back(fc);
        y_force[j].push_back(fy);
      }
    } catch (const std::exception& ex) {
      report.fail(realisation, ex.what());
      return;
    }
  }
  const Tolerance alpha_row = e.alpha_per_row(travels.size());
  for (std::size_t j = 0; j < travels.size(); ++j)
    compare_means(report, what + " force at " + fmt(1e3 * travels[j], "%.1f") + " mm travel", "N",
                  summarise(c_force[j]), summarise(y_force[j]), 1.0, "%.1f", alpha_row);
}

}  // namespace

void check_oedometer(const CheckContext& ctx, Report& report, const std::string& size) {
  const toml::table* t = size_section(ctx, report, "oedometer", size);
  if (!t) return;
  const ToleranceSection tolerances{*t, "oedometer." + size};
  fs::path config = ctx.opt.source / t->at_path("config").value_or(std::string());
  const fs::path work = ctx.opt.workdir / ("oedometer_" + size);
  fs::create_directories(work);
  if (size == "full") {
    // Generate the paper's packing with colza's defaults, then load it with the loading
    // config (its packing_file is filled in here).
    const fs::path settle = ctx.opt.source / t->at_path("settle_config").value_or(std::string("data/oedometer.toml"));
    const fs::path settled = work / "settle";
    std::printf("crosscheck: the full-size packing, generated and settled by colza (%s)...\n",
                settle.string().c_str());
    std::fflush(stdout);
    if (!ctx.runs.run_colza("oedometer", settle, settled, {}, {}, Reuse::kIfSameInputs)) {
      report.fail("oedometer full", "colza could not make the packing: " + ctx.runs.failure(settled));
      return;
    }
    std::string s;
    try {
      s = read_text(config);
    } catch (const std::exception& e) {
      report.fail("oedometer full", e.what());
      return;
    }
    const std::string marker = "@PACKING@";
    const auto at = s.find(marker);
    if (at == std::string::npos) {
      report.fail("oedometer full", config.string() + " has no packing_file = \"@PACKING@\"");
      return;
    }
    s.replace(at, marker.size(), fs::absolute(settled / "packing.txt").string());
    config = work / "oedometer_full.toml";
    std::ofstream(config) << s;
  }
  const fs::path c_out = work / "colza", y_out = work / "yade";
  std::printf("crosscheck: oedometer %s: running colza and YADE...\n", size.c_str());
  std::fflush(stdout);
  if (!ctx.runs.run_colza("oedometer", config, c_out) || !ctx.runs.run_yade("run_oedometer.py", config, y_out)) {
    report.fail("oedometer " + size, ctx.runs.failure(c_out, y_out));
    return;
  }
  ctx.speed.add(c_out, y_out, "oedometer " + size);
  try {
    compare_oedometer_curves(report, "oed " + size, read_csv(c_out / "curve.csv"), read_csv(y_out / "curve.csv"), tolerances,
                             read_json(c_out / "summary.json"), read_json(y_out / "summary.json"), config);
  } catch (const std::exception& e) {
    report.fail("oedometer " + size, e.what());
  }
  compare_ensemble(ctx, report, "oed " + size, tolerances, config, work, c_out, y_out);
}

}  // namespace crosscheck
