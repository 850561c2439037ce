#include "calibration/dem_model.hpp"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <utility>
#include <toml++/toml.h>
#include <unistd.h>

#include "analysis/mohr_coulomb.hpp"
#include "calibration/measured_csv.hpp"
#include "calibration/measured_shear_curve.hpp"
#include "config/config_error.hpp"
#include "core/concurrent.hpp"
#include "core/unstable_motion.hpp"
#include "core/version.hpp"
#include "io/fingerprint.hpp"
#include "io/output_dir.hpp"
#include "io/packing_file.hpp"
#include "io/summary.hpp"
#include "io/format_number.hpp"
#include "io/load_label.hpp"
#include "io/table.hpp"
#include "scenario/oedometer.hpp"

namespace colza::calibration {

namespace fs = std::filesystem;

namespace {

// A scratch name no other process uses: calibrations that share one runs directory
// (--runs) may compute the same run at the same time; each writes in its own scratch
// folder and the last rename wins with identical content (same fingerprint, same bits).
std::string process_unique(const std::string& name) { return name + "." + std::to_string(::getpid()); }

// A scratch folder removed when its scope ends, also when the run in it throws or is
// interrupted (Ctrl-C), so a stopped calibration leaves no half-written run behind.
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

// A shear design run's curve at normal stress sigma (Pa): load-<sigma>Pa.csv.
std::string shear_curve_file_name(double sigma) { return load_label(sigma) + ".csv"; }

std::string num17(double v) { return format_significant(v, 17); }  // round-trips a double

Scenario scenario_of(const Spec& s) { return s.stage == Stage::kShear ? Scenario::kShear : Scenario::kOedometer; }

// The settled sample depends on everything but the bond strengths (installed before
// loading), the loads and the keys of the shearing stage: specs that shear further or
// shorter, or record more often, share one sample. And on the packing file's contents when
// the config names one (`packing_line`, file_contents_line).
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

}  // namespace

DemModel::DemModel(const Spec& spec, fs::path runs_dir, bool verbose)
    : spec_(spec),
      runs_(std::move(runs_dir)),
      verbose_(verbose),
      fixed_packing_line_(file_contents_line(spec.fixed_packing_file)) {
  fs::create_directories(runs_);
}

std::vector<std::string> DemModel::seed_override(int replicate) const {
  if (replicate == 0) return {};
  return {"seed=" + std::to_string(spec_.base.seed + static_cast<std::uint64_t>(replicate))};
}

std::pair<std::string, std::string> DemModel::shared_packing(int replicate) {
  // Settled once at the centre of the design range (per realisation, each seed's packing
  // settled at the same time as the others), kept in runs/packing-<fp>/packing.txt.
  return packings_.get(replicate, [&] {
    std::vector<std::string> o = spec_.model_set;
    const Eigen::VectorXd mid = 0.5 * (spec_.problem.lower() + spec_.problem.upper());
    for (std::size_t j = 0; j < spec_.problem.parameters.size(); ++j)
      o.push_back(spec_.problem.parameters[j].key + "=" + num17(mid[j]));
    for (const auto& s : seed_override(replicate)) o.push_back(s);
    const RunConfig c = load_run_config(Scenario::kOedometer, spec_.model_config, o);
    const std::string fp = fingerprint_text(c.resolved_toml);
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
                    static_cast<unsigned long long>(c.seed), r.particles,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), file.c_str());
    }
    if (replicate == 0) {
      std::lock_guard<std::mutex> lock(note_mutex_);
      packing_note_ = "every run loads the packing settled once at the design centre: " + file.string() +
                      (spec_.problem.replicates > 0 ? " (replicates: one such packing per seed)" : "");
    }
    return std::pair<std::string, std::string>{file.string(), fp};
  });
}

