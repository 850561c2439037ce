// The DEM as the diagnosis's forward model: a model point (the baseline's parameters, a
// candidate at a strength) and a realisation -> every test's features, in the spec's order.
// Each test is one run of its scenario (calibration/run_cache.hpp: kept by fingerprint and
// reused, so a diagnosis stopped and started again reruns nothing it finished) with the
// overrides: the test's own, the baseline's parameters, the candidate's settings and
// strength keys; realisation k runs with seed + k. The features come from the run's outputs
// and kept curves by the same code that reduces a measured file (calibration/run_features.hpp).
#pragma once
#include <Eigen/Dense>
#include <atomic>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "calibration/run_cache.hpp"
#include "diagnose/diagnosis_spec.hpp"

namespace colza::diagnose {

class DemForward {
 public:
  DemForward(const DiagnosisSpec& spec, calibration::RunCache& cache, bool verbose);
  Eigen::VectorXd operator()(const ModelPoint& point, int realisation);
  // The overrides a test runs with at a model point ("key=value"), the test's own first.
  std::vector<std::string> overrides(const DiagnosisTest& test, const ModelPoint& point) const;
  int reused_runs() const { return reused_.load(); }
  int runs() const { return runs_.load(); }
  // (run id, the revision that made it) of every reused run, in no particular order.
  std::vector<std::pair<std::string, std::string>> reused_revisions() const;

 private:
  const DiagnosisSpec& spec_;
  calibration::RunCache& cache_;
  bool verbose_;
  std::atomic<int> runs_{0}, reused_{0};
  mutable std::mutex reused_mutex_;
  std::vector<std::pair<std::string, std::string>> reused_revisions_;
};

}  // namespace colza::diagnose
