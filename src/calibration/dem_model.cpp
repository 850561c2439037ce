#include "calibration/dem_model.hpp"

#include <cstdio>
#include <utility>

#include "calibration/lab_tests.hpp"
#include "calibration/run_features.hpp"
#include "io/format_number.hpp"

namespace colza::calibration {

namespace fs = std::filesystem;

namespace {

std::string num17(double v) { return format_significant(v, 17); }  // round-trips a double

// The spec's overrides and one "key=value" per parameter at x.
std::vector<std::string> overrides_at(const Spec& s, const Eigen::VectorXd& x, std::vector<std::string> o) {
  for (std::size_t j = 0; j < s.problem.parameters.size(); ++j)
    o.push_back(s.problem.parameters[j].key + "=" + num17(x[j]));
  return o;
}

// "kn_p = 450000, mu_pp = 0.3": the point, in an error about its run.
std::string point_label(const Spec& s, const Eigen::VectorXd& x) {
  std::string point;
  for (std::size_t j = 0; j < s.problem.parameters.size(); ++j)
    point += (j ? ", " : "") + s.problem.parameters[j].name + " = " + num17(x[j]);
  return point;
}

}  // namespace

DemModel::DemModel(const Spec& spec, fs::path runs_dir, bool verbose)
    : spec_(spec), cache_(std::move(runs_dir), verbose), verbose_(verbose) {}

RunRequest DemModel::request_for(const Eigen::VectorXd& x, int replicate) const {
  RunRequest r;
  r.scenario = scenario_of(spec_.stage);
  r.config_path = spec_.model_config;
  std::vector<std::string> o = spec_.model_set;
  if (spec_.stage == Stage::kShear) {
    std::string loads = "shear_box.normal_stresses=[";
    for (std::size_t k = 0; k < spec_.loads.size(); ++k) {
      if (k > 0) loads += ',';
      loads += num17(spec_.loads[k]);
    }
    o.push_back(loads + "]");
  }
  r.overrides = overrides_at(spec_, x, std::move(o));
  r.replicate = replicate;
  // Density/compression with [model] packing = "shared": one packing settled at the centre
  // of the design range (per realisation), loaded by every run.
  if (spec_.shared_packing)
    r.shared_packing_overrides = overrides_at(spec_, 0.5 * (spec_.problem.lower() + spec_.problem.upper()),
                                              spec_.model_set);
  // The peak strength is read from the load curves a run keeps.
  r.needs_load_curves = spec_.stage == Stage::kShear && spec_.strength.peak;
  r.annotations = {{"stage", to_string(spec_.stage)}, {"parameters", nlohmann::json::object()}};
  for (std::size_t j = 0; j < spec_.problem.parameters.size(); ++j)
    r.annotations["parameters"][spec_.problem.parameters[j].key] = x[j];
  r.label = point_label(spec_, x);
  return r;
}

Eigen::VectorXd DemModel::targets_from(const RunRecord& run) {
  const auto& t = spec_.problem.targets;
  const nlohmann::json& out = run.outputs;
  Features features;
  if (spec_.stage == Stage::kShear && spec_.strength.peak) {
    std::vector<std::string> found;
    try {
      features = strength_line_features(run.dir, spec_.loads, spec_.strength, run.id, found);
    } catch (...) {
      std::lock_guard<std::mutex> lock(note_mutex_);
      warnings_.insert(warnings_.end(), found.begin(), found.end());
      throw;
    }
    std::lock_guard<std::mutex> lock(note_mutex_);
    warnings_.insert(warnings_.end(), found.begin(), found.end());
  } else {
    features = output_features(out);
  }
  // A compression run that stopped short of the fit range's top (fit_force_max) has no c1
  // and c2, or those of a shorter curve: c1 and c2 depend on the range they are fitted over.
  const auto stopped_short = [&](const std::string& what) {
    return CalibrationError("model.set", "DEM run " + run.id + " " + what + " (largest force " +
                                             std::to_string(out.value("max_force", 0.0)) +
                                             " N): raise oedometer.stop_force / max_piston_travel or lower "
                                             "oedometer.fit_force_max in [model] set");
  };
  Eigen::VectorXd y(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    const auto found = features.find(t[i].name);
    if (found != features.end()) {
      y[i] = found->second;
      continue;
    }
    if (out.contains(t[i].name))
      throw CalibrationError("model", "DEM run " + run.id + ": output " + t[i].name + " is not a number (" +
                                          out[t[i].name].dump() + "); remove the run's folder to run it again");
    if (spec_.stage == Stage::kCompression) throw stopped_short("did not reach the fit range");
    throw CalibrationError("model", "DEM run " + run.id + " has no output " + t[i].name);
  }
  if (spec_.stage == Stage::kCompression && !out.value("fit_reached_force_max", true))
    throw stopped_short("stopped below the top of the fit range, so its c1 and c2 would be fitted over a shorter range");
  return y;
}

void DemModel::print_run(const Eigen::VectorXd& x, const RunRecord& run, const Eigen::VectorXd& y) const {
  std::string line = "  run " + run.id + ":";
  for (std::size_t j = 0; j < spec_.problem.parameters.size(); ++j) {
    char b[96];
    std::snprintf(b, sizeof b, " %s = %.5g", spec_.problem.parameters[j].name.c_str(), x[j]);
    line += b;
  }
  if (run.replicate > 0) line += " (seed " + std::to_string(run.seed) + ")";
  line += " ->";
  for (std::size_t i = 0; i < spec_.problem.targets.size(); ++i) {
    char b[96];
    std::snprintf(b, sizeof b, " %s = %.5g", spec_.problem.targets[i].name.c_str(), y[i]);
    line += b;
  }
  char b[64];
  std::snprintf(b, sizeof b, " (%.1f s%s)", run.wall_seconds, run.reused ? ", reused" : "");
  std::printf("%s%s\n", line.c_str(), b);
  std::fflush(stdout);
}

Eigen::VectorXd DemModel::run(const Eigen::VectorXd& x, int replicate) {
  const RunRecord run = cache_.run(request_for(x, replicate));
  if (replicate == 0 && !run.shared_packing_file.empty()) {
    std::lock_guard<std::mutex> lock(note_mutex_);
    packing_note_ = "every run loads the packing settled once at the design centre: " + run.shared_packing_file +
                    (spec_.problem.replicates > 0 ? " (replicates: one such packing per seed)" : "");
  }
  DemRunRecord rec{x, targets_from(run), run};
  if (verbose_) print_run(x, run, rec.y);
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
    if (r.run.replicate == replicate && r.x.size() == x.size() && (r.x - x).norm() == 0.0) return &r;
  return nullptr;
}

}  // namespace colza::calibration