RunConfig DemModel::config_for(const Eigen::VectorXd& x, int replicate, std::string& fp) {
  std::vector<std::string> o = spec_.model_set;
  if (spec_.stage == Stage::kShear) {
    std::string loads = "shear_box.normal_stresses=[";
    for (std::size_t k = 0; k < spec_.loads.size(); ++k) loads += (k ? "," : "") + num17(spec_.loads[k]);
    o.push_back(loads + "]");
  }
  for (std::size_t j = 0; j < spec_.problem.parameters.size(); ++j)
    o.push_back(spec_.problem.parameters[j].key + "=" + num17(x[j]));
  for (const auto& s : seed_override(replicate)) o.push_back(s);
  RunConfig c = load_run_config(scenario_of(spec_), spec_.model_config, o);
  std::string text = c.resolved_toml + fixed_packing_line_;
  if (spec_.shared_packing) {
    const auto [path, packing_fp] = shared_packing(replicate);
    c.oedometer.packing_file = path;
    text += "\n# shared packing " + packing_fp + "\n";
  }
  fp = fingerprint_text(text);
  return c;
}

std::shared_ptr<const ShearSample> DemModel::shear_sample(const RunConfig& c) {
  // One settled sample per sample fingerprint (different seeds settle at the same time),
  // kept in runs/sample-<fp>/packing.txt; every design run starts from the packing file
  // (identical start whether fresh or resumed).
  const std::string fp = sample_fingerprint(c, fixed_packing_line_);
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
        std::printf("  shear sample: %zu particles settled (%.1f s) -> %s\n", s.particles.size(),
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), file.c_str());
    }
    RunConfig from_file = c;
    from_file.shear_box.packing_file = file.string();
    return std::make_shared<const ShearSample>(prepare_shear_sample(from_file, quiet));
  });
}

nlohmann::json DemModel::run_oedometer_outputs(const RunConfig& c, const fs::path& dir, double& wall) {
  Progress quiet(false);
  const auto t0 = std::chrono::steady_clock::now();
  const OedometerResult r = run_oedometer(c, quiet);
  wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  nlohmann::json out = {{"bulk_density", r.bulk_density},
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
  fs::create_directories(dir);
  write_csv((dir / "curve.csv").string(), r.curve);
  return out;
}

nlohmann::json DemModel::run_shear_outputs(const RunConfig& c, double& wall, std::vector<Table>& curves) {
  const auto sample = shear_sample(c);
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t n = spec_.loads.size();
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
        const ShearLoadResult r = run_shear_load(c, *sample, spec_.loads[k], quiet);
        tau[k] = r.shear_strength;
        curves[k] = r.curve;
        load_json[k] = {{"normal_stress", spec_.loads[k]},
                        {"shear_strength", r.shear_strength},
                        {"peak_shear_stress", r.peak_shear_stress},
                        {"consolidated", r.consolidated},
                        {"mean_normal_stress_error", r.mean_normal_stress_error},
                        {"particles_outside", r.particles_outside},
                        {"bonds_installed", r.bonds_installed}};
      },
      std::max(1, threads / side_by_side));
  nlohmann::json loads = nlohmann::json::array();
  for (auto& l : load_json) loads.push_back(std::move(l));
  wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const MohrCoulombFit mc = fit_mohr_coulomb(spec_.loads, tau);
  return {{"cohesion", mc.cohesion},
          {"tan_phi", mc.slope},
          {"friction_angle_deg", mc.friction_angle_deg},
          {"line_r2", mc.r2},
          {"particles", sample->particles.size()},
          {"loads", loads}};
}

Eigen::VectorXd DemModel::targets_from(const nlohmann::json& out, const std::string& id) const {
  const auto& t = spec_.problem.targets;
  // A compression run that stopped short of the fit range's top (fit_force_max) has no c1
  // and c2, or those of a shorter curve: c1 and c2 depend on the range they are fitted over.
  const auto stopped_short = [&](const std::string& what) {
    return CalibrationError("model.set", "DEM run " + id + " " + what + " (largest force " +
                                             std::to_string(out.value("max_force", 0.0)) +
                                             " N): raise oedometer.stop_force / max_piston_travel or lower "
                                             "oedometer.fit_force_max in [model] set");
  };
  Eigen::VectorXd y(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!out.contains(t[i].name)) {
      if (spec_.stage == Stage::kCompression) throw stopped_short("did not reach the fit range");
      throw CalibrationError("model", "DEM run " + id + " has no output " + t[i].name);
    }
    if (!out[t[i].name].is_number())
      throw CalibrationError("model", "DEM run " + id + ": output " + t[i].name + " is not a number (" +
                                          out[t[i].name].dump() + "); remove the run's folder to run it again");
    y[i] = out[t[i].name].get<double>();
  }
  if (spec_.stage == Stage::kCompression && !out.value("fit_reached_force_max", true))
    throw stopped_short("stopped below the top of the fit range, so its c1 and c2 would be fitted over a shorter range");
  return y;
}

