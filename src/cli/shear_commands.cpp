#include "cli/shear_commands.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <optional>
#include <sstream>

#include "analysis/inertial_number.hpp"
#include "analysis/mohr_coulomb.hpp"
#include "analysis/shear_curve_features.hpp"
#include "cli/command_common.hpp"
#include "config/config_error.hpp"
#include "core/concurrent.hpp"
#include "core/version.hpp"
#include "io/fingerprint.hpp"
#include "io/format_number.hpp"
#include "io/hdf5_writer.hpp"
#include "io/lab_features_json.hpp"
#include "io/load_label.hpp"
#include "io/output_dir.hpp"
#include "io/scenario_inertial_numbers.hpp"
#include "io/packing_file.hpp"
#include "io/summary.hpp"
#include "scenario/shear_box.hpp"

namespace colza {

namespace fs = std::filesystem;

namespace {

// FNV-1a 64 of the configuration as used, without the list of loads, and of the packing
// file's contents when the config names one (a file regenerated at the same path is another
// sample): finished loads and the prepared sample are reused only by a series with the same
// fingerprint.
std::string config_fingerprint(const RunConfig& c) {
  toml::table doc = toml::parse(c.resolved_toml);
  if (auto* box = doc["shear_box"].as_table()) box->erase("normal_stresses");
  std::ostringstream text;
  text << doc << file_contents_line(c.shear_box.packing_file);
  return fingerprint_text(text.str());
}

// What a user must not miss in a shear load's result: printed as WARNING lines and kept in
// summary.json's "warnings". A mean stress error past this during shearing means the servo
// did not hold the load (the paper's speed gives ~0.2 %, ten times it ~2 %).
constexpr double kHeldStressError = 0.10;

// The whole curve's features (analysis/shear_curve_features.hpp) from the recorded rows, as
// for a measured curve: peak over a trailing 1 mm, secant stiffness to half the peak.
ShearCurveSettings shear_feature_settings(const RunConfig& c) {
  ShearCurveSettings s;
  s.window = {c.shear_box.strength_window_start, c.shear_box.strength_window_end};
  return s;
}

std::vector<std::string> load_warnings(const RunConfig& c, const ShearSample& sample, const ShearLoadResult& r,
                                       bool series) {
  std::vector<std::string> w = settings_warnings(c, Scenario::kShear, series, {r.normal_stress_target});
  if (!sample.settling.converged) w.push_back(settling_warning(c, sample.settling));  // a packing file's is converged
  if (!r.consolidated)
    w.push_back("the plate did not hold the normal stress within shear_box.consolidation_tolerance before "
                "shear_box.consolidation_max_time = " + format_shortest(c.shear_box.consolidation_max_time) +
                " s; shearing began anyway");
  if (c.shear_box.preconsolidation_stress > 0.0 && !r.preconsolidated)
    w.push_back("the plate did not hold shear_box.preconsolidation_stress = " +
                format_shortest(c.shear_box.preconsolidation_stress) + " Pa within shear_box.consolidation_max_time; "
                "the sample was unloaded to the normal stress anyway");
  if (r.mean_normal_stress_error > kHeldStressError)
    w.push_back("during shearing the normal stress was " + format_significant(r.mean_normal_stress, 4) +
                " Pa on average against " + format_shortest(r.normal_stress_target) + " Pa (mean error " +
                format_significant(100.0 * r.mean_normal_stress_error, 3) + " %): the servo did not hold it" +
                (r.normal_stress_target < 1000.0 ? " (normal stresses are in Pa)" : ""));
  if (r.particles_outside > 0)
    w.push_back(std::to_string(r.particles_outside) + (r.particles_outside == 1 ? " particle" : " particles") +
                " ended outside the box");
  // The shear plane must pass through the sample: a plate that came to rest less than a
  // sphere above it (a sparse packing file; a generated sample too shallow is refused before
  // the run, config/sample_depth.hpp) shears (almost) nothing of it.
  const std::vector<double>& plate = r.curve.column("plate_height");
  const double plane = c.shear_box.shear_plane;
  if (!plate.empty() && plate.front() < plane + c.particle.diameter_max)
    w.push_back("the plate came to rest at " + format_significant(1e3 * plate.front(), 4) +
                " mm, not particle.diameter_max above the shear plane at " + format_significant(1e3 * plane, 4) +
                " mm (shear_box.shear_plane): the upper half holds (almost) no sample, and this shear strength is "
                "not the sample's");
  double inertial_number = 0.0;
  inertial_number_json(shear_inertial_inputs(c, r.normal_stress_target), inertial_number);
  if (inertial_number > kQuasiStaticInertialNumber)
    w.push_back("the inertial number is " + format_significant(inertial_number, 3) + ", above " +
                format_shortest(kQuasiStaticInertialNumber) +
                ": the test is not quasi-static and its strength depends on shear_box.shear_speed");
  return w;
}

// `series`: the load is one of shear_box.normal_stresses (else --normal-stress's).
nlohmann::json load_summary(const RunConfig& c, const ShearSample& sample, const ShearLoadResult& r, int threads,
                            bool series) {
  nlohmann::json s = common_summary(c, "shear", threads);
  s["edge_contacts"] = to_string(c.shear_box.edge_contacts);
  s["config_fingerprint"] = config_fingerprint(c);
  s["particles"] = r.particles;
  s["particles_generated"] = sample.generated;
  s["normal_stress"] = r.normal_stress_target;
  s["shear_strength"] = r.shear_strength;
  s["strength_window"] = {c.shear_box.strength_window_start, c.shear_box.strength_window_end};
  s["peak_shear_stress"] = r.peak_shear_stress;
  const ShearCurveSettings features = shear_feature_settings(c);
  s["curve_features"] = shear_features_json(
      shear_curve_features(r.curve.column("shear_displacement"), r.curve.column("shear_stress"),
                           r.curve.column("plate_height"), features),
      features);
  double inertial_number = 0.0;
  s["inertial_number"] = inertial_number_json(shear_inertial_inputs(c, r.normal_stress_target), inertial_number);
  s["mean_normal_stress"] = r.mean_normal_stress;
  s["mean_normal_stress_error"] = r.mean_normal_stress_error;
  s["consolidated"] = r.consolidated;
  s["consolidation_time"] = r.consolidation_time;
  s["preconsolidation_stress"] = c.shear_box.preconsolidation_stress;
  if (c.shear_box.preconsolidation_stress > 0.0) s["preconsolidated"] = r.preconsolidated;
  s["particles_outside"] = r.particles_outside;
  s["warnings"] = load_warnings(c, sample, r, series);
  s["bond_install"] = to_string(c.contact.bond_install);
  s["bonds_installed"] = r.bonds_installed;
  s["bonds_broken_tension"] = r.bonds_broken_tension;
  s["bonds_broken_shear"] = r.bonds_broken_shear;
  // The sample's settling, when this run settled it (not from a packing file, nor a resumed
  // series' sample); "steps" are the load's own, consolidation and shearing.
  if (sample.settling.in_this_run()) s["settling"] = settling_json(c, sample.settling);
  s["dt"] = r.dt;
  s["steps"] = r.steps;
  add_snapshots_summary(s, r.snapshots);
  add_timing(s, r.stages);
  return s;
}

void write_load(OutputStaging& out, const RunConfig& c, const ShearLoadResult& r, const nlohmann::json& s) {
  write_csv(out.path("curve.csv"), r.curve);
  write_result_h5(out, "shear", c, s, "curve", r.curve, {{"particles/final", &r.final_state}}, &r.snapshots);
  write_json(out.path("summary.json"), s);
}

void print_load(const ShearLoadResult& r, const nlohmann::json& summary) {
  std::printf("  sigma %.2f kPa: shear strength %.3f kPa (peak %.3f), normal stress held %.2f kPa (mean error %.2f %%)%s, "
              "%zu outside, %.1f s wall\n",
              r.normal_stress_target * 1e-3, r.shear_strength * 1e-3, r.peak_shear_stress * 1e-3,
              r.mean_normal_stress * 1e-3, 100.0 * r.mean_normal_stress_error,
              r.consolidated ? "" : ", NOT consolidated within the time limit", r.particles_outside,
              total_wall_seconds(r.stages));
  for (const auto& warning : summary["warnings"]) std::printf("    WARNING: %s\n", warning.get<std::string>().c_str());
}

}  // namespace

void run_shear_scenario(const RunConfig& c, const RunOptions& opt, OutputStaging& out) {
  Progress progress(!opt.quiet);
  const ShearSample sample = prepare_shear_sample(c, progress);
  write_packing(out.path("packing.txt"), sample.particles);
  const ShearLoadResult r = run_shear_load(c, sample, opt.normal_stress, progress, c.output.snapshot_interval);
  nlohmann::json s = load_summary(c, sample, r, opt.threads, /*series=*/false);
  std::vector<StageTiming> stages = sample.stages;
  stages.insert(stages.end(), r.stages.begin(), r.stages.end());
  add_timing(s, stages);
  write_load(out, c, r, s);
  if (c.shear_box.packing_file.empty())
    std::printf("shear: %zu particles (%zu generated)\n", r.particles, sample.generated);
  else
    std::printf("shear: %zu particles (read from %s)\n", r.particles, c.shear_box.packing_file.c_str());
  print_load(r, s);
}

namespace {

// Where a series writes. A new series, or one resumed (no --force), writes straight into
// --out: each load appears, complete, as soon as it is done, and a stopped series keeps the
// finished loads for the next start. With --force the whole new series is built in a
// staging folder and replaces the earlier one only once every load is done, so a stopped
// or failed run leaves the earlier result as it was.
class SeriesOutput {
 public:
  // `load_dirs`: the series' load folders. With --force, one that exists in dir and is not
  // part of an earlier colza result (a user's folder) stops the series before it runs.
  SeriesOutput(const fs::path& dir, bool force, const std::vector<std::string>& load_dirs) : dir_(dir) {
    std::error_code ec;
    if (force) {
      stale_ = earlier_run_outputs(dir);
      for (const auto& name : load_dirs)
        if (fs::exists(dir / name, ec) && std::find(stale_.begin(), stale_.end(), name) == stale_.end())
          throw ConfigError("--out " + dir.string(), "",
                            "holds " + name + ", which is not part of an earlier colza result and which this series "
                            "would replace; move it away and run again");
      staging_.emplace(dir, /*overwrite=*/true);
    } else {
      fs::create_directories(dir, ec);
      if (ec) throw ConfigError("--out " + dir.string(), "", "cannot create the directory: " + ec.message());
    }
  }
  std::string path(const std::string& name) { return staging_ ? staging_->path(name) : (dir_ / name).string(); }
  void commit_summary(const nlohmann::json& summary) {
    if (staging_) {
      write_json(staging_->path("summary.json"), summary);
      staging_->commit(stale_);
      return;
    }
    OutputStaging out(dir_, /*overwrite=*/true);  // an earlier summary was refused unless --force
    write_json(out.path("summary.json"), summary);
    out.commit();
  }

