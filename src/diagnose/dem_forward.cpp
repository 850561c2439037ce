#include "diagnose/dem_forward.hpp"

#include <cstdio>

#include "calibration/calibrate.hpp"
#include "calibration/run_features.hpp"
#include "io/format_number.hpp"

namespace colza::diagnose {

namespace {

std::string assignment(const std::string& key, double value) { return key + "=" + format_significant(value, 17); }

}  // namespace

DemForward::DemForward(const DiagnosisSpec& spec, calibration::RunCache& cache, bool verbose)
    : spec_(spec), cache_(cache), verbose_(verbose) {}

std::vector<std::string> DemForward::overrides(const DiagnosisTest& test, const ModelPoint& x) const {
  std::vector<std::string> o = test.set;
  for (std::size_t j = 0; j < spec_.parameters.size(); ++j)
    o.push_back(assignment(spec_.parameters[j].key, x.baseline[static_cast<Eigen::Index>(j)]));
  if (x.candidate >= 0) {
    const CatalogueEntry& e = spec_.candidates[static_cast<std::size_t>(x.candidate)];
    o.insert(o.end(), e.candidate.settings.begin(), e.candidate.settings.end());
    o.push_back(assignment(e.candidate.parameter.key, x.strength));
    for (const StrengthKey& a : e.also_sets) o.push_back(assignment(a.key, a.factor * x.strength));
  }
  return o;
}

Eigen::VectorXd DemForward::operator()(const ModelPoint& x, int realisation) {
  std::vector<double> values;
  for (const DiagnosisTest& test : spec_.tests) {
    calibration::RunRequest request;
    request.scenario = test.scenario;
    request.config_path = test.config;
    request.overrides = overrides(test, x);
    request.replicate = realisation;
    request.needs_load_curves = test.scenario == Scenario::kShear;
    request.label = "diagnosis test " + test.name;
    const calibration::RunRecord run = cache_.run(request);
    ++runs_;
    if (run.reused) {
      ++reused_;
      const std::lock_guard<std::mutex> lock(reused_mutex_);
      reused_revisions_.emplace_back(run.id, run.made_by);
    }
    std::string fingerprint, packing;
    const calibration::Features f = calibration::run_features_of(
        run.outputs, run.dir, test.scenario, cache_.config_for(request, fingerprint, packing));
    for (const Feature& feature : test.features) {
      const auto it = f.find(feature.name);
      if (it == f.end()) {
        throw calibration::CalibrationError("tests", "test " + test.name + ": run " + run.id + " has no feature " +
                                                         feature.name + " (it has: " + calibration::feature_names(f) + ")");
      }
      values.push_back(it->second);
    }
    if (verbose_) {
      std::printf("  %s run %s%s (realisation %d)\n", test.name.c_str(), run.id.c_str(), run.reused ? " reused" : "",
                  realisation);
      std::fflush(stdout);
    }
  }
  return Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
}

std::vector<std::pair<std::string, std::string>> DemForward::reused_revisions() const {
  const std::lock_guard<std::mutex> lock(reused_mutex_);
  return reused_revisions_;
}

}  // namespace colza::diagnose