bool DemModel::has_load_curves(const fs::path& dir) const {
  for (double sigma : spec_.loads)
    if (!fs::exists(dir / shear_curve_file_name(sigma))) return false;
  return true;
}

Eigen::VectorXd DemModel::peak_targets(const fs::path& dir, const std::string& id) {
  // C and tan(Phi) of the line through the peak strengths of the run's kept load curves,
  // by the same definition as the measured curves' (StrengthDefinition).
  std::vector<double> tau;
  for (double sigma : spec_.loads) {
    const fs::path file = dir / shear_curve_file_name(sigma);
    const auto cols = read_csv_columns(file.string(), {kShearDisplacementColumn, kShearStressColumn}, file.string(),
                                       "(a DEM run's load curve)");
    std::size_t samples = 0;
    double at = 0.0;
    tau.push_back(curve_strength(cols[0], cols[1], spec_.strength, samples, at));
    if (samples == 0)
      throw CalibrationError("measured.peak_width", "DEM run " + id + ": " + file.string() + " spans less shear "
                             "displacement than the peak width " + format_significant(spec_.strength.peak_width, 6) +
                             " m: narrow measured.peak_width or shear further (shear_box.shear_displacement)");
    if (samples < 2)
      throw CalibrationError("measured.peak_width", "DEM run " + id + ": 1 row of " + file.string() +
                             " in the peak's interval: widen measured.peak_width or record the curve more often "
                             "(shear_box.record_interval)");
    if (at > cols[0].back() - spec_.strength.peak_width) {
      std::lock_guard<std::mutex> lock(note_mutex_);
      warnings_.push_back("DEM run " + id + ": the largest mean of " + file.string() + " lies in its last " +
                          format_significant(spec_.strength.peak_width, 6) + " m: the run may not have reached its "
                          "peak; shear further (shear_box.shear_displacement)");
    }
  }
  const MohrCoulombFit mc = fit_mohr_coulomb(spec_.loads, tau);
  return Eigen::Vector2d(mc.cohesion, mc.slope);
}

