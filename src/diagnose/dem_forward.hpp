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
#include <string>
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

 private:
  const DiagnosisSpec& spec_;
  calibration::RunCache& cache_;
  bool verbose_;
  std::atomic<int> runs_{0}, reused_{0};
};

}  // namespace colza::diagnose
