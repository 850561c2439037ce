#include "calibration/run_cache.hpp"

#include "calibration/run_features.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <toml++/toml.h>
#include <unistd.h>
#include <utility>

#include "analysis/mohr_coulomb.hpp"
#include "core/unstable_motion.hpp"
#include "core/version.hpp"
#include "io/fingerprint.hpp"
#include "io/load_label.hpp"
#include "io/output_dir.hpp"
#include "io/packing_file.hpp"
#include "io/progress.hpp"
#include "io/summary.hpp"
#include "io/table.hpp"
#include "scenario/oedometer.hpp"
#include "scenario/repose.hpp"

namespace colza::calibration {

namespace fs = std::filesystem;

namespace {

// A scratch name no other process uses: calibrations that share one runs directory
// (--runs) may compute the same run at the same time; each writes in its own scratch
// folder and the last rename wins with identical content (same fingerprint, same bits).
std::string process_unique(const std::string& name) { return name + "." + std::to_string(::getpid()); }

// A scratch folder removed when its scope ends, also when the run in it throws or is
// interrupted (Ctrl-C), so a stopped run leaves nothing half-written behind.
struct ScratchFolder {
  fs::path path;
  explicit ScratchFolder(fs::path p) : path(std::move(p)) { fs::remove_all(path); }
  ~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The packing file a configuration names for its scenario ("" when the seed makes the sample).
std::string named_packing_file(const RunConfig& c, Scenario scenario) {
  if (scenario == Scenario::kShear) return c.shear_box.packing_file;
  if (scenario == Scenario::kOedometer) return c.oedometer.packing_file;
  return "";
}

// One oedometer run: its outputs, and its curve written to dir/curve.csv.
nlohmann::json run_oedometer_outputs(const RunConfig& c, const fs::path& dir, double& wall) {
  Progress quiet(false);
  const auto t0 = std::chrono::steady_clock::now();
  const OedometerResult r = run_oedometer(c, quiet);
  wall = seconds_since(t0);
  nlohmann::json out = {{"bulk_density", r.bulk_density},
                        {"packing_height", r.packing_height},
                        {"particles", r.particles},
                        {"settling_converged", r.settling.converged},
                        {"max_force", r.max_force},
                        {"stop_reason", r.stop_reason},
                        {"fit_valid", r.fit.valid},
                        {"fit_reached_force_max", r.fit.reached_force_max}};
  if (r.fit.valid) {
    out["c0"] = r.fit.fit.coefficients[0];
    out["c1"] = r.fit.fit.coefficients[1];
    out["c2"] = r.fit.fit.coefficients[2];
    out["fit_r2"] = r.fit.fit.r2;
  }
  // A load-unload run's branch and cycle features (run_features.hpp names).
  if (!c.oedometer.cycles.targets.empty())
    for (const auto& [name, value] : load_unload_features(r.cycles)) out[name] = value;
  fs::create_directories(dir);
  write_csv((dir / "curve.csv").string(), r.curve);
  return out;
}

// A shear series over c.shear_box.normal_stresses from one settled sample: its outputs (each
// load's, and the Mohr-Coulomb line through the window strengths) and each load's curve.
nlohmann::json run_shear_outputs(const RunConfig& c, const ShearSample& sample, double& wall,
                                 std::vector<Table>& curves) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<double>& loads = c.shear_box.normal_stresses;
  const std::size_t n = loads.size();
  std::vector<double> tau(n);
  std::vector<nlohmann::json> load_json(n);
  curves.assign(n, Table{});
  // With two threads or more the loads run side by side, min(threads, loads) at a time with
  // threads / that many each (the remainder idles: 3 threads, 2 loads: one each): two loads
  // at one thread each beat one after the other at two (the force loop scales by ~1.8 on
  // two threads). Same bits at any thread count.
  const int threads = worker_threads_here();
  const int side_by_side = std::max(1, std::min(threads, static_cast<int>(n)));
  run_concurrently(
      n, side_by_side,
      [&](std::size_t k) {
        Progress quiet(false);
        const ShearLoadResult r = run_shear_load(c, sample, loads[k], quiet);
        tau[k] = r.shear_strength;
        curves[k] = r.curve;
        load_json[k] = {{"normal_stress", loads[k]},
                        {"shear_strength", r.shear_strength},
                        {"peak_shear_stress", r.peak_shear_stress},
                        {"consolidated", r.consolidated},
                        {"mean_normal_stress_error", r.mean_normal_stress_error},
                        {"particles_outside", r.particles_outside},
                        {"bonds_installed", r.bonds_installed}};
      },
      std::max(1, threads / side_by_side));
  nlohmann::json load_array = nlohmann::json::array();
  for (auto& l : load_json) load_array.push_back(std::move(l));
  wall = seconds_since(t0);
  const MohrCoulombFit mc = fit_mohr_coulomb(loads, tau);
  return {{"cohesion", mc.cohesion},
          {"tan_phi", mc.slope},
          {"friction_angle_deg", mc.friction_angle_deg},
          {"line_r2", mc.r2},
          {"particles", sample.particles.size()},
          {"loads", load_array}};
}

// `overrides` with, for realisation k >= 1, seed = the configuration's seed + k.
std::vector<std::string> with_seed(Scenario scenario, const std::string& config_path,
                                   const std::vector<std::string>& overrides, int replicate) {
  if (replicate == 0) return overrides;
  const std::uint64_t seed = load_run_config(scenario, config_path, overrides).seed;
  std::vector<std::string> o = overrides;
  o.push_back("seed=" + std::to_string(seed + static_cast<std::uint64_t>(replicate)));
  return o;
}

// One angle of repose run: its outputs, and the heap's profile (scenario/repose.hpp) written
// to dir/heap_profile.csv.
nlohmann::json run_repose_outputs(const RunConfig& c, const fs::path& dir, double& wall) {
  Progress quiet(false);
  const auto t0 = std::chrono::steady_clock::now();
  const ReposeResult r = run_repose(c, quiet);
  wall = seconds_since(t0);
  const HeapAngle& h = r.heap;
  nlohmann::json out = {{"particles", r.particles},
                        {"column_height", r.column_height},
                        {"column_bulk_density", r.column_bulk_density},
                        {"settling_converged", r.settling.converged},
                        {"rest_converged", r.rest.converged},
                        {"heap_fit_valid", h.valid},
                        {"heap_height", h.height},
                        {"heap_radius", h.radius},
                        {"spheres_beyond_heap", r.spheres_beyond_heap}};
  if (h.valid) {
    out["angle_of_repose_deg"] = h.angle_deg;
    out["angle_of_repose_error_deg"] = h.angle_error_deg;
    out["heap_fit_r2"] = h.r2;
  }
  fs::create_directories(dir);
  write_csv((dir / "heap_profile.csv").string(), heap_profile_table(r.final_state, r.base_height, r.heap));
  return out;
}

bool has_load_curves(const fs::path& dir, const std::vector<double>& loads) {
  for (double sigma : loads)
    if (!fs::exists(dir / shear_curve_file_name(sigma))) return false;
  return true;
}

}  // namespace

std::string shear_curve_file_name(double sigma) { return load_label(sigma) + ".csv"; }

std::string sample_fingerprint(const RunConfig& c, const std::string& packing_line) {
  toml::table doc = toml::parse(c.resolved_toml);
  if (auto* box = doc["shear_box"].as_table())
    for (const char* k : {"normal_stresses", "shear_displacement", "shear_speed", "strength_window_start",
                          "strength_window_end", "record_interval"})
      box->erase(k);
  if (auto* contact = doc["contact"].as_table()) contact->erase("contact_bond");
  std::ostringstream text;
  text << doc << packing_line;
  return fingerprint_text(text.str());
}

RunCache::RunCache(fs::path runs_dir, bool verbose) : runs_(std::move(runs_dir)), verbose_(verbose) {
  fs::create_directories(runs_);
}

std::string RunCache::packing_line(const std::string& packing_file) {
  return packing_lines_.get(packing_file, [&] { return file_contents_line(packing_file); });
}

std::pair<std::string, std::string> RunCache::shared_packing(const RunRequest& request) {
  const RunConfig c = load_run_config(Scenario::kOedometer, request.config_path,
                                      with_seed(Scenario::kOedometer, request.config_path,
                                                *request.shared_packing_overrides, request.replicate));
  const std::string fp = fingerprint_text(c.resolved_toml);
  return packings_.get(fp, [&] {
    const fs::path dir = runs_ / ("packing-" + fp);
    const fs::path file = dir / "packing.txt";
    if (!fs::exists(file)) {
      fs::create_directories(dir);
      Progress quiet(false);
      const auto t0 = std::chrono::steady_clock::now();
      const OedometerResult r = run_oedometer(c, quiet);
      write_packing_atomically(file.string(), r.settled);
      write_text_atomically(dir / "config.toml", c.resolved_toml);
      if (verbose_)
        std::printf("  shared packing (seed %llu): %zu particles settled at the design centre (%.1f s) -> %s\n",
                    static_cast<unsigned long long>(c.seed), r.particles, seconds_since(t0), file.c_str());
    }
    return std::pair<std::string, std::string>{file.string(), fp};
  });
}

RunConfig RunCache::config_for(const RunRequest& request, std::string& fp, std::string& shared_packing_file) {
  RunConfig c = load_run_config(request.scenario, request.config_path,
                                with_seed(request.scenario, request.config_path, request.overrides, request.replicate));
  std::string text = c.resolved_toml + packing_line(named_packing_file(c, request.scenario));
  shared_packing_file.clear();
  if (request.shared_packing_overrides) {
    const auto [path, packing_fp] = shared_packing(request);
    c.oedometer.packing_file = path;
    shared_packing_file = path;
    text += "\n# shared packing " + packing_fp + "\n";
  }
  fp = fingerprint_text(text);
  return c;
}

std::shared_ptr<const ShearSample> RunCache::shear_sample(const RunConfig& c, const std::string& line) {
  // One settled sample per sample fingerprint (different seeds settle at the same time);
  // every run starts from the packing file (identical start whether fresh or resumed).
  const std::string fp = sample_fingerprint(c, line);
  return samples_.get(fp, [&] {
    const fs::path dir = runs_ / ("sample-" + fp);
    const fs::path file = dir / "packing.txt";
    Progress quiet(false);
    if (!fs::exists(file)) {
      const auto t0 = std::chrono::steady_clock::now();
      const ShearSample s = prepare_shear_sample(c, quiet);
      fs::create_directories(dir);  // only now: an interrupted settling leaves no empty folder
      write_packing_atomically(file.string(), s.particles);
      if (verbose_)
        std::printf("  shear sample: %zu particles settled (%.1f s) -> %s\n", s.particles.size(), seconds_since(t0),
                    file.c_str());
    }
    RunConfig from_file = c;
    from_file.shear_box.packing_file = file.string();
    return std::make_shared<const ShearSample>(prepare_shear_sample(from_file, quiet));
  });
}

bool RunCache::reusable(const fs::path& dir, const std::string& fp, const RunConfig& c, bool needs_load_curves,
                        RunRecord& rec) const {
  const fs::path summary = dir / "summary.json";
  if (!fs::exists(summary)) return false;
  const std::string advice = "remove the run's folder to run it again";
  const auto s = read_json_file(summary.string(), advice);
  require_fields(s, summary.string(),
                 {{"fingerprint", JsonField::kString}, {"wall_seconds", JsonField::kNumber},
                  {"colza_revision", JsonField::kString}, {"outputs", JsonField::kObject}},
                 advice);
  // A finished run is reused unless the caller needs what it did not keep (the load
  // curves): then it runs again in its place.
  if (s.value("fingerprint", "") != fp) return false;
  if (needs_load_curves && !has_load_curves(dir, c.shear_box.normal_stresses)) return false;
  rec.outputs = s["outputs"];
  rec.reused = true;
  rec.wall_seconds = s.value("wall_seconds", 0.0);
  rec.made_by = s.value("colza_revision", "unknown");
  return true;
}

RunRecord RunCache::run(const RunRequest& request) {
  RunRecord rec;
  const RunConfig c = config_for(request, rec.id, rec.shared_packing_file);
  rec.dir = runs_ / rec.id;
  rec.replicate = request.replicate;
  rec.seed = c.seed;
  const bool is_shear = request.scenario == Scenario::kShear;
  if (reusable(rec.dir, rec.id, c, is_shear && request.needs_load_curves, rec)) return rec;

  double wall = 0.0;
  nlohmann::json outputs;
  // The run's summary.json: what it is (fingerprint, config, code revision, the caller's
  // annotations) and its outputs; written last, it marks the run as finished.
  auto summary_of = [&] {
    nlohmann::json s = request.annotations;
    s["fingerprint"] = rec.id;
    s["outputs"] = outputs;
    s["wall_seconds"] = wall;
    s["config_toml"] = c.resolved_toml;
    s["colza_revision"] = git_revision();
    if (!rec.shared_packing_file.empty()) s["packing_file"] = rec.shared_packing_file;
    return s;
  };
  // A run that blows up says which run it was.
  auto named = [&](const UnstableMotion& e) {
    const std::string realisation = request.replicate ? ", replicate " + std::to_string(request.replicate) : "";
    return UnstableMotion("run " + rec.id + " (" + request.label + realisation + "): " + e.what(),
                          e.fixed_time_step_too_large());
  };
  if (is_shear) {
    // Each load's whole curve is kept (load-<sigma>Pa.csv), so that other strength
    // definitions and curve features can be read from the runs later.
    std::vector<Table> curves;
    try {
      const auto sample = shear_sample(c, packing_line(named_packing_file(c, request.scenario)));
      outputs = run_shear_outputs(c, *sample, wall, curves);
    } catch (const UnstableMotion& e) {
      throw named(e);
    }
    OutputStaging out(rec.dir, true);
    for (std::size_t k = 0; k < curves.size(); ++k)
      write_csv(out.path(shear_curve_file_name(c.shear_box.normal_stresses[k])), curves[k]);
    write_json(out.path("summary.json"), summary_of());
    out.commit();
  } else {
    // The curve is written into the staging folder's final place after the summary check.
    const bool is_repose = request.scenario == Scenario::kRepose;
    const char* curve = is_repose ? "heap_profile.csv" : "curve.csv";
    const ScratchFolder tmp(runs_ / process_unique(".tmp-" + rec.id));
    try {
      outputs = is_repose ? run_repose_outputs(c, tmp.path, wall) : run_oedometer_outputs(c, tmp.path, wall);
    } catch (const UnstableMotion& e) {
      throw named(e);
    }
    OutputStaging out(rec.dir, true);
    fs::rename(tmp.path / curve, out.path(curve));
    write_json(out.path("summary.json"), summary_of());
    out.commit();
  }
  rec.outputs = outputs;
  rec.wall_seconds = wall;
  rec.made_by = git_revision();
  return rec;
}

std::string runs_by_another_revision_warning(const std::vector<std::pair<std::string, std::string>>& reused,
                                             const fs::path& runs_dir) {
  constexpr std::size_t kNamed = 10;  // runs named; the others counted
  std::set<std::string> listed;
  std::string named;
  for (const auto& [id, made_by] : reused) {
    if (made_by == git_revision() || !listed.insert(id).second) continue;
    if (listed.size() <= kNamed) named += (named.empty() ? "" : ", ") + id + " (" + made_by + ")";
  }
  if (listed.empty()) return "";
  if (listed.size() > kNamed) named += " and " + std::to_string(listed.size() - kNamed) + " more";
  return "reused runs made by another revision of colza than this one (" + std::string(git_revision()) +
         "): " + named + "; they stand only if the physics did not change in between: remove them from " +
         runs_dir.string() + " to run them again";
}

}  // namespace colza::calibration