Eigen::VectorXd DemModel::run(const Eigen::VectorXd& x, int replicate) {
  std::string fp;
  const RunConfig c = config_for(x, replicate, fp);
  const fs::path dir = runs_ / fp;
  const fs::path summary = dir / "summary.json";
  DemRunRecord rec;
  rec.id = fp;
  rec.x = x;
  rec.replicate = replicate;
  // The peak strength is read from the load curves a run keeps (peak_targets).
  const bool reads_peaks = spec_.stage == Stage::kShear && spec_.strength.peak;
  if (fs::exists(summary)) {
    const std::string advice = "remove the run's folder to run it again";
    const auto s = read_json_file(summary.string(), advice);
    require_fields(s, summary.string(),
                   {{"fingerprint", JsonField::kString}, {"wall_seconds", JsonField::kNumber},
                    {"colza_revision", JsonField::kString}, {"outputs", JsonField::kObject}},
                   advice);
    // A run reuses a finished one unless the spec needs what the older run did not keep
    // (the load curves, for the peak strength): then it runs again in its place.
    if (s.value("fingerprint", "") == fp && (!reads_peaks || has_load_curves(dir))) {
      rec.outputs = s["outputs"];
      rec.reused = true;
      rec.wall_seconds = s.value("wall_seconds", 0.0);
      rec.made_by = s.value("colza_revision", "unknown");
    }
  }
  if (!rec.reused) {
    double wall = 0.0;
    nlohmann::json outputs;
    // The run's summary.json: what it is (fingerprint, config, parameters, code revision)
    // and its outputs; written last, it marks the run as finished.
    auto summary_of = [&] {
      nlohmann::json s = {{"fingerprint", fp},         {"stage", to_string(spec_.stage)}, {"outputs", outputs},
                          {"wall_seconds", wall},      {"config_toml", c.resolved_toml},
                          {"colza_revision", git_revision()}};
      s["parameters"] = nlohmann::json::object();
      for (std::size_t j = 0; j < spec_.problem.parameters.size(); ++j)
        s["parameters"][spec_.problem.parameters[j].key] = x[j];
      if (spec_.shared_packing) s["packing_file"] = c.oedometer.packing_file;
      return s;
    };
    // A run that blows up says which point of the calibration it was.
    auto with_point = [&](const UnstableMotion& e) {
      std::string point;
      for (std::size_t j = 0; j < spec_.problem.parameters.size(); ++j)
        point += (j ? ", " : "") + spec_.problem.parameters[j].name + " = " + num17(x[j]);
      return UnstableMotion("run " + fp + " (" + point + (replicate ? ", replicate " + std::to_string(replicate) : "") +
                            "): " + e.what(),
                            e.fixed_time_step_too_large());
    };
    if (spec_.stage == Stage::kShear) {
      // Each load's whole curve is kept (load-<sigma>Pa.csv), so that other strength
      // definitions can be read from the runs later.
      std::vector<Table> curves;
      try {
        outputs = run_shear_outputs(c, wall, curves);
      } catch (const UnstableMotion& e) {
        throw with_point(e);
      }
      OutputStaging out(dir, true);
      for (std::size_t k = 0; k < curves.size(); ++k)
        write_csv(out.path(shear_curve_file_name(spec_.loads[k])), curves[k]);
      write_json(out.path("summary.json"), summary_of());
      out.commit();
    } else {
      // The curve is written into the staging folder's final place after the summary check.
      const ScratchFolder tmp(runs_ / process_unique(".tmp-" + fp));
      try {
        outputs = run_oedometer_outputs(c, tmp.path, wall);
      } catch (const UnstableMotion& e) {
        throw with_point(e);
      }
      OutputStaging out(dir, true);
      fs::rename(tmp.path / "curve.csv", out.path("curve.csv"));
      write_json(out.path("summary.json"), summary_of());
      out.commit();
    }
    rec.outputs = outputs;
    rec.wall_seconds = wall;
    rec.made_by = git_revision();
  }
  rec.y = reads_peaks ? peak_targets(dir, fp) : targets_from(rec.outputs, fp);
  if (verbose_) {
    std::string line = "  run " + fp + ":";
    for (std::size_t j = 0; j < spec_.problem.parameters.size(); ++j) {
      char b[96];
      std::snprintf(b, sizeof b, " %s = %.5g", spec_.problem.parameters[j].name.c_str(), x[j]);
      line += b;
    }
    if (replicate > 0) line += " (seed " + std::to_string(c.seed) + ")";
    line += " ->";
    for (std::size_t i = 0; i < spec_.problem.targets.size(); ++i) {
      char b[96];
      std::snprintf(b, sizeof b, " %s = %.5g", spec_.problem.targets[i].name.c_str(), rec.y[i]);
      line += b;
    }
    char b[64];
    std::snprintf(b, sizeof b, " (%.1f s%s)", rec.wall_seconds, rec.reused ? ", reused" : "");
    std::printf("%s%s\n", line.c_str(), b);
    std::fflush(stdout);
  }
  Eigen::VectorXd y = rec.y;
  std::lock_guard<std::mutex> lock(mutex_);
  records_.push_back(std::move(rec));
  return y;
}

std::vector<DemRunRecord> DemModel::records() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return records_;
}

const DemRunRecord* DemModel::find(const Eigen::VectorXd& x, int replicate) const {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& r : records_)
    if (r.replicate == replicate && r.x.size() == x.size() && (r.x - x).norm() == 0.0) return &r;
  return nullptr;
}

}  // namespace colza::calibration