 private:
  fs::path dir_;
  std::optional<OutputStaging> staging_;
  std::vector<std::string> stale_;
};

// The fingerprint holds the config, not the code: what another build made stands only if
// the physics did not change in between.
void warn_if_made_by_another_build(const nlohmann::json& made, const std::string& what) {
  const std::string made_by = made.value("git_revision", "unknown");
  if (made_by != git_revision())
    std::fprintf(stderr, "colza: warning: reusing %s made by colza %s (this is %s); pass --force to make it again\n",
                 what.c_str(), made_by.c_str(), git_revision());
}

}  // namespace

int run_shear_series(const RunConfig& config, const RunOptions& opt) {
  const auto t_start = std::chrono::steady_clock::now();
  const fs::path dir(opt.out_dir);
  // run_command has checked --out: a finished series is not overwritten without --force; an
  // unfinished one (its sample.json) is resumed.
  std::vector<std::string> load_names;
  for (double sigma : config.shear_box.normal_stresses) load_names.push_back(load_label(sigma));
  SeriesOutput out(dir, opt.force, load_names);
  const std::string fingerprint = config_fingerprint(config);

  // --- the sample, shared by all loads (reused by a resumed series) ----------------
  RunConfig c = config;
  Progress progress(!opt.quiet && opt.jobs <= 1);
  ShearSample sample;
  const fs::path sample_info = dir / "sample.json";
  const bool resumed = !opt.force && fs::exists(sample_info);
  if (resumed) {
    const nlohmann::json earlier = read_json_file(sample_info.string());
    require_fields(earlier, sample_info.string(),
                   {{"config_fingerprint", JsonField::kString, true},
                    {"particles_generated", JsonField::kNumber},
                    {"git_revision", JsonField::kString}});
    if (!fs::exists(dir / "packing.txt"))
      throw ConfigError((dir / "packing.txt").string(), "",
                        "is missing next to sample.json: the finished loads were run on a sample that is gone; pass "
                        "--force to start the series again");
    // An unfinished series of another configuration is not silently replaced: its loads
    // would stay next to the new ones.
    if (earlier["config_fingerprint"] != fingerprint)
      throw ConfigError("--out " + dir.string(), "",
                        "holds an unfinished series of another configuration (sample.json's config_fingerprint "
                        "differs); pass --force to replace it, or choose another directory");
    RunConfig from_file = c;
    from_file.shear_box.packing_file = (dir / "packing.txt").string();
    sample = prepare_shear_sample(from_file, progress);
    sample.generated = earlier.value("particles_generated", sample.generated);
    warn_if_made_by_another_build(earlier, "the sample (packing.txt)");
  } else {
    sample = prepare_shear_sample(c, progress);
    write_packing_atomically(out.path("packing.txt"), sample.particles);
    nlohmann::json info = {{"config_fingerprint", fingerprint},
                           {"git_revision", git_revision()},
                           {"particles", sample.particles.size()},
                           {"particles_generated", sample.generated},
                           {"settling_converged", sample.settling.converged},
                           {"stages", stages_json(sample.stages)}};
    write_text_atomically(out.path("sample.json"), info.dump(2) + "\n");
  }
  const std::size_t load_count = c.shear_box.normal_stresses.size();
  std::printf("shear series: %zu particles (%zu generated)%s, %zu load%s, %d job(s)\n", sample.particles.size(),
              sample.generated, resumed ? ", sample reused" : "", load_count, load_count == 1 ? "" : "s", opt.jobs);

  // --- loads ------------------------------------------------------------------------
  const auto& loads = c.shear_box.normal_stresses;
  std::vector<double> strength(loads.size(), 0.0);
  std::vector<nlohmann::json> load_json(loads.size());
  std::vector<std::size_t> todo;
  for (std::size_t k = 0; k < loads.size(); ++k) {
    const fs::path summary = dir / load_names[k] / "summary.json";
    if (!opt.force && fs::exists(summary)) {
      const std::string advice = "remove the load's folder, or pass --force";
      const auto s = read_json_file(summary.string(), advice);
      require_fields(s, summary.string(),
                     {{"config_fingerprint", JsonField::kString}, {"normal_stress", JsonField::kNumber},
                      {"shear_strength", JsonField::kNumber, true}, {"mean_normal_stress", JsonField::kNumber},
                      {"consolidated", JsonField::kBoolean}, {"particles_outside", JsonField::kNumber},
                      {"wall_seconds", JsonField::kNumber}, {"git_revision", JsonField::kString}},
                     advice);
      if (s.value("config_fingerprint", "") == fingerprint && s.value("normal_stress", -1.0) == loads[k]) {
        strength[k] = s["shear_strength"].get<double>();
        load_json[k] = s;
        load_json[k]["reused"] = true;
        std::printf("  sigma %.2f kPa: reusing the finished load in %s\n", loads[k] * 1e-3, load_names[k].c_str());
        warn_if_made_by_another_build(s, load_names[k]);
        continue;
      }
    }
    todo.push_back(k);
  }
  // Each load's folder, named before the loads run side by side (SeriesOutput::path is not
  // thread-safe: with --force it notes the name for the final move).
  std::vector<std::string> load_dirs(loads.size());
  for (std::size_t k : todo) load_dirs[k] = out.path(load_names[k]);
  std::mutex mutex;  // guards the per-load results and stdout
  run_concurrently(todo.size(), opt.jobs, [&](std::size_t t) {
    const std::size_t k = todo[t];
    Progress load_progress(!opt.quiet && opt.jobs <= 1);
    const ShearLoadResult r = run_shear_load(c, sample, loads[k], load_progress, c.output.snapshot_interval);
    nlohmann::json s = load_summary(c, sample, r, opt.threads, /*series=*/true);
    OutputStaging load_out(load_dirs[k], true);
    write_load(load_out, c, r, s);
    load_out.commit();
    std::lock_guard<std::mutex> lock(mutex);
    strength[k] = r.shear_strength;
    load_json[k] = s;
    load_json[k]["reused"] = false;
    print_load(r, s);
    std::fflush(stdout);
  });

  // --- Mohr-Coulomb line ----------------------------------------------------------
  nlohmann::json s = common_summary(c, "shear-series", opt.threads);
  s["edge_contacts"] = to_string(c.shear_box.edge_contacts);
  s["config_fingerprint"] = fingerprint;
  s["particles"] = sample.particles.size();
  s["particles_generated"] = sample.generated;
  s["warnings"] = settings_warnings(c, Scenario::kShear, /*series=*/true, loads);
  s["loads"] = nlohmann::json::array();
  for (std::size_t k = 0; k < loads.size(); ++k)
    s["loads"].push_back({{"normal_stress", loads[k]},
                          {"shear_strength", strength[k]},
                          {"mean_normal_stress", load_json[k].value("mean_normal_stress", 0.0)},
                          {"consolidated", load_json[k].value("consolidated", false)},
                          {"particles_outside", load_json[k].value("particles_outside", 0)},
                          {"wall_seconds", load_json[k].value("wall_seconds", 0.0)},
                          {"reused", load_json[k].value("reused", false)},
                          // null for a load reused from a build before these were reported
                          {"curve_features", load_json[k].value("curve_features", nlohmann::json(nullptr))},
                          {"inertial_number", load_json[k].contains("inertial_number")
                                                  ? load_json[k]["inertial_number"].value("value", nlohmann::json(nullptr))
                                                  : nlohmann::json(nullptr)},
                          {"directory", load_names[k]}});
  if (loads.size() >= 2) {
    const MohrCoulombFit mc = fit_mohr_coulomb(loads, strength);
    s["cohesion"] = mc.cohesion;
    s["friction_angle_deg"] = mc.friction_angle_deg;
    s["r2"] = mc.r2;
    if (mc.degrees_of_freedom > 0) {
      s["cohesion_standard_error"] = mc.cohesion_se;
      s["friction_angle_standard_error_deg"] = mc.friction_angle_se_deg;
      s["degrees_of_freedom"] = mc.degrees_of_freedom;
      std::printf("Mohr-Coulomb: C = %.3f +/- %.3f kPa, Phi = %.2f +/- %.2f deg (standard errors, %d degree(s) of "
                  "freedom), R^2 = %.4f\n",
                  mc.cohesion * 1e-3, mc.cohesion_se * 1e-3, mc.friction_angle_deg, mc.friction_angle_se_deg,
                  mc.degrees_of_freedom, mc.r2);
      if (const std::string note = cohesion_note(mc); !note.empty()) {
        s["cohesion_note"] = note;
        std::printf("  NOTE: %s\n", note.c_str());
      }
    } else {
      std::printf("Mohr-Coulomb: C = %.3f kPa, Phi = %.2f deg (two loads: a line through two points, no standard "
                  "error)\n",
                  mc.cohesion * 1e-3, mc.friction_angle_deg);
    }
  }
  s["wall_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  s["jobs"] = opt.jobs;
  out.commit_summary(s);
  return 0;
}

}  // namespace colza
