// crosscheck shear: the direct shear box. colza makes the sample once (generation, settling
// and cut: its packing.txt); then, from that packing, (1) a short deterministic run (the
// stress is not consolidated, shearing starts at once) must coincide in both codes like the
// micro scenes, and (2) every load of [shear.<size>] runs the full protocol in both codes
// (servo consolidation, bonds, shearing); the shear strength, the mean normal stress, the
// shear-stress curve over the strength window and the Mohr-Coulomb C and Phi of the loads are
// compared.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#include "checks.hpp"
#include "analysis/curve_comparison.hpp"
#include "ensemble_runs.hpp"
#include "result_files.hpp"
#include "shear_setting.hpp"

namespace crosscheck {

void compare_shear_start(Report& report, const std::string& label, const Csv& c, const Csv& y, const Tolerance& relative) {
  if (c.rows() != y.rows() || c.rows() == 0) throw std::runtime_error("different numbers of curve rows");
  for (const char* q : {"shear_stress", "normal_stress"}) {
    const colza::MaxDifference d = colza::max_difference(c.at(q), y.at(q), c.rows());
    report.check(label + " start, " + q + " (" + std::to_string(c.rows()) + " rows, max |diff| / max)", d.max_colza,
                 d.max_yade, d.relative, Measure::kRelative, relative);
  }
  // max_magnitude, not std::max, so that a count that is not finite is not skipped; each code's
  // shown count (its last contact count) is NaN then, and the row says which code's was.
  double dmax = 0.0, c_max_count = 0.0, y_max_count = 0.0;
  for (std::size_t r = 0; r < c.rows(); ++r)
    for (const char* q : {"contacts", "bonds"}) {
      dmax = colza::max_magnitude(dmax, c.at(q)[r] - y.at(q)[r]);
      c_max_count = colza::max_magnitude(c_max_count, c.at(q)[r]);
      y_max_count = colza::max_magnitude(y_max_count, y.at(q)[r]);
    }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  report.check(label + " start, contacts and bonds (max |diff|)", std::isnan(c_max_count) ? nan : c.at("contacts").back(),
               std::isnan(y_max_count) ? nan : y.at("contacts").back(), dmax, Measure::kAbsolute, fixed_tolerance(0.0), "%.0f");
}

namespace {

// The normal stresses (Pa) to run: --loads, or [shear.<size>] loads. Never empty, and no two
// share a run folder: main refuses such --loads, and read_tolerances a table without loads
// or with two the same to the pascal.
std::vector<double> loads_to_run(const CheckContext& ctx, const ShearSetting& s, Report& report) {
  std::vector<double> loads = ctx.opt.loads;
  if (!loads.empty()) {
    std::string list;
    for (double l : loads) list += (list.empty() ? "" : ", ") + fmt(1e-3 * l, "%.2f");
    report.note(s.label + ": the loads given by --loads (" + list + " kPa), not those of [" + s.base + "]");
  } else if (const auto* a = s.t.at_path("loads").as_array()) {
    for (const auto& n : *a) loads.push_back(n.value<double>().value_or(0.0));
  }
  return loads;
}

// The sample's packing file, made by colza (the load of this run is cut short: it only makes
// packing.txt) and kept in the work dir for the next cross-check while the scene and colza
// stay the same (Reuse::kIfSameInputs); nothing (and a failed row) if colza could not make it.
// The run's normal stress is the table's first load whatever --loads says (`loads[0]` only
// when the table has none): the sample does not depend on it (packing.txt is written before
// the load), and another value would be another stamp, so the sample would be made again.
std::optional<fs::path> shear_sample(const CheckContext& ctx, const ShearSetting& s, Report& report,
                                     const std::vector<double>& loads) {
  double sample_load = loads.at(0);
  if (const auto* table_loads = s.t.at_path("loads").as_array(); table_loads && !table_loads->empty())
    sample_load = table_loads->get(0)->value<double>().value_or(sample_load);
  const fs::path prep = s.work / "sample";
  std::printf("crosscheck: %s: the sample (colza: generation, settling, cut)...\n", s.label.c_str());
  std::fflush(stdout);
  if (!ctx.runs.run_colza("shear", s.scene, prep,
                          {"shear_box.consolidation_max_time=1e-9", "shear_box.strength_window_start=0",
                           "shear_box.strength_window_end=1e-9", "shear_box.shear_displacement=1e-9"},
                          normal_stress_argument(sample_load), Reuse::kIfSameInputs)) {
    report.fail(s.label, "colza could not make the sample: " + ctx.runs.failure(prep));
    return std::nullopt;
  }
  return fs::absolute(prep / "packing.txt");
}

// Deterministic start: no consolidation (the servo runs 4 steps), shearing at once for
// early_steps; before chaos sets in the two codes must coincide.
void compare_deterministic_start(const CheckContext& ctx, const ShearSetting& s, Report& report,
                                 const toml::table& doc, double first_load) {
  const toml::table& box = *doc["shear_box"].as_table();
  const double dt = doc.at_path("integration.time_step").value_or(0.0);
  const double speed = box.at_path("shear_speed").value_or(0.005);
  const double early_steps = tol_number(s.t, "early_steps", 400);
  const double disp = early_steps * dt * speed;
  toml::table e = doc;
  toml::table& eb = *e["shear_box"].as_table();
  eb.insert_or_assign("consolidation_max_time", 4 * dt);
  eb.insert_or_assign("shear_displacement", disp);
  eb.insert_or_assign("strength_window_start", 0.0);
  eb.insert_or_assign("strength_window_end", disp);
  eb.insert_or_assign("record_interval", 10);
  const fs::path econfig = write_config(s, e, "shear_" + s.size + "_early.toml");
  const fs::path c_out = s.work / "colza_early", y_out = s.work / "yade_early";
  const std::vector<std::string> sigma = normal_stress_argument(first_load);
  std::printf("crosscheck: %s: deterministic start (%g steps)...\n", s.label.c_str(), early_steps);
  std::fflush(stdout);
  if (!ctx.runs.run_colza("shear", econfig, c_out, {}, sigma) || !ctx.runs.run_yade("run_shear.py", econfig, y_out, sigma)) {
    report.fail(s.label + " deterministic start", ctx.runs.failure(c_out, y_out));
    return;
  }
  try {
    compare_shear_start(report, s.label, read_csv(c_out / "curve.csv"), read_csv(y_out / "curve.csv"),
                        s.tolerances().get("early_relative", 1e-6));
  } catch (const std::exception& ex) {
    report.fail(s.label + " deterministic start", ex.what());
  }
}

// A row of one realisation's strength-like quantity: judged against the tolerance `key`, or,
// when the ensemble judges it (`by_ensemble`), an information row: one realisation's scatter
// is too wide for a tolerance with any power (crosscheck/README.md, "Ensembles").
void check_one_realisation(Report& report, bool by_ensemble, const std::string& metric, double colza, double yade,
                           double difference, Measure measure, const ShearSetting& s, const char* key, double fallback,
                           const char* f) {
  if (by_ensemble)
    report.info(metric + ", one realisation", fmt(colza, f), fmt(yade, f),
                "difference " + fmt(difference, "%.3g") + ": judged by the ensemble");
  else
    report.check(metric, colza, yade, difference, measure, s.tolerances().get(key, fallback), f);
}

// One load, full protocol, in both codes: the rows of its comparison, and both codes' shear
// strengths (Pa) if it ran and was read. With `by_ensemble` its strength and curve rows are
// information only.
std::optional<std::pair<double, double>> compare_load(const CheckContext& ctx, const ShearSetting& s,
                                                      Report& report, const fs::path& config, double sigma,
                                                      double window_start, double window_end, bool by_ensemble) {
  const std::string l = s.label + " " + fmt(1e-3 * sigma, "%.2f") + " kPa";
  const fs::path c_out = load_run_folder(s, "colza", sigma, 0), y_out = load_run_folder(s, "yade", sigma, 0);
  const std::vector<std::string> arg = normal_stress_argument(sigma);
  std::printf("crosscheck: %s: running colza and YADE...\n", l.c_str());
  std::fflush(stdout);
  if (!ctx.runs.run_colza("shear", config, c_out, {}, arg) || !ctx.runs.run_yade("run_shear.py", config, y_out, arg)) {
    report.fail(l, ctx.runs.failure(c_out, y_out));
    return std::nullopt;
  }
  ctx.speed.add(c_out, y_out, s.label);
  try {
    const auto cs = read_json(c_out / "summary.json"), ys = read_json(y_out / "summary.json");
    const Csv c = read_csv(c_out / "curve.csv"), y = read_csv(y_out / "curve.csv");
    check_same_count(report, l + " particles", cs, ys, "particles");
    const bool both = cs.value("consolidated", false) && ys.value("consolidated", false);
    report.add(Row{l + " consolidated", cs.value("consolidated", false) ? "yes" : "no",
                   ys.value("consolidated", false) ? "yes" : "no", "-", "", "both", both, false, "(fixed)"});
    report.info(l + " consolidation time (s)", fmt(cs.value("consolidation_time", 0.0)),
                fmt(ys.value("consolidation_time", 0.0)), "chaotic, not compared");
    const double c_tau = cs.value("shear_strength", 0.0), y_tau = ys.value("shear_strength", 0.0);
    check_one_realisation(report, by_ensemble, l + " shear strength (kPa; difference / colza's)", 1e-3 * c_tau,
                          1e-3 * y_tau, std::abs(c_tau - y_tau) / std::abs(c_tau), Measure::kRelative, s,
                          "strength_relative", 0.1, "%.3f");
    const double c_sig = cs.value("mean_normal_stress", 0.0), y_sig = ys.value("mean_normal_stress", 0.0);
    report.check(l + " mean normal stress (kPa; difference / colza's)", 1e-3 * c_sig, 1e-3 * y_sig,
                 std::abs(c_sig - y_sig) / std::abs(c_sig), Measure::kRelative,
                 s.tolerances().get("normal_stress_relative", 0.01), "%.3f");
    // shear stress over the strength window, YADE interpolated at colza's offsets
    const colza::RmsDifference d = colza::rms_difference(c.at("shear_displacement"), c.at("shear_stress"),
                                           y.at("shear_displacement"), y.at("shear_stress"), window_start, window_end);
    check_one_realisation(report, by_ensemble,
                          l + " shear stress rms difference / rms (" + std::to_string(d.n) + " rows, " +
                              fmt(1e3 * window_start, "%.2f") + "-" + fmt(1e3 * window_end, "%.2f") + " mm, kPa)",
                          1e-3 * d.rms_colza, 1e-3 * d.rms_yade, d.relative, Measure::kRelative, s, "curve_rms_relative",
                          0.2, "%.4g");
    const double c_out_n = cs.value("particles_outside", kMissingValue), y_out_n = ys.value("particles_outside", kMissingValue);
    report.add(Row{l + " particles outside the box", fmt(c_out_n, "%.0f"), fmt(y_out_n, "%.0f"), "-", "", "0",
                   c_out_n == 0.0 && y_out_n == 0.0, false, "(fixed)"});
    return std::make_pair(c_tau, y_tau);
  } catch (const std::exception& e) {
    report.fail(l, e.what());
    return std::nullopt;
  }
}

}  // namespace

void check_shear(const CheckContext& ctx, Report& report, const std::string& size) {
  const toml::table* t = size_section(ctx, report, "shear", size);
  if (!t) return;
  const ShearSetting s{size, "shear." + size, "shear " + size, *t, ctx.opt.source / t->at_path("config").value_or(std::string()),
                       ctx.opt.workdir / ("shear_" + size)};
  fs::create_directories(s.work);
  toml::table doc;
  try {
    doc = toml::parse_file(s.scene.string());
  } catch (const std::exception& e) {
    report.fail(s.label, "cannot read " + s.scene.string() + ": " + e.what());
    return;
  }
  toml::table* box = doc["shear_box"].as_table();
  if (!box) {
    report.fail(s.label, s.scene.string() + " has no [shear_box]");
    return;
  }
  const std::vector<double> loads = loads_to_run(ctx, s, report);
  // 1. The sample.
  const std::optional<fs::path> packing = shear_sample(ctx, s, report, loads);
  if (!packing) return;
  box->insert_or_assign("packing_file", packing->string());
  // The tolerances table may shorten the shearing (a YADE load of the full box to 30 mm
  // takes hours): these keys replace the scene's and are printed with the table.
  for (const char* key : {"shear_displacement", "strength_window_start", "strength_window_end"})
    if (const auto v = t->at_path(key).value<double>()) {
      box->insert_or_assign(key, *v);
      std::printf("crosscheck: %s: shear_box.%s = %g (from [%s])\n", s.label.c_str(), key, *v, s.base.c_str());
    }
  const fs::path config = write_config(s, doc, "shear_" + size + ".toml");
  const double window_start = box->at_path("strength_window_start").value_or(0.020);
  const double window_end = box->at_path("strength_window_end").value_or(0.030);

  // 2. Deterministic start.
  compare_deterministic_start(ctx, s, report, doc, loads[0]);

  // 3. The loads, full protocol (with an ensemble to follow, one realisation's strength and
  // curve rows are information only).
  const bool by_ensemble = read_ensemble(s.tolerances()).realisations >= 2;
  std::vector<double> c_strength, y_strength;
  for (double sigma : loads)
    if (const auto strengths = compare_load(ctx, s, report, config, sigma, window_start, window_end, by_ensemble)) {
      c_strength.push_back(strengths->first);
      y_strength.push_back(strengths->second);
    }
  // 4. Mohr-Coulomb line through (nominal load, strength), as colza's shear-series.
  if (c_strength.size() == loads.size() && loads.size() >= 2) {
    const auto [cc, cphi] = colza::mohr_coulomb(loads, c_strength);
    const auto [yc, yphi] = colza::mohr_coulomb(loads, y_strength);
    check_one_realisation(report, by_ensemble, s.label + " cohesion C (kPa)", 1e-3 * cc, 1e-3 * yc,
                          1e-3 * std::abs(cc - yc), Measure::kAbsolute, s, "cohesion_absolute_kpa", 5.0, "%.3f");
    check_one_realisation(report, by_ensemble, s.label + " friction angle Phi (deg)", cphi, yphi, std::abs(cphi - yphi),
                          Measure::kAbsolute, s, "friction_angle_absolute_deg", 5.0, "%.2f");
  }

  // 5. More realisations of every load: means against standard errors.
  compare_shear_ensemble(ctx, s, report, doc, loads);
}

}  // namespace crosscheck
